package org.beziertracer.accel;

import static org.beziertracer.accel.RayBox.MISS;
import static org.beziertracer.accel.RayBox.ROBUST_EXIT;

/**
 * The two halves of a packet query on a {@link Bvh} ({@link RayPacket}): {@link #gather} traverses
 * the tree once with the packet's interval bounds and lists the leaves it cannot rule out;
 * {@link #traceLanes} answers the packet's rays from that list, as the lanes of a batch, closest
 * hit or any hit (one loop for both). Stateless.
 */
final class PacketTraversal {

    private PacketTraversal() {}

    /**
     * Lists in {@code p} the leaves of {@code bvh} that some ray of the packet may enter at a
     * distance of at least {@code tMin}, nearest least entry first. Returns false (and the packet
     * is traced ray by ray) when the rays' directions are not traversable together or the list
     * would pass {@link RayPacket#MAX_LEAVES}. {@code tMax} must be at least every ray's own.
     */
    static boolean gather(Bvh bvh, RayPacket p, double tMin, double tMax, int[] stack) {
        p.gatheredBy = null;
        p.leafCount = 0;
        if (!p.reciprocals()) {
            return false;
        }
        final float[] b = bvh.nodeBounds;
        final int[] nd = bvh.nodes;
        // Per axis: the near plane (as one ray picks it, by the sign of invD), and the origin bound
        // that gives the least entry (resp. the greatest exit): fl(P - o) · invD falls as o grows
        // when invD > 0, rises when invD < 0.
        final boolean px = p.invLo[0] > 0, py = p.invLo[1] > 0, pz = p.invLo[2] > 0;
        final int sx = px ? 0 : 3, sy = py ? 0 : 3, sz = pz ? 0 : 3;
        final double nox = px ? p.oHi[0] : p.oLo[0], noy = py ? p.oHi[1] : p.oLo[1], noz = pz ? p.oHi[2] : p.oLo[2];
        final double fox = px ? p.oLo[0] : p.oHi[0], foy = py ? p.oLo[1] : p.oHi[1], foz = pz ? p.oLo[2] : p.oHi[2];
        final double lx = p.invLo[0], ly = p.invLo[1], lz = p.invLo[2];
        final double hx = p.invHi[0], hy = p.invHi[1], hz = p.invHi[2];
        if (bvh.primIndices.length == 0) {
            p.gatheredBy = bvh;
            return true;
        }
        int node = 0, sp = 0;
        double entry = enter(b, 0, sx, sy, sz, nox, noy, noz, fox, foy, foz, lx, ly, lz, hx, hy, hz, tMin, tMax);
        if (entry == MISS) {
            node = -1;
        }
        for (;;) {
            if (node >= 0) {
                int n = nd[2 * node + 1];
                if (n > 0) {
                    if (!insert(p, node, entry)) {
                        return false;
                    }
                    node = -1;
                } else {
                    int near = nd[2 * node], far = near + 1;
                    double tNear = enter(b, 6 * near, sx, sy, sz, nox, noy, noz, fox, foy, foz,
                            lx, ly, lz, hx, hy, hz, tMin, tMax);
                    double tFar = enter(b, 6 * far, sx, sy, sz, nox, noy, noz, fox, foy, foz,
                            lx, ly, lz, hx, hy, hz, tMin, tMax);
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
                        entry = tNear;
                        if (tFar != MISS) {
                            stack[sp] = far;
                            stack[sp + 1] = Float.floatToRawIntBits(RayBox.down(tFar));
                            sp += 2;
                        }
                    }
                }
            }
            if (node < 0) {
                if (sp == 0) {
                    p.gatheredBy = bvh;
                    return true;
                }
                sp -= 2;
                node = stack[sp];
                entry = Float.intBitsToFloat(stack[sp + 1]);
            }
        }
    }

    /**
     * The least entry distance (from {@code tMin} to {@code tMax}) of any ray of the packet into the box at
     * {@code o}, or {@link RayBox#MISS} when the bounds show that no ray meets it: per axis the
     * least near-plane distance and the greatest (robust) far-plane distance over the corners of
     * the origin and reciprocal-direction bounds.
     */
    private static double enter(float[] b, int o, int sx, int sy, int sz,
            double nox, double noy, double noz, double fox, double foy, double foz,
            double lx, double ly, double lz, double hx, double hy, double hz, double tMin, double tMax) {
        double near = tMin, far = tMax;
        double a = b[o + sx] - nox;
        double lo = a * (a >= 0 ? lx : hx);
        double c = b[o + 3 - sx] - fox;
        double hi = c * (c >= 0 ? hx : lx) * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        a = b[o + 1 + sy] - noy;
        lo = a * (a >= 0 ? ly : hy);
        c = b[o + 4 - sy] - foy;
        hi = c * (c >= 0 ? hy : ly) * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        a = b[o + 2 + sz] - noz;
        lo = a * (a >= 0 ? lz : hz);
        c = b[o + 5 - sz] - foz;
        hi = c * (c >= 0 ? hz : lz) * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        return near <= far && near < MISS ? near : MISS;
    }

    /** Inserts leaf {@code node} in entry order (the entry rounded down to a float); false when full. */
    private static boolean insert(RayPacket p, int node, double entry) {
        int n = p.leafCount;
        if (n == RayPacket.MAX_LEAVES) {
            return false;
        }
        float e = RayBox.down(entry);
        int i = n;
        while (i > 0 && p.leafEntry[i - 1] > e) {
            p.leafEntry[i] = p.leafEntry[i - 1];
            p.leafNodes[i] = p.leafNodes[i - 1];
            i--;
        }
        p.leafEntry[i] = e;
        p.leafNodes[i] = node;
        p.leafCount = n + 1;
        return true;
    }

    /**
     * The rays of a gathered packet, as lanes of a batch, leaf by leaf: at each listed leaf (nearest
     * least entry first), the lanes still open whose {@code tMax} has not passed the leaf's least
     * entry and whose own slab test passes go to the leaf's primitives together. Closest hits when
     * {@code closest} is given (a primitive lowers the {@code tMax} of the lanes it hits), any hits
     * when {@code any} is (a lane closes as soon as a primitive blocks it, {@code occluded[lane]}).
     *
     * <p><b>Why the answers are each ray's own.</b> A lane meets the primitives a ray alone would
     * meet with the same list: its own slab test on each listed leaf whose least entry is within its
     * {@code tMax}, in list order, with its {@code tMax} as its own earlier primitives left it. A
     * lane's answer depends on nothing but its own ray and {@code tMax}, so meeting the leaves side
     * by side with other lanes changes neither the answer nor the work. The list holds every leaf a
     * ray alone would visit ({@link RayPacket}), so the answer is the one of a traversal of its own;
     * a batch of one is how a single ray of a packet is traced.
     *
     * @param rays     per lane {@code i}, its origin and reciprocal direction at {@code rays[6i .. 6i+6)}
     * @param tMax     per lane; lowered by closest hits
     * @param occluded per lane, any hits only (null for closest hits): set when blocked; a lane set on
     *                 entry (blocked by something outside the hierarchy) is not traced
     * @param live, reached  scratch of at least {@code n} ints each
     */
    static <Q> void traceLanes(Bvh bvh, RayPacket p, double[] rays, int n, double tMin, double[] tMax,
            LaneIntersector<Q> closest, LaneOccluder<Q> any, Q query, int[] live, int[] reached, boolean[] occluded) {
        final float[] b = bvh.nodeBounds;
        final int[] nd = bvh.nodes;
        final int[] prims = bvh.primIndices;
        int liveCount = 0;
        for (int i = 0; i < n; i++) {
            if (any == null || !occluded[i]) {
                live[liveCount++] = i;
            }
        }
        for (int k = 0, count = p.leafCount; k < count && liveCount > 0; k++) {
            float entry = p.leafEntry[k];
            int kept = 0, reach = 0;
            int node = p.leafNodes[k];
            for (int j = 0; j < liveCount; j++) {
                int i = live[j];
                if (entry > tMax[i] || any != null && occluded[i]) {
                    continue; // answered: nothing left in reach (every later leaf starts farther still), or blocked
                }
                live[kept++] = i;
                int o = 6 * i;
                double invDx = rays[o + 3], invDy = rays[o + 4], invDz = rays[o + 5];
                if (RayBox.slab(b, 6 * node, rays[o], rays[o + 1], rays[o + 2], invDx, invDy, invDz,
                        RayBox.nearOffset(invDx), RayBox.nearOffset(invDy), RayBox.nearOffset(invDz), tMin, tMax[i])
                        != MISS) {
                    reached[reach++] = i;
                }
            }
            liveCount = kept;
            for (int q = nd[2 * node], end = q + nd[2 * node + 1]; q < end && reach > 0; q++) {
                if (any == null) {
                    closest.intersect(query, prims[q], reached, reach, tMax);
                    continue;
                }
                any.occludes(query, prims[q], reached, reach, tMax, occluded);
                // blocked lanes are answered: out of this leaf's list (and of the live list at the next leaf)
                int still = 0;
                for (int j = 0; j < reach; j++) {
                    if (!occluded[reached[j]]) {
                        reached[still++] = reached[j];
                    }
                }
                reach = still;
            }
        }
    }
}
