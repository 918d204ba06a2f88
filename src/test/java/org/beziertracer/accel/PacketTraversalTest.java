package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Packets of rays traversed together ({@link RayPacket}, {@link PacketTraversal}) against the
 * same rays one at a time, on seeded random boxes: every leaf a ray's own slab test accepts is in
 * the packet's list, and the answers are the same to the bit.
 */
class PacketTraversalTest {

    /** A packet of {@code n} rays about a random direction: one origin, or origins spread over a small box. */
    private static double[] randomPacket(Random rnd, int n) {
        double[] o = {-15 + 30 * rnd.nextDouble(), -15 + 30 * rnd.nextDouble(), -15 + 30 * rnd.nextDouble()};
        // Aim at the middle of the boxes, so most packets meet some
        double[] d = {rnd.nextGaussian() - o[0] / 15, rnd.nextGaussian() - o[1] / 15, rnd.nextGaussian() - o[2] / 15};
        double spread = Math.pow(10, -6 + 6 * rnd.nextDouble());
        double originSpread = rnd.nextBoolean() ? 0 : Math.pow(10, -4 + 4 * rnd.nextDouble());
        double[] rays = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                rays[6 * i + a] = o[a] + originSpread * (2 * rnd.nextDouble() - 1);
                rays[6 * i + 3 + a] = d[a] + spread * (2 * rnd.nextDouble() - 1);
            }
        }
        return rays;
    }

    private static boolean oneSignPerAxis(double[] rays, int n) {
        for (int a = 0; a < 3; a++) {
            boolean pos = false, neg = false;
            for (int i = 0; i < n; i++) {
                double d = rays[6 * i + 3 + a];
                pos |= d > 0;
                neg |= !(d > 0);
            }
            if (pos && neg || neg && anyZero(rays, n, a)) {
                return false;
            }
        }
        return true;
    }

    private static boolean anyZero(double[] rays, int n, int a) {
        for (int i = 0; i < n; i++) {
            if (rays[6 * i + 3 + a] == 0) {
                return true;
            }
        }
        return false;
    }

    @Test
    void everyLeafARayEntersIsListedAndTheAnswersAreTheSame() {
        int packets = 0, gathered = 0, hits = 0, checkedLeaves = 0;
        for (long seed = 1; seed <= 40; seed++) {
            Random rnd = new Random(seed);
            int count = 50 + rnd.nextInt(400);
            double[] boxes = seed % 2 == 0 ? BoxScene.randomBoxes(rnd, count) : tiles(rnd, count);
            BoxScene scene = new BoxScene(boxes, count);
            Bvh bvh = Bvh.build(scene.bounds, count);
            int[] stack = bvh.newStack();
            RayPacket packet = new RayPacket();
            for (int k = 0; k < 60; k++) {
                int n = 1 + rnd.nextInt(16);
                double[] rays = randomPacket(rnd, n);
                double tMin = rnd.nextInt(4) == 0 ? 1.0 : 0.0;
                double tMax = rnd.nextInt(3) == 0 ? 5 + 20 * rnd.nextDouble() : Double.POSITIVE_INFINITY;
                packets++;
                boolean ok = bvh.gather(packet.of(rays, n), tMin, tMax, stack);
                String where = "seed " + seed + " packet " + k;
                if (!oneSignPerAxis(rays, n)) {
                    assertFalse(ok, where + ": a packet whose directions change sign is not gathered");
                    continue;
                }
                if (!ok) {
                    assertEquals(RayPacket.MAX_LEAVES, packet.leafCount(), where + ": only a full list may fail");
                    continue;
                }
                gathered++;
                assertTrue(packet.gatheredBy(bvh));
                for (int j = 1; j < packet.leafCount; j++) {
                    assertTrue(packet.leafEntry[j - 1] <= packet.leafEntry[j], where + ": entries ascend");
                }
                for (int i = 0; i < n; i++) {
                    int o = 6 * i;
                    scene.setRay(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], tMin);
                    // Every leaf the ray's own test accepts is listed, no later than the ray enters it
                    for (int node = 0; node < bvh.nodeCount(); node++) {
                        if (bvh.leafPrimCount(node) == 0) {
                            continue;
                        }
                        double entry = RayBox.entry(bvh.nodeBounds, 6 * node, scene.ox, scene.oy, scene.oz,
                                scene.invDx, scene.invDy, scene.invDz, tMin, tMax);
                        if (entry != RayBox.MISS) {
                            checkedLeaves++;
                            int at = indexOf(packet, node);
                            assertTrue(at >= 0, where + " ray " + i + ": leaf " + node + " entered at " + entry
                                    + " is not listed; " + scene.ray());
                            assertTrue(packet.leafEntry[at] <= entry, where + ": listed entry beyond the ray's");
                        }
                    }
                    double alone = bvh.closestHit(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                            scene.invDz, tMin, tMax, scene, scene, stack);
                    scene.resetCalls();
                    double together = closestHitIn(bvh, packet, scene, tMin, tMax);
                    assertEquals(-1, scene.calledTwice, where + ": a primitive called twice");
                    assertEquals(alone, together, 0, where + " ray " + i + ": closest hit; " + scene.ray());
                    assertEquals(scene.bruteForce(tMax), together, 0, where + ": brute force");
                    hits += together < tMax ? 1 : 0;
                    double shorter = together < tMax ? together * (0.5 + rnd.nextDouble()) : tMax;
                    assertEquals(bvh.occluded(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy, scene.invDz,
                                    tMin, shorter, scene, scene, stack),
                            occludedIn(bvh, packet, scene, tMin, shorter), where + ": occluded");
                }
            }
        }
        // The property was exercised, not skipped
        assertTrue(gathered > packets / 2, gathered + " of " + packets + " packets gathered");
        assertTrue(hits > 1000, hits + " hits");
        assertTrue(checkedLeaves > 5000, checkedLeaves + " leaves entered");
    }

    /**
     * Boxes that tile a block of space as sub-patch boxes do: cells of a grid sharing their faces,
     * each face moved by up to 10⁻³ (or not at all), so that rays enter neighbouring boxes at
     * equal or nearly equal distances.
     */
    private static double[] tiles(Random rnd, int n) {
        double[] b = new double[6 * n];
        int side = (int) Math.ceil(Math.cbrt(n));
        double cell = 20.0 / side;
        for (int p = 0; p < n; p++) {
            if (p > 0 && rnd.nextInt(3) == 0) {
                // a near twin of the last box: entries a hair apart
                for (int a = 0; a < 6; a++) {
                    b[6 * p + a] = b[6 * p - 6 + a] + (a < 3 ? -1 : 1) * 1e-4 * rnd.nextDouble();
                }
                continue;
            }
            int[] ijk = {p % side, p / side % side, p / (side * side)};
            for (int a = 0; a < 3; a++) {
                double jitter = rnd.nextBoolean() ? 0 : 1e-3 * rnd.nextDouble();
                b[6 * p + a] = -10 + ijk[a] * cell + jitter;
                b[6 * p + 3 + a] = -10 + (ijk[a] + 1) * cell - (rnd.nextBoolean() ? 0 : jitter);
            }
        }
        return b;
    }

    @Test
    void anySortedListOfLowerBoundsGivesTheClosestHit() {
        // the batch traversal's contract, apart from gather: a list of every leaf, each with any lower
        // bound of the ray's entry, ascending, gives the brute-force answer
        Random rnd = new Random(5);
        int checked = 0;
        for (int round = 0; round < 30; round++) {
            int count = 100 + rnd.nextInt(300);
            BoxScene scene = new BoxScene(tiles(rnd, count), count);
            Bvh bvh = Bvh.build(scene.bounds, count);
            RayPacket p = new RayPacket();
            for (int r = 0; r < 200; r++) {
                scene.randomRay(rnd);
                double tMax = Double.POSITIVE_INFINITY;
                p.leafCount = 0;
                for (int node = 0; node < bvh.nodeCount() && p.leafCount < RayPacket.MAX_LEAVES; node++) {
                    if (bvh.leafPrimCount(node) == 0) {
                        continue;
                    }
                    double e = RayBox.entry(bvh.nodeBounds, 6 * node, scene.ox, scene.oy, scene.oz, scene.invDx,
                            scene.invDy, scene.invDz, scene.tMin, tMax);
                    double slack = rnd.nextInt(4) == 0 ? 0 : 2e-4 * rnd.nextDouble();
                    double bound = e == RayBox.MISS ? scene.tMin + 40 * rnd.nextDouble() : Math.max(scene.tMin, e - slack);
                    p.leafNodes[p.leafCount] = node;
                    p.leafEntry[p.leafCount++] = RayBox.down(bound);
                }
                if (p.leafCount == RayPacket.MAX_LEAVES) {
                    continue;
                }
                sortByEntry(p);
                p.gatheredBy = bvh;
                double together = closestHitIn(bvh, p, scene, scene.tMin, tMax);
                assertEquals(scene.bruteForce(tMax), together, 0, "round " + round + ": " + scene.ray());
                if (together < tMax) {
                    checked++;
                    // A shadow ray that ends just past the nearest box is blocked by it, one that ends at it is not
                    assertTrue(occludedIn(bvh, p, scene, scene.tMin, Math.nextUp(together)), "round " + round + ": " + scene.ray());
                    assertFalse(occludedIn(bvh, p, scene, scene.tMin, together), "round " + round + ": " + scene.ray());
                }
            }
        }
        assertTrue(checked > 500, checked + " hits");
    }

    private static void sortByEntry(RayPacket p) {
        for (int i = 1; i < p.leafCount; i++) {
            for (int j = i; j > 0 && p.leafEntry[j - 1] > p.leafEntry[j]; j--) {
                float e = p.leafEntry[j];
                p.leafEntry[j] = p.leafEntry[j - 1];
                p.leafEntry[j - 1] = e;
                int n = p.leafNodes[j];
                p.leafNodes[j] = p.leafNodes[j - 1];
                p.leafNodes[j - 1] = n;
            }
        }
    }

    @Test
    void raysThroughABoxEdgeThatOnlyTheRoundingAllowanceAcceptsAreListed() {
        // Rays aimed exactly at a point of an edge of the unit box: entry on one axis and exit on
        // another are the same distance, rounded two ways. Keep those whose own test passes only
        // because exits are scaled by 1 + 2γ₃, and check that a packet of them lists the box.
        double[] box = {0, 0, 0, 1, 1, 1};
        Bvh bvh = Bvh.build(box, 1);
        RayPacket p = new RayPacket();
        Random rnd = new Random(11);
        int found = 0;
        for (int k = 0; k < 400_000 && found < 60; k++) {
            // Enter across the plane x_a = 0, leave across x_b = 1 at the same point (then mirror
            // each axis at random: x -> 1 - x maps the box onto itself)
            int a = rnd.nextInt(3), b = (a + 1 + rnd.nextInt(2)) % 3, c = 3 - a - b;
            double[] o = new double[3], at = new double[3];
            o[a] = -1 - 3 * rnd.nextDouble();
            o[b] = 1 - 3 * rnd.nextDouble();
            o[c] = rnd.nextDouble();
            at[a] = 0;
            at[b] = 1;
            at[c] = rnd.nextDouble();
            for (int m = 0; m < 3; m++) {
                if (rnd.nextBoolean()) {
                    o[m] = 1 - o[m];
                    at[m] = 1 - at[m];
                }
            }
            double[] d = {at[0] - o[0], at[1] - o[1], at[2] - o[2]};
            if (d[0] == 0 || d[1] == 0 || d[2] == 0) {
                continue;
            }
            double[] inv = {1 / d[0], 1 / d[1], 1 / d[2]};
            // The slab interval without the allowance
            double near = 0, far = Double.POSITIVE_INFINITY;
            for (int m = 0; m < 3; m++) {
                double lo = ((inv[m] > 0 ? 0 : 1) - o[m]) * inv[m], hi = ((inv[m] > 0 ? 1 : 0) - o[m]) * inv[m];
                near = Math.max(near, lo);
                far = Math.min(far, hi);
            }
            if (!(near > far)) {
                continue;   // this one meets the edge even without the allowance
            }
            found++;
            double[] rays = {o[0], o[1], o[2], d[0], d[1], d[2]};
            assertTrue(RayBox.entry(box, 0, o[0], o[1], o[2], inv[0], inv[1], inv[2], 0, Double.POSITIVE_INFINITY)
                    != RayBox.MISS, "the ray's own test accepts the box");
            assertTrue(bvh.gather(p.of(rays, 1), 0, Double.POSITIVE_INFINITY, bvh.newStack()));
            assertEquals(1, p.leafCount(), "the packet lists the box its ray enters at the edge");
        }
        assertTrue(found >= 60, "only " + found + " rays that need the allowance");
    }

    private static int indexOf(RayPacket p, int node) {
        for (int j = 0; j < p.leafCount; j++) {
            if (p.leafNodes[j] == node) {
                return j;
            }
        }
        return -1;
    }

    @Test
    void zeroDirectionsSignChangesAndNaNAreNotGathered() {
        Random rnd = new Random(7);
        BoxScene scene = new BoxScene(BoxScene.randomBoxes(rnd, 100), 100);
        Bvh bvh = Bvh.build(scene.bounds, 100);
        int[] stack = bvh.newStack();
        RayPacket p = new RayPacket();
        double[][] bad = {
            {0, 0, -20, 0.1, 0.2, 1, 0, 0, -20, 0.0, 0.2, 1},      // a zero component
            {0, 0, -20, 0.1, 0.2, 1, 0, 0, -20, -0.1, 0.2, 1},     // a sign change
            {0, 0, -20, 0.1, 0.2, 1, Double.NaN, 0, -20, 0.1, 0.2, 1},
            {0, 0, -20, 0.1, 0.2, 1, 0, 0, -20, 0.1, Double.NaN, 1},
            {0, 0, -20, 0.1, 0.2, 1, Double.POSITIVE_INFINITY, 0, -20, 0.1, 0.2, 1},
        };
        for (double[] rays : bad) {
            assertFalse(bvh.gather(p.of(rays, 2), 0, Double.POSITIVE_INFINITY, stack));
            assertFalse(p.gatheredBy(bvh));
            assertThrows(IllegalStateException.class, () -> bvh.closestHitsIn(p, new double[] {0, 0, -20, 10, 5, 1}, 1, 0,
                    new double[] {Double.POSITIVE_INFINITY}, lanes(scene), scene, new int[1], new int[1]));
        }
        // A good packet is gathered, and adding a ray afterwards makes it stale
        double[] good = {0, 0, -20, 0.1, 0.2, 1, 0, 0, -20, 0.11, 0.2, 1};
        assertTrue(bvh.gather(p.of(good, 2), 0, Double.POSITIVE_INFINITY, stack));
        assertTrue(p.gatheredBy(bvh));
        p.add(0, 0, -20, 0.1, 0.21, 1);
        assertFalse(p.gatheredBy(bvh));
        // A packet of one hierarchy is refused by another, and by the flat list
        assertTrue(bvh.gather(p.of(good, 2), 0, Double.POSITIVE_INFINITY, stack));
        Bvh other = Bvh.build(scene.bounds, 100);
        assertThrows(IllegalStateException.class, () -> other.occludedAllIn(p, new double[] {0, 0, -20, 10, 5, 1}, 1, 0,
                new double[] {1}, anyLanes(scene), scene, new int[1], new int[1], new boolean[1]));
        assertFalse(FlatList.build(scene.bounds, 100).gather(p, 0, Double.POSITIVE_INFINITY, null));
    }

    @Test
    void aPacketOverMoreLeavesThanTheListHoldsIsNotGathered() {
        // A row of tiny boxes along x, and a packet that sweeps the whole row
        int n = 4 * RayPacket.MAX_LEAVES;
        double[] b = new double[6 * n];
        for (int i = 0; i < n; i++) {
            double x = -10 + 20.0 * i / n;
            double[] box = {x, -0.01, -0.01, x + 0.001, 0.01, 0.01};
            System.arraycopy(box, 0, b, 6 * i, 6);
        }
        Bvh bvh = Bvh.build(b, n, BvhOptions.defaults());
        RayPacket p = new RayPacket();
        double[] wide = {0, -0.001, -5, -0.9, 0.0001, 0.5, 0, -0.001, -5, 0.9, 0.0001, 0.5};
        double[] wideSameSign = {-11, -0.001, -5, 0.01, 0.0001, 0.5, -11, -0.001, -5, 4, 0.0001, 0.5};
        assertFalse(bvh.gather(p.of(wide, 2), 0, Double.POSITIVE_INFINITY, bvh.newStack()), "sign change");
        assertFalse(bvh.gather(p.of(wideSameSign, 2), 0, Double.POSITIVE_INFINITY, bvh.newStack()));
        assertEquals(RayPacket.MAX_LEAVES, p.leafCount());
        assertFalse(p.gatheredBy(bvh));
    }

    /**
     * The closest hit of the scene's current ray, a packet's ray alone: a batch of one lane
     * ({@link Bvh#closestHitsIn}), the scene's own leaf test for it.
     */
    static double closestHitIn(Bvh bvh, RayPacket p, BoxScene scene, double tMin, double tMax) {
        double[] t = {tMax};
        bvh.closestHitsIn(p, new double[] {scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy, scene.invDz}, 1,
                tMin, t, lanes(scene), scene, new int[1], new int[1]);
        return t[0];
    }

    /** {@link #closestHitIn} for an any-hit query ({@link Bvh#occludedAllIn}). */
    static boolean occludedIn(Bvh bvh, RayPacket p, BoxScene scene, double tMin, double tMax) {
        boolean[] blocked = {false};
        bvh.occludedAllIn(p, new double[] {scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy, scene.invDz}, 1,
                tMin, new double[] {tMax}, anyLanes(scene), scene, new int[1], new int[1], blocked);
        return blocked[0];
    }

    /** The scene's closest-hit leaf test over lanes (one lane: the scene's current ray). */
    static LaneIntersector<BoxScene> lanes(BoxScene scene) {
        return (q, prim, lanes, count, tMax) -> {
            for (int j = 0; j < count; j++) {
                tMax[lanes[j]] = q.intersect(q, prim, tMax[lanes[j]]);
            }
        };
    }

    /** The scene's any-hit leaf test over lanes (one lane: the scene's current ray). */
    static LaneOccluder<BoxScene> anyLanes(BoxScene scene) {
        return (q, prim, lanes, count, tMax, occluded) -> {
            for (int j = 0; j < count; j++) {
                occluded[lanes[j]] |= q.occludes(q, prim, tMax[lanes[j]]);
            }
        };
    }
}
