package org.beziertracer.accel;

import static org.beziertracer.accel.RayBox.MISS;

import org.beziertracer.math.Aabb;

/**
 * Binary bounding-volume hierarchy over primitive boxes, built with the binned SAH (I. Wald, "On
 * fast Construction of SAH-based Bounding Volume Hierarchies", IEEE RT 2007; see {@link
 * BinnedSahBuilder}), stored and traversed like tinybvh by J. Bikker.
 *
 * <p><b>Layout</b> (flat parallel arrays, root at node 0):
 * <ul>
 *   <li>{@code nodeBounds[6*i .. 6*i+5]} = {@code minX, minY, minZ, maxX, maxY, maxZ} of node i;
 *   <li>{@code count[i] > 0}: leaf holding primitives
 *       {@code primIndices[leftFirst[i] .. leftFirst[i]+count[i]-1]};
 *   <li>{@code count[i] == 0}: interior node with children {@code leftFirst[i]} and
 *       {@code leftFirst[i]+1} (always adjacent, always after their parent).
 * </ul>
 * {@code primIndices} is the identity permutation partitioned in place by the build ("leaf
 * order"). An empty BVH ({@code primCount == 0}) has one node with an empty box and misses
 * every ray.
 *
 * <p><b>Traversal.</b> Slab tests with the reciprocal direction ({@link RayBox}: zero components
 * are fine), near child first by entry distance, children entered beyond the current {@code tMax}
 * skipped. The caller owns the stack ({@code int[stackSize()]}); it holds pairs
 * {@code (node, floatBits(entry))} with the entry distance rounded down to {@code float}, so a
 * popped node is skipped without a second box test once {@code tMax} has shrunk below its entry.
 * Queries do not allocate.
 *
 * <p><b>Thread safety.</b> Immutable: every array is written only during build or refit and never
 * afterwards; accessors return copies. A built {@code Bvh} may be shared by any number of render
 * threads. {@link #refit} returns a new instance (sharing the unchanged topology arrays) and
 * leaves this one untouched, so it can be published while threads still trace the old one.
 */
public final class Bvh implements Accelerator {

    private final double[] nodeBounds;
    private final int[] leftFirst;
    private final int[] count;
    private final int[] primIndices;
    private final int depth;
    private final double buildMillis;

    Bvh(double[] nodeBounds, int[] leftFirst, int[] count, int[] primIndices, int depth,
            double buildMillis) {
        this.nodeBounds = nodeBounds;
        this.leftFirst = leftFirst;
        this.count = count;
        this.primIndices = primIndices;
        this.depth = depth;
        this.buildMillis = buildMillis;
    }

    /**
     * About the most heap {@link #build} holds at once for {@code primCount} primitives, in bytes:
     * the builder's arrays (centroids, primitive order, room for {@code 2n-1} nodes, work stack)
     * while the final node arrays are copied out of them. Keep this in step with
     * {@link BinnedSahBuilder} and the fields above when the layout changes.
     */
    public static long estimateBytes(long primCount) {
        long nodes = Math.max(1, 2 * primCount - 1);
        long nodeBytes = 6 * 8 + 4 + 4;                       // nodeBounds, leftFirst, count
        long builder = primCount * (3 * 8 + 4 + 2 * 4) + nodes * nodeBytes;
        return builder + nodes * nodeBytes;                   // + the final copy of the node arrays
    }

    /**
     * Builds a hierarchy over {@code primCount} boxes.
     *
     * @param primBounds six doubles per primitive ({@code minX, minY, minZ, maxX, maxY, maxZ}),
     *     finite with {@code min <= max}; read, not kept
     * @throws IllegalArgumentException for a short array or a non-finite or inverted box
     */
    public static Bvh build(double[] primBounds, int primCount, BvhOptions opts) {
        return BinnedSahBuilder.build(primBounds, primCount, opts);
    }

    /** Like {@link #build(double[], int, BvhOptions)} with {@link BvhOptions#defaults()}. */
    public static Bvh build(double[] primBounds, int primCount) {
        return build(primBounds, primCount, BvhOptions.defaults());
    }

    @Override
    public <Q> double closestHit(double ox, double oy, double oz, double invDx, double invDy,
            double invDz, double tMin, double tMax, LeafIntersector<Q> leaf, Q query, int[] stack) {
        final double[] b = nodeBounds;
        final int sx = RayBox.nearOffset(invDx), sy = RayBox.nearOffset(invDy),
                sz = RayBox.nearOffset(invDz);
        if (primIndices.length == 0
                || RayBox.slab(b, 0, ox, oy, oz, invDx, invDy, invDz, sx, sy, sz, tMin, tMax) == MISS) {
            return tMax;
        }
        int node = 0, sp = 0;
        for (;;) {
            int n = count[node];
            if (n > 0) {
                // Leaf: every primitive may shrink tMax
                for (int i = leftFirst[node], end = i + n; i < end; i++) {
                    tMax = leaf.intersect(query, primIndices[i], tMax);
                }
                node = -1;
            } else {
                // Interior: visit the nearer child, push the farther one with its entry
                int near = leftFirst[node], far = near + 1;
                double tNear = RayBox.slab(b, 6 * near, ox, oy, oz, invDx, invDy, invDz,
                        sx, sy, sz, tMin, tMax);
                double tFar = RayBox.slab(b, 6 * far, ox, oy, oz, invDx, invDy, invDz,
                        sx, sy, sz, tMin, tMax);
                if (tFar < tNear) {
                    double t = tNear;
                    tNear = tFar;
                    tFar = t;
                    int c = near;
                    near = far;
                    far = c;
                }
                if (tNear == MISS) {
                    node = -1;
                } else {
                    node = near;
                    if (tFar != MISS) {
                        stack[sp] = far;
                        stack[sp + 1] = Float.floatToRawIntBits(floorToFloat(tFar));
                        sp += 2;
                    }
                }
            }
            if (node < 0) {
                // Pop the next node still entered before tMax
                do {
                    if (sp == 0) {
                        return tMax;
                    }
                    sp -= 2;
                } while (Float.intBitsToFloat(stack[sp + 1]) > tMax);
                node = stack[sp];
            }
        }
    }

    @Override
    public <Q> boolean occluded(double ox, double oy, double oz, double invDx, double invDy,
            double invDz, double tMin, double tMax, LeafOccluder<Q> leaf, Q query, int[] stack) {
        final double[] b = nodeBounds;
        final int sx = RayBox.nearOffset(invDx), sy = RayBox.nearOffset(invDy),
                sz = RayBox.nearOffset(invDz);
        if (primIndices.length == 0
                || RayBox.slab(b, 0, ox, oy, oz, invDx, invDy, invDz, sx, sy, sz, tMin, tMax) == MISS) {
            return false;
        }
        int node = 0, sp = 0;
        for (;;) {
            int n = count[node];
            if (n > 0) {
                for (int i = leftFirst[node], end = i + n; i < end; i++) {
                    if (leaf.occludes(query, primIndices[i], tMax)) {
                        return true;
                    }
                }
                node = -1;
            } else {
                int left = leftFirst[node];
                boolean hitL = RayBox.slab(b, 6 * left, ox, oy, oz, invDx, invDy, invDz,
                        sx, sy, sz, tMin, tMax) != MISS;
                boolean hitR = RayBox.slab(b, 6 * left + 6, ox, oy, oz, invDx, invDy, invDz,
                        sx, sy, sz, tMin, tMax) != MISS;
                if (hitL) {
                    node = left;
                    if (hitR) {
                        stack[sp] = left + 1; // entry unused: tMax never shrinks here
                        sp += 2;
                    }
                } else {
                    node = hitR ? left + 1 : -1;
                }
            }
            if (node < 0) {
                if (sp == 0) {
                    return false;
                }
                sp -= 2;
                node = stack[sp];
            }
        }
    }

    /** Largest float not above {@code t} (conservative entry for the stack). */
    private static float floorToFloat(double t) {
        float f = (float) t;
        return f > t ? Math.nextDown(f) : f;
    }

    /** {@code 2 * depth()}: at most one pushed (node, entry) pair per level below the root. */
    @Override
    public int stackSize() {
        return 2 * depth;
    }

    @Override
    public Bvh refit(double[] newPrimBounds) {
        long start = System.nanoTime();
        int primCount = primIndices.length;
        checkBounds(newPrimBounds, primCount);
        int nodes = count.length;
        double[] nb = new double[6 * nodes];
        if (primCount == 0) {
            System.arraycopy(nodeBounds, 0, nb, 0, 6);
        }
        // Children always follow their parent, so a backward sweep is bottom-up
        for (int i = nodes - 1; i >= 0 && primCount > 0; i--) {
            int o = 6 * i;
            BinnedSahBuilder.setEmpty(nb, o);
            if (count[i] > 0) {
                for (int k = leftFirst[i], end = k + count[i]; k < end; k++) {
                    BinnedSahBuilder.grow(nb, o, newPrimBounds, 6 * primIndices[k]);
                }
            } else {
                BinnedSahBuilder.grow(nb, o, nb, 6 * leftFirst[i]);
                BinnedSahBuilder.grow(nb, o, nb, 6 * leftFirst[i] + 6);
            }
        }
        return new Bvh(nb, leftFirst, count, primIndices, depth, (System.nanoTime() - start) * 1e-6);
    }

    static void checkBounds(double[] primBounds, int primCount) {
        if (primCount < 0 || primBounds.length < 6 * (long) primCount) {
            throw new IllegalArgumentException("need 6 doubles for each of " + primCount
                    + " primitives, got an array of " + primBounds.length);
        }
        for (int p = 0; p < primCount; p++) {
            for (int a = 0; a < 3; a++) {
                double lo = primBounds[6 * p + a], hi = primBounds[6 * p + 3 + a];
                if (!Double.isFinite(lo) || !Double.isFinite(hi) || lo > hi) {
                    throw new IllegalArgumentException("primitive " + p + " has a bad box on axis "
                            + "xyz".charAt(a) + ": [" + lo + ", " + hi + "]");
                }
            }
        }
    }

    @Override
    public int nodeCount() {
        return count.length;
    }

    @Override
    public int depth() {
        return depth;
    }

    @Override
    public int primCount() {
        return primIndices.length;
    }

    @Override
    public double buildMillis() {
        return buildMillis;
    }

    /** Copy of the primitive indices in leaf order. */
    public int[] primIndices() {
        return primIndices.clone();
    }

    /** Primitive stored at position {@code slot} of the leaf order. */
    public int primIndex(int slot) {
        return primIndices[slot];
    }

    @Override
    public Aabb bounds() {
        return nodeBounds(0);
    }

    /** Box of node {@code node}. */
    public Aabb nodeBounds(int node) {
        int o = 6 * node;
        double[] b = nodeBounds;
        return new Aabb(b[o], b[o + 1], b[o + 2], b[o + 3], b[o + 4], b[o + 5]);
    }

    /** True when {@code node} is a leaf (an empty BVH's root counts as a leaf). */
    public boolean isLeaf(int node) {
        return count[node] > 0 || primIndices.length == 0;
    }

    /** Number of primitives in leaf {@code node}; 0 for an interior node. */
    public int leafPrimCount(int node) {
        return count[node];
    }

    /** Left child of an interior node (the right one is this + 1), or first leaf-order slot of a leaf. */
    public int nodeLeftFirst(int node) {
        return leftFirst[node];
    }

    /**
     * SAH cost of the tree relative to the root area (cost 1 per interior node entered, 4 per
     * primitive test, as in the build), a quality figure for reports; 0 when the root is flat.
     */
    public double sahCost() {
        double rootArea = BinnedSahBuilder.halfArea(nodeBounds, 0);
        if (!(rootArea > 0)) {
            return 0;
        }
        double sum = 0;
        for (int i = 0; i < count.length; i++) {
            double rel = BinnedSahBuilder.halfArea(nodeBounds, 6 * i) / rootArea;
            sum += rel * (count[i] > 0 ? BinnedSahBuilder.PRIMITIVE_COST * count[i]
                    : BinnedSahBuilder.TRAVERSAL_COST);
        }
        return sum;
    }

    @Override
    public String toString() {
        return "Bvh[prims=" + primCount() + ", nodes=" + nodeCount() + ", depth=" + depth
                + ", buildMillis=" + String.format(java.util.Locale.ROOT, "%.3f", buildMillis) + "]";
    }
}
