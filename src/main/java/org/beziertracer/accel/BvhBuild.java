package org.beziertracer.accel;

import java.util.Arrays;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * What the {@link Bvh} builders share: the primitives' boxes rounded outward to floats and kept
 * in leaf order, the node arrays in their deterministic slot layout, and the box helpers.
 *
 * <p><b>Slot layout.</b> A subtree over {@code n} primitives owns {@code 2n-1} node slots fixed
 * before it is built: the node itself, then its children's pair, then the left child's
 * descendants ({@code 2·nLeft-2} slots), then the right child's. So children are adjacent and after
 * their parent, no slot counter is shared between threads, and the arrays are the same whatever
 * the scheduling. Slots left over (a leaf of several primitives does not use its subtree's room)
 * are squeezed out at the end ({@link #toBvh}).
 *
 * <p>Boxes: every node box is a union of the primitives' boxes rounded outward, so it contains
 * the double boxes of its primitives.
 */
abstract class BvhBuild {

    /** Subtrees over at least this many primitives are built as separate fork-join tasks. */
    static final int PARALLEL_PRIMS = 4096;

    /**
     * In leaf order, like {@link #prims} (moved with it by every partition, so each pass reads
     * memory in order): the primitive's box rounded outward to floats, 6 each.
     */
    final float[] boxes;
    /** The primitive indices in leaf order. */
    final int[] prims;
    /** Per node slot: its box, 6 floats. */
    float[] nodeBounds;
    /** Per node slot: {@code leftFirst, count}; {@code count = -1} marks a slot no node took. */
    int[] nodes;
    final int maxLeafSize;
    /** Whether big subtrees are forked (set before the build starts). */
    boolean parallel;
    final AtomicInteger depth = new AtomicInteger();
    final AtomicInteger used = new AtomicInteger();

    /** The boxes of {@code primBounds} in the leaf order {@code order} (kept as {@link #prims}). */
    BvhBuild(double[] primBounds, int[] order, BvhOptions opts) {
        int primCount = order.length;
        this.maxLeafSize = opts.maxLeafSize();
        prims = order;
        boxes = new float[6 * primCount];
        for (int i = 0; i < primCount; i++) {
            RayBox.roundOutward(primBounds, 6 * order[i], boxes, 6 * i);
        }
        int slots = 2 * primCount - 1;
        nodeBounds = new float[6 * slots];
        nodes = new int[2 * slots];
        Arrays.fill(nodes, -1);
    }

    /** The primitives in their own order, {@code 0 .. n-1}: the leaf order before a build sorts it. */
    static int[] identity(int n) {
        int[] order = new int[n];
        for (int p = 0; p < n; p++) {
            order[p] = p;
        }
        return order;
    }

    /** The hierarchy of no primitive: one empty leaf. */
    static Bvh empty(long start) {
        float inf = Float.POSITIVE_INFINITY;
        return new Bvh(new float[] {inf, inf, inf, -inf, -inf, -inf}, new int[] {0, 0}, new int[0], 1,
                (System.nanoTime() - start) * 1e-6);
    }

    /** Node {@code slot} becomes a leaf over leaf-order positions {@code first .. first+n-1}. */
    final void leaf(int slot, int first, int n) {
        nodes[2 * slot] = first;
        nodes[2 * slot + 1] = n;
    }

    /** Node {@code slot} becomes an interior node with children {@code left} and {@code left+1}. */
    final void interior(int slot, int left) {
        nodes[2 * slot] = left;
        nodes[2 * slot + 1] = 0;
    }

    /** Records what one build task made: {@code made} nodes, the deepest at level {@code deepest}. */
    final void made(int made, int deepest) {
        used.addAndGet(made);
        depth.accumulateAndGet(deepest, Math::max);
    }

    /** The finished hierarchy, with the slots no node took squeezed out. */
    final Bvh toBvh(long start) {
        int slots = nodes.length / 2;
        if (used.get() < slots) {
            squeeze(slots);
        }
        return new Bvh(nodeBounds, nodes, prims, depth.get(), (System.nanoTime() - start) * 1e-6);
    }

    private void squeeze(int slots) {
        int[] index = new int[slots];
        int next = 0;
        for (int i = 0; i < slots; i++) {
            index[i] = next;
            if (nodes[2 * i + 1] >= 0) {
                next++;
            }
        }
        float[] nb = new float[6 * next];
        int[] nd = new int[2 * next];
        for (int i = 0; i < slots; i++) {
            int n = nodes[2 * i + 1];
            if (n >= 0) {
                int j = index[i];
                System.arraycopy(nodeBounds, 6 * i, nb, 6 * j, 6);
                nd[2 * j] = n > 0 ? nodes[2 * i] : index[nodes[2 * i]];
                nd[2 * j + 1] = n;
            }
        }
        nodeBounds = nb;
        nodes = nd;
    }

    /** Union of the boxes at leaf-order positions {@code first .. first+n-1} into {@code box[o..o+5]}. */
    final void unionOf(int first, int n, float[] box, int o) {
        setEmpty(box, o);
        for (int i = first; i < first + n; i++) {
            grow(box, o, boxes, 6 * i);
        }
    }

    static double halfArea(float[] b, int o) {
        double dx = (double) b[o + 3] - b[o], dy = (double) b[o + 4] - b[o + 1], dz = (double) b[o + 5] - b[o + 2];
        return dx * dy + dy * dz + dz * dx;
    }

    static void setEmpty(float[] b, int o) {
        b[o] = b[o + 1] = b[o + 2] = Float.POSITIVE_INFINITY;
        b[o + 3] = b[o + 4] = b[o + 5] = Float.NEGATIVE_INFINITY;
    }

    /**
     * Exchanges positions {@code i} and {@code j} of a leaf order: the indices {@code prims}, the
     * boxes (6 floats each) and the centres (3 floats each) that move with them.
     */
    static void swap(int[] prims, float[] boxes, float[] centres, int i, int j) {
        int p = prims[i];
        prims[i] = prims[j];
        prims[j] = p;
        for (int k = 0; k < 6; k++) {
            float t = boxes[6 * i + k];
            boxes[6 * i + k] = boxes[6 * j + k];
            boxes[6 * j + k] = t;
        }
        for (int k = 0; k < 3; k++) {
            float t = centres[3 * i + k];
            centres[3 * i + k] = centres[3 * j + k];
            centres[3 * j + k] = t;
        }
    }

    /** Grows box {@code dst[d..d+5]} to contain box {@code src[s..s+5]}. */
    static void grow(float[] dst, int d, float[] src, int s) {
        for (int k = 0; k < 3; k++) {
            dst[d + k] = Math.min(dst[d + k], src[s + k]);
            dst[d + 3 + k] = Math.max(dst[d + 3 + k], src[s + 3 + k]);
        }
    }

    /** Grows float box {@code dst[d..d+5]} to contain double box {@code src[s..s+5]} rounded outward. */
    static void growRounded(float[] dst, int d, double[] src, int s) {
        for (int k = 0; k < 3; k++) {
            dst[d + k] = Math.min(dst[d + k], RayBox.down(src[s + k]));
            dst[d + 3 + k] = Math.max(dst[d + 3 + k], RayBox.up(src[s + 3 + k]));
        }
    }

    /** Grows box {@code dst[0..5]} to contain point {@code src[s..s+2]}. */
    static void growPoint(float[] dst, float[] src, int s) {
        for (int k = 0; k < 3; k++) {
            dst[k] = Math.min(dst[k], src[s + k]);
            dst[3 + k] = Math.max(dst[3 + k], src[s + k]);
        }
    }
}
