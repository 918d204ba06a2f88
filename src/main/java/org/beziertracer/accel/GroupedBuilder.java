package org.beziertracer.accel;

import java.util.Arrays;
import java.util.stream.IntStream;

/**
 * Two-level build of a {@link Bvh} over primitives that come in contiguous groups (the
 * sub-patches of one patch): a binned-SAH hierarchy over the groups' boxes, one group a leaf
 * ({@link BinnedSahBuilder}, or {@link MortonBuilder} for very many groups), whose leaves are then
 * replaced by the roots of the groups' own small trees (median splits of the centres along their
 * widest axis down to one primitive a leaf, the groups in parallel). The result is one ordinary
 * {@link Bvh}: same layout, same traversal, same {@link Bvh#refit}.
 *
 * <p>Method: the two-level (top-level / bottom-level) hierarchy of instanced ray tracers, I. Wald,
 * C. Benthin and P. Slusallek, "A Simple and Practical Method for Interactive Ray Tracing of
 * Dynamic Scenes", Saarland University technical report, 2002; here the two levels are merged into
 * one tree, since the groups are not instances. A group's few tens of sub-patches lie side by side
 * on one patch, where a median split costs a fraction of a binned SAH's sweep per node and loses
 * little: on the 100-teapot scene (93,400 sub-patches) the build takes 8–11 instead of 42–54 ms for
 * trees 5 % dearer by the SAH that traced its frame faster (docs/performance-journal.md, "Fifth pass"). A
 * tree cannot mix the sub-patches of neighbouring patches, so it is used only for big scenes
 * ({@link BvhOptions#groupsPay}).
 *
 * <p>Layout: the top tree's nodes first (its leaves hold the groups' roots), then each group's
 * other nodes in group order, each group's subtree in the slot layout of {@link BvhBuild}, so
 * children still follow their parent; a group's primitives keep their positions
 * {@code groupFirst[j] ..} of the leaf order. Deterministic like the other builders.
 */
final class GroupedBuilder {
    private GroupedBuilder() {}

    /**
     * The hierarchy over {@code primCount} boxes in the groups {@code groupFirst[j] ..
     * groupFirst[j+1]-1} ({@code groupFirst[0] == 0}, non-decreasing, last {@code == primCount};
     * an empty group is skipped).
     */
    static Bvh build(double[] primBounds, int primCount, int[] groupFirst, BvhOptions opts) {
        long start = System.nanoTime();
        Bvh.checkBounds(primBounds, primCount);
        checkGroups(groupFirst, primCount);
        if (primCount == 0) {
            return BvhBuild.empty(start);
        }
        int[] groups = IntStream.range(0, groupFirst.length - 1)
                .filter(j -> groupFirst[j + 1] > groupFirst[j]).toArray();
        int g = groups.length;
        double[] groupBounds = new double[6 * g];
        for (int i = 0; i < g; i++) {
            int first = groupFirst[groups[i]];
            unionOf(primBounds, first, groupFirst[groups[i] + 1] - first, groupBounds, 6 * i);
        }
        // The top tree: one group a leaf, the widest axis binned as in any build of this size
        BvhOptions topOpts = new BvhOptions(1, opts.binCount(), opts.mortonPrims());
        Bvh top = g >= opts.mortonPrims() ? MortonBuilder.build(groupBounds, g, topOpts)
                : BinnedSahBuilder.build(groupBounds, BvhBuild.identity(g), topOpts, true, false, start);
        // Every leaf holds one primitive: a group of n takes 2n-1 nodes, its root in the top tree
        int topCount = top.nodeCount();
        int[] base = new int[g + 1];
        base[0] = topCount;
        for (int i = 0; i < g; i++) {
            base[i + 1] = base[i] + 2 * (groupFirst[groups[i] + 1] - groupFirst[groups[i]]) - 2;
        }
        int total = base[g];
        float[] bounds = Arrays.copyOf(top.nodeBounds, 6 * total);
        int[] nodes = Arrays.copyOf(top.nodes, 2 * total);
        int[] rootSlot = new int[g];
        for (int slot = 0; slot < topCount; slot++) {
            if (top.nodes[2 * slot + 1] > 0) {
                rootSlot[top.primIndices[top.nodes[2 * slot]]] = slot;
            }
        }
        int[] prims = new int[primCount];
        float[] boxes = new float[6 * primCount];
        float[] centres = new float[3 * primCount];
        IntStream.range(0, g).parallel().forEach(i -> {
            int first = groupFirst[groups[i]], n = groupFirst[groups[i] + 1] - first;
            for (int p = first; p < first + n; p++) {
                prims[p] = p;
                RayBox.roundOutward(primBounds, 6 * p, boxes, 6 * p);
                for (int a = 0; a < 3; a++) {
                    centres[3 * p + a] = boxes[6 * p + a] + boxes[6 * p + 3 + a];
                }
            }
            new Group(prims, boxes, centres, bounds, nodes).build(rootSlot[i], base[i], first, n);
        });
        return new Bvh(bounds, nodes, prims, depth(nodes, total), (System.nanoTime() - start) * 1e-6);
    }

    /**
     * One group's tree, split at the median of the centres along their widest axis down to one
     * primitive a leaf; a node over n primitives owns 2n-1 slots as in {@link BvhBuild} (itself,
     * its children's pair, the left child's descendants, the right child's), except that the
     * group's root sits in its top-tree leaf.
     */
    private record Group(int[] prims, float[] boxes, float[] centres, float[] bounds, int[] nodes) {

        /** The subtree over positions {@code first .. first+n-1} at {@code slot}, descendants from {@code desc}. */
        void build(int slot, int desc, int first, int n) {
            if (n == 1) {
                nodes[2 * slot] = first;
                nodes[2 * slot + 1] = 1;
                System.arraycopy(boxes, 6 * first, bounds, 6 * slot, 6);
                return;
            }
            int axis = widestAxis(first, n), nl = n / 2;
            select(first, first + n - 1, first + nl, axis);
            nodes[2 * slot] = desc;
            nodes[2 * slot + 1] = 0;
            build(desc, desc + 2, first, nl);
            build(desc + 1, desc + 2 * nl, first + nl, n - nl);
            BvhBuild.setEmpty(bounds, 6 * slot);
            BvhBuild.grow(bounds, 6 * slot, bounds, 6 * desc);
            BvhBuild.grow(bounds, 6 * slot, bounds, 6 * desc + 6);
        }

        private int widestAxis(int first, int n) {
            int best = 0;
            float bestExtent = -1;
            for (int a = 0; a < 3; a++) {
                float lo = Float.POSITIVE_INFINITY, hi = Float.NEGATIVE_INFINITY;
                for (int p = first; p < first + n; p++) {
                    float c = centres[3 * p + a];
                    lo = Math.min(lo, c);
                    hi = Math.max(hi, c);
                }
                if (hi - lo > bestExtent) {
                    bestExtent = hi - lo;
                    best = a;
                }
            }
            return best;
        }

        /** Quickselect (Hoare): positions {@code lo..hi} partitioned so {@code k} holds its rank's centre on {@code axis}. */
        private void select(int lo, int hi, int k, int axis) {
            while (lo < hi) {
                float pivot = centres[3 * ((lo + hi) >>> 1) + axis];
                int i = lo, j = hi;
                while (i <= j) {
                    while (centres[3 * i + axis] < pivot) {
                        i++;
                    }
                    while (centres[3 * j + axis] > pivot) {
                        j--;
                    }
                    if (i <= j) {
                        BvhBuild.swap(prims, boxes, centres, i++, j--);
                    }
                }
                if (k <= j) {
                    hi = j;
                } else if (k >= i) {
                    lo = i;
                } else {
                    return;
                }
            }
        }

    }

    /** Levels of the tree (the root is level 1); children follow their parent. */
    private static int depth(int[] nodes, int total) {
        int[] level = new int[total];
        level[0] = 1;
        int deepest = 1;
        for (int i = 0; i < total; i++) {
            if (nodes[2 * i + 1] == 0) {
                int left = nodes[2 * i];
                level[left] = level[left + 1] = level[i] + 1;
                deepest = Math.max(deepest, level[i] + 1);
            }
        }
        return deepest;
    }

    private static void unionOf(double[] primBounds, int first, int n, double[] out, int o) {
        for (int a = 0; a < 3; a++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int p = first; p < first + n; p++) {
                lo = Math.min(lo, primBounds[6 * p + a]);
                hi = Math.max(hi, primBounds[6 * p + 3 + a]);
            }
            out[o + a] = lo;
            out[o + 3 + a] = hi;
        }
    }

    private static void checkGroups(int[] groupFirst, int primCount) {
        if (groupFirst.length < 2 || groupFirst[0] != 0 || groupFirst[groupFirst.length - 1] != primCount) {
            throw new IllegalArgumentException("groups must start at 0 and end at " + primCount + ", got "
                    + (groupFirst.length == 0 ? "none" : groupFirst[0] + ".." + groupFirst[groupFirst.length - 1]));
        }
        for (int j = 1; j < groupFirst.length; j++) {
            if (groupFirst[j] < groupFirst[j - 1]) {
                throw new IllegalArgumentException("group " + j + " starts at " + groupFirst[j]
                        + ", before group " + (j - 1) + " at " + groupFirst[j - 1]);
            }
        }
    }
}
