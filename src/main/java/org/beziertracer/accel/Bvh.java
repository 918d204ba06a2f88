package org.beziertracer.accel;

import static org.beziertracer.accel.RayBox.MISS;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.HeapBytes;

/**
 * Binary bounding-volume hierarchy over primitive boxes, built with the binned SAH (I. Wald, "On
 * fast Construction of SAH-based Bounding Volume Hierarchies", IEEE RT 2007; see {@link
 * BinnedSahBuilder}, which builds independent subtrees in parallel), stored and traversed like
 * tinybvh by J. Bikker.
 *
 * <p><b>Layout</b> (flat arrays, root at node 0, 32 bytes a node):
 * <ul>
 *   <li>{@code nodeBounds[6*i .. 6*i+5]} = {@code minX, minY, minZ, maxX, maxY, maxZ} of node i as
 *       floats, <b>rounded outward</b> from the double boxes given to {@link #build} (a node's box
 *       contains its primitives' double boxes, so no ray that meets a primitive's box misses its
 *       leaf because of the rounding);
 *   <li>{@code nodes[2*i] = leftFirst}, {@code nodes[2*i+1] = count};
 *   <li>{@code count > 0}: leaf holding primitives
 *       {@code primIndices[leftFirst .. leftFirst+count-1]};
 *   <li>{@code count == 0}: interior node with children {@code leftFirst} and {@code leftFirst+1}
 *       (always adjacent, always after their parent).
 * </ul>
 * {@code primIndices} is the identity permutation partitioned in place by the build ("leaf
 * order"). An empty BVH ({@code primCount == 0}) has one node with an empty box and misses
 * every ray. A build is deterministic: the same boxes give the same arrays, however many threads
 * built it.
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

    /** Bytes of one node: six float bounds and two ints. */
    static final int NODE_BYTES = 6 * 4 + 2 * 4;

    final float[] nodeBounds;
    final int[] nodes;
    final int[] primIndices;
    private final int depth;
    private final double buildMillis;

    Bvh(float[] nodeBounds, int[] nodes, int[] primIndices, int depth, double buildMillis) {
        this.nodeBounds = nodeBounds;
        this.nodes = nodes;
        this.primIndices = primIndices;
        this.depth = depth;
        this.buildMillis = buildMillis;
    }

    /** Bytes per primitive a build holds besides the nodes: the larger of the two builders'. */
    static final int BUILD_BYTES_PER_PRIM = Math.max(
            4 + 6 * 4 + 3 * 4,                     // binned SAH: leaf order, float boxes, centroids
            4 + 6 * 4 + 8 + 2 * 4);                // Morton: leaf order, float boxes, codes, made-node lists

    /**
     * About the most heap {@link #build} holds at once for {@code primCount} primitives, in bytes
     * (not counting the caller's boxes): the builder's float boxes, centroids or codes, and the
     * primitive order, and the node arrays, written in place (room for {@code 2n-1} nodes). Keep
     * this in step with {@link BinnedSahBuilder}, {@link MortonBuilder} and the fields above when
     * the layout changes.
     */
    public static long estimateBytes(long primCount) {
        long nodes = Math.max(1, 2 * primCount - 1);
        return primCount * BUILD_BYTES_PER_PRIM + nodes * NODE_BYTES;
    }

    /** Heap held by this hierarchy's arrays, in bytes (array headers included). */
    @Override
    public long bytes() {
        return HeapBytes.of(nodeBounds) + HeapBytes.of(nodes) + HeapBytes.of(primIndices);
    }

    /**
     * Builds a hierarchy over {@code primCount} boxes: with the binned SAH, or in Morton order
     * from {@link BvhOptions#mortonPrims()} primitives on.
     *
     * @param primBounds six doubles per primitive ({@code minX, minY, minZ, maxX, maxY, maxZ}),
     *     finite with {@code min <= max}; read, not kept
     * @throws IllegalArgumentException for a short array or a non-finite or inverted box
     */
    public static Bvh build(double[] primBounds, int primCount, BvhOptions opts) {
        return primCount >= opts.mortonPrims() ? MortonBuilder.build(primBounds, primCount, opts)
                : BinnedSahBuilder.build(primBounds, primCount, opts);
    }

    /**
     * Builds a hierarchy over {@code primCount} boxes that come in contiguous groups, in two
     * levels ({@link GroupedBuilder}): a tree per group, then one over the groups.
     *
     * @param groupFirst the first primitive of each group, then {@code primCount}: group {@code j}
     *     is {@code groupFirst[j] .. groupFirst[j+1]-1} (may be empty)
     * @throws IllegalArgumentException for a bad box (as {@link #build(double[], int, BvhOptions)})
     *     or groups that do not cover {@code 0 .. primCount-1} in order
     */
    public static Bvh build(double[] primBounds, int primCount, int[] groupFirst, BvhOptions opts) {
        return GroupedBuilder.build(primBounds, primCount, groupFirst, opts);
    }

    /** The node boxes and nodes ({@code leftFirst, count} pairs), copies, for tests. */
    float[] nodeBoundsCopy() {
        return nodeBounds.clone();
    }

    int[] nodesCopy() {
        return nodes.clone();
    }

    /** Like {@link #build(double[], int, BvhOptions)} with {@link BvhOptions#defaults()}. */
    public static Bvh build(double[] primBounds, int primCount) {
        return build(primBounds, primCount, BvhOptions.defaults());
    }

    @Override
    public <Q> double closestHit(double ox, double oy, double oz, double invDx, double invDy,
            double invDz, double tMin, double tMax, LeafIntersector<Q> leaf, Q query, int[] stack) {
        final float[] b = nodeBounds;
        final int[] nd = nodes;
        final int sx = RayBox.nearOffset(invDx), sy = RayBox.nearOffset(invDy),
                sz = RayBox.nearOffset(invDz);
        if (primIndices.length == 0
                || RayBox.slab(b, 0, ox, oy, oz, invDx, invDy, invDz, sx, sy, sz, tMin, tMax) == MISS) {
            return tMax;
        }
        int node = 0, sp = 0;
        for (;;) {
            int n = nd[2 * node + 1];
            if (n > 0) {
                // Leaf: every primitive may shrink tMax
                for (int i = nd[2 * node], end = i + n; i < end; i++) {
                    tMax = leaf.intersect(query, primIndices[i], tMax);
                }
                node = -1;
            } else {
                // Interior: visit the nearer child, push the farther one with its entry
                int near = nd[2 * node], far = near + 1;
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
                        stack[sp + 1] = Float.floatToRawIntBits(RayBox.down(tFar));
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
        final float[] b = nodeBounds;
        final int[] nd = nodes;
        final int sx = RayBox.nearOffset(invDx), sy = RayBox.nearOffset(invDy),
                sz = RayBox.nearOffset(invDz);
        if (primIndices.length == 0
                || RayBox.slab(b, 0, ox, oy, oz, invDx, invDy, invDz, sx, sy, sz, tMin, tMax) == MISS) {
            return false;
        }
        int node = 0, sp = 0;
        for (;;) {
            int n = nd[2 * node + 1];
            if (n > 0) {
                for (int i = nd[2 * node], end = i + n; i < end; i++) {
                    if (leaf.occludes(query, primIndices[i], tMax)) {
                        return true;
                    }
                }
                node = -1;
            } else {
                int left = nd[2 * node];
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

    @Override
    public boolean gather(RayPacket packet, double tMin, double tMax, int[] stack) {
        return PacketTraversal.gather(this, packet, tMin, tMax, stack);
    }

    /**
     * Closest hits of all {@code n} rays of a packet this hierarchy {@linkplain #gather gathered},
     * leaf by leaf: each leaf gets the lanes that reach it together ({@link LaneIntersector}); every
     * lane gets the answer a traversal of its own gives it ({@link PacketTraversal#traceLanes}).
     *
     * @param rays          per lane {@code i}: origin and reciprocal direction at {@code rays[6i .. 6i+6)}
     * @param tMax          per lane; lowered to each lane's closest hit
     * @param live, reached scratch of at least {@code n} ints each
     * @throws IllegalStateException when the packet was not gathered by this hierarchy
     */
    public <Q> void closestHitsIn(RayPacket packet, double[] rays, int n, double tMin, double[] tMax,
            LaneIntersector<Q> leaf, Q query, int[] live, int[] reached) {
        requireGathered(packet);
        PacketTraversal.traceLanes(this, packet, rays, n, tMin, tMax, leaf, null, query, live, reached, null);
    }

    /**
     * Any-hit answers of all {@code n} rays of a packet this hierarchy {@linkplain #gather gathered},
     * leaf by leaf ({@link LaneOccluder}); every lane gets the answer a traversal of its own gives it.
     *
     * @param rays          per lane {@code i}: origin and reciprocal direction at {@code rays[6i .. 6i+6)}
     * @param occluded      per lane, set when blocked (lanes set on entry are not traced)
     * @param live, reached scratch of at least {@code n} ints each
     * @throws IllegalStateException when the packet was not gathered by this hierarchy
     */
    public <Q> void occludedAllIn(RayPacket packet, double[] rays, int n, double tMin, double[] tMax,
            LaneOccluder<Q> leaf, Q query, int[] live, int[] reached, boolean[] occluded) {
        requireGathered(packet);
        PacketTraversal.traceLanes(this, packet, rays, n, tMin, tMax, null, leaf, query, live, reached, occluded);
    }

    private void requireGathered(RayPacket packet) {
        if (!packet.gatheredBy(this)) {
            throw new IllegalStateException("the packet was not gathered by this hierarchy");
        }
    }

    /** {@code 2 * depth()}: at most one pushed (node, entry) pair per level below the root. */
    @Override
    public int stackSize() {
        return 2 * depth;
    }

    /**
     * A new hierarchy, same topology, over new boxes for every primitive (see {@link #refit(double[],
     * int, int)}).
     */
    @Override
    public Bvh refit(double[] newPrimBounds) {
        checkBounds(newPrimBounds, primIndices.length);
        return refit(newPrimBounds, 0, primIndices.length);
    }

    /**
     * A new hierarchy, same topology, where primitives {@code first .. first+count-1} have new
     * boxes and the others keep theirs: a leaf that holds only changed primitives gets the union of
     * their new boxes; a leaf that mixes changed and unchanged ones grows to hold the new boxes too
     * (its old box already holds the unchanged ones: conservative, never too small); their
     * ancestors are recomputed; every other node keeps its box. This instance is unchanged. Cost:
     * one pass over the nodes.
     *
     * @param rangeBounds six doubles for each changed primitive, in order from {@code first}
     * @throws IllegalArgumentException for a short array, a range outside the primitives or a
     *     non-finite or inverted box
     */
    public Bvh refit(double[] rangeBounds, int first, int count) {
        long start = System.nanoTime();
        int primCount = primIndices.length;
        if (first < 0 || count < 0 || first > primCount - count) {
            throw new IllegalArgumentException("primitives " + first + ".." + (first + count - 1)
                    + " are not among the " + primCount + " of this hierarchy");
        }
        checkBounds(rangeBounds, count);
        float[] nb = nodeBounds.clone();
        int nodeCount = nodes.length / 2;
        boolean[] dirty = new boolean[nodeCount];
        // Children always follow their parent, so a backward sweep is bottom-up
        for (int i = nodeCount - 1; i >= 0 && count > 0; i--) {
            int lf = nodes[2 * i], n = nodes[2 * i + 1], o = 6 * i;
            if (n > 0) {
                int changed = 0;
                for (int k = lf; k < lf + n; k++) {
                    changed += primIndices[k] - first >= 0 && primIndices[k] - first < count ? 1 : 0;
                }
                if (changed > 0) {
                    dirty[i] = true;
                    if (changed == n) {
                        BvhBuild.setEmpty(nb, o);
                    }
                    for (int k = lf; k < lf + n; k++) {
                        int r = primIndices[k] - first;
                        if (r >= 0 && r < count) {
                            BvhBuild.growRounded(nb, o, rangeBounds, 6 * r);
                        }
                    }
                }
            } else if (dirty[lf] || dirty[lf + 1]) {
                dirty[i] = true;
                BvhBuild.setEmpty(nb, o);
                BvhBuild.grow(nb, o, nb, 6 * lf);
                BvhBuild.grow(nb, o, nb, 6 * lf + 6);
            }
        }
        return new Bvh(nb, nodes, primIndices, depth, (System.nanoTime() - start) * 1e-6);
    }

    /** Throws, naming the primitive and axis, when the array is short or a box is bad. */
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
        return nodes.length / 2;
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

    /** Box of node {@code node} (the stored floats, as doubles). */
    public Aabb nodeBounds(int node) {
        int o = 6 * node;
        float[] b = nodeBounds;
        if (b[o] > b[o + 3]) {
            return Aabb.EMPTY;
        }
        return new Aabb(b[o], b[o + 1], b[o + 2], b[o + 3], b[o + 4], b[o + 5]);
    }

    /** True when {@code node} is a leaf (an empty BVH's root counts as a leaf). */
    public boolean isLeaf(int node) {
        return nodes[2 * node + 1] > 0 || primIndices.length == 0;
    }

    /** Number of primitives in leaf {@code node}; 0 for an interior node. */
    public int leafPrimCount(int node) {
        return nodes[2 * node + 1];
    }

    /** Left child of an interior node (the right one is this + 1), or first leaf-order slot of a leaf. */
    public int nodeLeftFirst(int node) {
        return nodes[2 * node];
    }

    /**
     * SAH cost of the tree relative to the root area (cost 1 per interior node entered, 4 per
     * primitive test, as in the build), a quality figure for reports; 0 when the root is flat.
     */
    public double sahCost() {
        double rootArea = BvhBuild.halfArea(nodeBounds, 0);
        if (!(rootArea > 0)) {
            return 0;
        }
        double sum = 0;
        for (int i = 0; i < nodeCount(); i++) {
            double rel = BvhBuild.halfArea(nodeBounds, 6 * i) / rootArea;
            int n = nodes[2 * i + 1];
            sum += rel * (n > 0 ? BinnedSahBuilder.PRIMITIVE_COST * n : BinnedSahBuilder.TRAVERSAL_COST);
        }
        return sum;
    }

    @Override
    public String toString() {
        return "Bvh[prims=" + primCount() + ", nodes=" + nodeCount() + ", depth=" + depth
                + ", buildMillis=" + String.format(java.util.Locale.ROOT, "%.3f", buildMillis) + "]";
    }
}
