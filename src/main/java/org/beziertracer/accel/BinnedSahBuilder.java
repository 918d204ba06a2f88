package org.beziertracer.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.RecursiveAction;

/**
 * Top-down binned surface-area-heuristic builder for {@link Bvh}, parallel over subtrees.
 *
 * <p>Method: I. Wald, "On fast Construction of SAH-based Bounding Volume Hierarchies", IEEE
 * Symposium on Interactive Ray Tracing, 2007. Each node's primitive centroids are binned into
 * {@code binCount} equal intervals of the centroid bounds along each axis, or only the widest
 * one in builds of more than {@link #ALL_AXES_PRIMS} primitives ({@link SahBinner}; fewer bins
 * for nodes with fewer primitives); a right and a left sweep evaluate the
 * SAH at every bin border; the cheapest border wins. The children's boxes are the unions of their bins' boxes,
 * and their centroid bounds are gathered while the node's indices are partitioned in place, so
 * each level costs one binning pass and one partition pass. Node layout and the in-place
 * partition of one index array follow tinybvh by J. Bikker. Independent subtrees over at least
 * {@link BvhBuild#PARALLEL_PRIMS} primitives are built as fork-join tasks (the "binned SAH per
 * subtree in parallel" of Wald 2007, §4). The primitives' boxes and centroids move with their
 * indices, so every pass reads memory in order.
 *
 * <p>Nodes take the deterministic slots of {@link BvhBuild}, so the result does not depend on
 * the scheduling.
 *
 * <p>Rules: a node with one primitive is a leaf; a node with at most {@code maxLeafSize}
 * primitives becomes a leaf when that is no dearer than the best split. A larger node is always
 * split: by the SAH when the centroids are spread out, otherwise (all centroids equal, e.g.
 * identical boxes) at the middle of its index range, so the build always terminates with leaves
 * of at most {@code maxLeafSize}. Each task is iterative (explicit work stack), so even a
 * degenerate, list-like tree cannot overflow the Java stack.
 *
 */
final class BinnedSahBuilder extends BvhBuild {

    /** SAH cost of visiting a node (one box test), relative to {@link #PRIMITIVE_COST}. */
    static final double TRAVERSAL_COST = 1.0;
    /** SAH cost of one leaf callback: a sub-patch test is several times dearer than a box test. */
    static final double PRIMITIVE_COST = 4.0;

    /**
     * Builds of at most this many primitives bin all three axes (Wald 2007); larger ones only the
     * widest. Binning three axes triples the binning pass (100 teapots, 93,400 sub-patches: 80 →
     * 130 ms of CPU per build) for trees a few per cent cheaper to trace (the curved bicubic frame
     * 5 % less CPU, the teapot frame 2–4 %), which pays for a model's single build but not for
     * scenes whose build time is the concern.
     */
    static final int ALL_AXES_PRIMS = 1 << 16;

    /** In leaf order: twice the centre of the primitive's box ({@code min + max}), 3 each. */
    final float[] centroids;
    final int binCount;
    /** Bin all three axes ({@link #ALL_AXES_PRIMS}), else the widest only. */
    final boolean allAxes;

    /** Over the primitives {@code order} (their indices into {@code primBounds}, in leaf order). */
    private BinnedSahBuilder(double[] primBounds, int[] order, BvhOptions opts, boolean allAxes) {
        super(primBounds, order, opts);
        this.binCount = opts.binCount();
        this.allAxes = allAxes;
        centroids = new float[3 * order.length];
        for (int i = 0; i < order.length; i++) {
            int p = order[i];
            for (int a = 0; a < 3; a++) {
                centroids[3 * i + a] = (float) (primBounds[6 * p + a] + primBounds[6 * p + 3 + a]);
            }
        }
    }

    static Bvh build(double[] primBounds, int primCount, BvhOptions opts) {
        return build(primBounds, primCount, opts, true);
    }

    /** As {@link #build(double[], int, BvhOptions)}; {@code parallel = false}: on the calling thread only. */
    static Bvh build(double[] primBounds, int primCount, BvhOptions opts, boolean parallel) {
        long start = System.nanoTime();
        Bvh.checkBounds(primBounds, primCount);
        if (primCount == 0) {
            return empty(start);
        }
        return build(primBounds, identity(primCount), opts, parallel, primCount <= ALL_AXES_PRIMS, start);
    }

    /**
     * The hierarchy over the primitives {@code order} (indices into {@code primBounds}, checked by
     * the caller; not empty), which becomes its leaf order; {@code allAxes}: bin all three axes.
     */
    static Bvh build(double[] primBounds, int[] order, BvhOptions opts, boolean parallel, boolean allAxes,
                     long start) {
        int primCount = order.length;
        BinnedSahBuilder b = new BinnedSahBuilder(primBounds, order, opts, allAxes);
        float[] rootCentroids = new float[6];
        b.unionOf(0, primCount, b.nodeBounds, 0, rootCentroids);
        Subtree root = new Subtree(b, 0, 1, 0, primCount, 1, rootCentroids);
        b.parallel = parallel && primCount >= PARALLEL_PRIMS;
        if (b.parallel) {
            root.invoke();
        } else {
            root.compute();
        }
        return b.toBvh(start);
    }

    /**
     * Union of the boxes at leaf-order positions {@code first .. first+n-1} into {@code box[o..o+5]}
     * and of their centroids into {@code cbox[0..5]}.
     */
    void unionOf(int first, int n, float[] box, int o, float[] cbox) {
        unionOf(first, n, box, o);
        setEmpty(cbox, 0);
        for (int i = first; i < first + n; i++) {
            growPoint(cbox, centroids, 3 * i);
        }
    }

    /** Exchanges positions {@code i} and {@code j} of the leaf order (index, box, centroid). */
    void swap(int i, int j) {
        swap(prims, boxes, centroids, i, j);
    }

    /** One subtree, built iteratively; its big children become tasks of their own. */
    static final class Subtree extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        final transient BinnedSahBuilder b;
        final int slot, desc, first, n, level;
        final float[] centroidBox;

        /**
         * The subtree rooted at node {@code slot} (box already written) over leaf-order positions
         * {@code first .. first+n-1}, whose descendants take the slots from {@code desc} on, at
         * depth {@code level}, with the centroid bounds {@code centroidBox}.
         */
        Subtree(BinnedSahBuilder b, int slot, int desc, int first, int n, int level, float[] centroidBox) {
            this.b = b;
            this.slot = slot;
            this.desc = desc;
            this.first = first;
            this.n = n;
            this.level = level;
            this.centroidBox = centroidBox;
        }

        @Override
        protected void compute() {
            SahBinner w = new SahBinner(b);
            List<Subtree> forked = new ArrayList<>();
            WorkStack stack = new WorkStack();
            stack.push(slot, desc, first, n, level, centroidBox);
            int deepest = 0, made = 0;
            float[] cbox = new float[6];
            while (stack.size > 0) {
                int[] e = stack.pop(cbox);
                int s = e[0], d = e[1], f = e[2], count = e[3], lvl = e[4];
                deepest = Math.max(deepest, lvl);
                made++;
                int mid = w.split(s, d, f, count, cbox);
                if (mid < 0) {
                    b.leaf(s, f, count);
                    continue;
                }
                int nl = mid - f, nr = count - nl;
                b.interior(s, d);
                if (b.parallel && nl >= PARALLEL_PRIMS) {
                    Subtree left = new Subtree(b, d, d + 2, f, nl, lvl + 1, w.leftCentroids.clone());
                    left.fork();
                    forked.add(left);
                } else {
                    stack.push(d, d + 2, f, nl, lvl + 1, w.leftCentroids);
                }
                stack.push(d + 1, d + 2 * nl, mid, nr, lvl + 1, w.rightCentroids);
            }
            for (Subtree t : forked) {
                t.join();
            }
            b.made(made, deepest);
        }
    }

    /** Pending nodes of one task: 5 ints and a centroid box each. */
    static final class WorkStack {
        int[] ints = new int[5 * 64];
        float[] floats = new float[6 * 64];
        int size;
        final int[] top = new int[5];

        void push(int slot, int desc, int first, int n, int level, float[] cbox) {
            if (5 * (size + 1) > ints.length) {
                ints = Arrays.copyOf(ints, 2 * ints.length);
                floats = Arrays.copyOf(floats, 2 * floats.length);
            }
            int i = 5 * size;
            ints[i] = slot;
            ints[i + 1] = desc;
            ints[i + 2] = first;
            ints[i + 3] = n;
            ints[i + 4] = level;
            System.arraycopy(cbox, 0, floats, 6 * size, 6);
            size++;
        }

        int[] pop(float[] cbox) {
            size--;
            System.arraycopy(ints, 5 * size, top, 0, 5);
            System.arraycopy(floats, 6 * size, cbox, 0, 6);
            return top;
        }
    }
}
