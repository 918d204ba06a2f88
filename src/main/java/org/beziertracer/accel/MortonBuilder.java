package org.beziertracer.accel;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.RecursiveAction;

/**
 * Morton-ordered builder for {@link Bvh} (a linear BVH), for big inputs where the binned SAH's
 * pass per tree level costs too much.
 *
 * <p>Method: T. Karras, "Maximizing Parallelism in the Construction of BVHs, Octrees, and k-d
 * Trees", HPG 2012, after C. Lauterbach et al., "Fast BVH Construction on GPUs", Eurographics 2009.
 * Each primitive's box centre is quantised to 21 bits per axis inside the bounds of all centres
 * (cubic cells: one scale for all axes, from the widest extent; per-axis scales gave a 50 % dearer
 * tree on a flat grid of teapots) and the bits are interleaved into a 63-bit Morton code (a Z-order curve); the primitives are
 * sorted by code (LSD radix sort, 6 passes of 11 bits, stable). A node over a run of the sorted
 * order is split where its highest differing code bit flips (a binary search); a run of equal
 * codes is split at its middle. Node boxes are unions, computed bottom-up by each build task after
 * its subtree is complete. Subtrees over at least {@link BvhBuild#PARALLEL_PRIMS} primitives are
 * fork-join tasks; nodes take the deterministic slots of {@link BvhBuild}.
 *
 * <p>Leaves hold one primitive, except a run of equal codes of at most {@code maxLeafSize}
 * primitives. The tree is at most {@code 63 + ⌈log2 n⌉} levels deep.
 */
final class MortonBuilder extends BvhBuild {

    /** Bits per axis of the quantised centres. */
    static final int BITS = 21;
    private static final int RADIX_BITS = 11;

    /** Morton codes in leaf order. */
    final long[] codes;

    private MortonBuilder(double[] primBounds, int[] order, long[] sortedCodes, BvhOptions opts) {
        super(primBounds, order, opts);
        this.codes = sortedCodes;
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
        long[] keys = codes(primBounds, primCount);
        int[] order = identity(primCount);
        sort(keys, order);
        MortonBuilder b = new MortonBuilder(primBounds, order, keys, opts);
        Subtree root = new Subtree(b, 0, 1, 0, primCount, 1);
        b.parallel = parallel && primCount >= PARALLEL_PRIMS;
        if (b.parallel) {
            root.invoke();
        } else {
            root.compute();
        }
        return b.toBvh(start);
    }

    /** The Morton code of each primitive's box centre, quantised inside the bounds of all centres. */
    static long[] codes(double[] primBounds, int n) {
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int p = 0; p < n; p++) {
            for (int a = 0; a < 3; a++) {
                double c = 0.5 * primBounds[6 * p + a] + 0.5 * primBounds[6 * p + 3 + a];
                lo[a] = Math.min(lo[a], c);
                hi[a] = Math.max(hi[a], c);
            }
        }
        // Cubic cells: one scale for all axes, from the widest extent
        double cells = (1 << BITS) - 1;
        double extent = Math.max(hi[0] - lo[0], Math.max(hi[1] - lo[1], hi[2] - lo[2]));
        double s = cells / extent;
        double[] scale = new double[3];
        for (int a = 0; a < 3; a++) {
            scale[a] = extent > 0 && Double.isFinite(s) ? s : 0;
        }
        long[] keys = new long[n];
        for (int p = 0; p < n; p++) {
            long code = 0;
            for (int a = 0; a < 3; a++) {
                double c = 0.5 * primBounds[6 * p + a] + 0.5 * primBounds[6 * p + 3 + a];
                long q = (long) Math.min(cells, Math.max(0, (c - lo[a]) * scale[a]));
                code |= spread(q) << (2 - a);
            }
            keys[p] = code;
        }
        return keys;
    }

    /** The low 21 bits of {@code x} spread to every third bit (bit i to bit 3i). */
    static long spread(long x) {
        x &= 0x1fffffL;
        x = (x | x << 32) & 0x1f00000000ffffL;
        x = (x | x << 16) & 0x1f0000ff0000ffL;
        x = (x | x << 8) & 0x100f00f00f00f00fL;
        x = (x | x << 4) & 0x10c30c30c30c30c3L;
        x = (x | x << 2) & 0x1249249249249249L;
        return x;
    }

    /** Sorts {@code keys} ascending (stable LSD radix sort) and permutes {@code values} alike. */
    static void sort(long[] keys, int[] values) {
        int n = keys.length, buckets = 1 << RADIX_BITS, mask = buckets - 1;
        long[] k2 = new long[n];
        int[] v2 = new int[n];
        int[] count = new int[buckets];
        long[] ks = keys, kd = k2;
        int[] vs = values, vd = v2;
        for (int shift = 0; shift < 3 * BITS; shift += RADIX_BITS) {
            java.util.Arrays.fill(count, 0);
            for (int i = 0; i < n; i++) {
                count[(int) (ks[i] >>> shift) & mask]++;
            }
            if (count[(int) (ks[0] >>> shift) & mask] == n) {
                continue; // every key has this digit: the pass would not move anything
            }
            for (int d = 0, sum = 0; d < buckets; d++) {
                int c = count[d];
                count[d] = sum;
                sum += c;
            }
            for (int i = 0; i < n; i++) {
                int at = count[(int) (ks[i] >>> shift) & mask]++;
                kd[at] = ks[i];
                vd[at] = vs[i];
            }
            long[] tk = ks;
            ks = kd;
            kd = tk;
            int[] tv = vs;
            vs = vd;
            vd = tv;
        }
        if (ks != keys) {
            System.arraycopy(ks, 0, keys, 0, n);
            System.arraycopy(vs, 0, values, 0, n);
        }
    }

    /**
     * Where to split the sorted run {@code first .. first+n-1} (n ≥ 2): the first position whose
     * highest differing bit is set, or the middle of a run of equal codes; -1 when a run of equal
     * codes is small enough to be a leaf.
     */
    int split(int first, int n) {
        long a = codes[first], z = codes[first + n - 1];
        if (a == z) {
            return n <= maxLeafSize ? -1 : first + n / 2;
        }
        long bit = Long.highestOneBit(a ^ z);
        int lo = first + 1, hi = first + n - 1; // codes[hi] has the bit, codes[first] not
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if ((codes[mid] & bit) != 0) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }

    /** One subtree, built iteratively; its big children become tasks of their own. */
    static final class Subtree extends RecursiveAction {
        private static final long serialVersionUID = 1L;
        final transient MortonBuilder b;
        final int slot, desc, first, n, level;

        Subtree(MortonBuilder b, int slot, int desc, int first, int n, int level) {
            this.b = b;
            this.slot = slot;
            this.desc = desc;
            this.first = first;
            this.n = n;
            this.level = level;
        }

        @Override
        protected void compute() {
            List<Subtree> forked = new ArrayList<>();
            IntStack work = new IntStack(5), madeSlots = new IntStack(1);
            work.push(slot, desc, first, n, level);
            int deepest = 0;
            int[] e = new int[5];
            while (work.size > 0) {
                work.pop(e);
                int s = e[0], d = e[1], f = e[2], count = e[3], lvl = e[4];
                deepest = Math.max(deepest, lvl);
                madeSlots.push(s);
                int mid = count == 1 ? -1 : b.split(f, count);
                if (mid < 0) {
                    b.leaf(s, f, count);
                    continue;
                }
                int nl = mid - f;
                b.interior(s, d);
                if (b.parallel && nl >= PARALLEL_PRIMS) {
                    Subtree left = new Subtree(b, d, d + 2, f, nl, lvl + 1);
                    left.fork();
                    forked.add(left);
                } else {
                    work.push(d, d + 2, f, nl, lvl + 1);
                }
                work.push(d + 1, d + 2 * nl, mid, count - nl, lvl + 1);
            }
            for (Subtree t : forked) {
                t.join();
            }
            // Boxes bottom-up: a node's children were made after it here, or by a joined task
            float[] nb = b.nodeBounds;
            for (int i = madeSlots.size - 1; i >= 0; i--) {
                int s = madeSlots.values[i], left = b.nodes[2 * s], count = b.nodes[2 * s + 1];
                if (count > 0) {
                    b.unionOf(left, count, nb, 6 * s);
                } else {
                    setEmpty(nb, 6 * s);
                    grow(nb, 6 * s, nb, 6 * left);
                    grow(nb, 6 * s, nb, 6 * left + 6);
                }
            }
            b.made(madeSlots.size, deepest);
        }
    }

    /** A growable stack of fixed-size int records. */
    static final class IntStack {
        final int width;
        int[] values;
        int size;

        IntStack(int width) {
            this.width = width;
            this.values = new int[64 * width];
        }

        void push(int a) {
            grow();
            values[size++] = a;
        }

        void push(int a, int b, int c, int d, int e) {
            grow();
            int o = width * size++;
            values[o] = a;
            values[o + 1] = b;
            values[o + 2] = c;
            values[o + 3] = d;
            values[o + 4] = e;
        }

        private void grow() {
            if (width * (size + 1) > values.length) {
                values = java.util.Arrays.copyOf(values, 2 * values.length);
            }
        }

        void pop(int[] into) {
            size--;
            System.arraycopy(values, width * size, into, 0, width);
        }
    }
}
