package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROOT_UV;
import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * The steps of {@link BezierClipper} one by one, against values worked out independently: the
 * clip line, the clipped interval of a piece whose distances are exactly linear, the split that
 * puts the nearer half on top, the polish of a candidate and Newton confined to a piece.
 */
class ClippingStepsTest {

    /** A net of {@code count} random points with random garbage before and after, at a random base. */
    private static double[] netWithGarbage(Random rnd, int count, int base) {
        double[] a = new double[base + 3 * count + 30];
        for (int k = 0; k < a.length; k++) {
            a[k] = 10 * rnd.nextGaussian();
        }
        return a;
    }

    /** The mean of two edges of the corners (xy), the direction {@link BezierClipper#clipLine} starts from. */
    private static double[] meanEdge(double[] net, int base, int n, int m, boolean alongU) {
        int row = 3 * (n + 1);
        int p00 = base, pn0 = base + 3 * n, p0m = base + row * m, pnm = base + row * m + 3 * n;
        if (alongU) { // the v edges: P00→P0m and Pn0→Pnm
            return new double[] {net[p0m] - net[p00] + net[pnm] - net[pn0], net[p0m + 1] - net[p00 + 1] + net[pnm + 1] - net[pn0 + 1]};
        }
        return new double[] {net[pn0] - net[p00] + net[pnm] - net[p0m], net[pn0 + 1] - net[p00 + 1] + net[pnm + 1] - net[p0m + 1]};
    }

    private static double[] unit(double x, double y) {
        double l = Math.hypot(x, y);
        return new double[] {x / l, y / l};
    }

    @Test
    void theClipLineFollowsTheMeanOfTheOtherDirectionsEdges() {
        Random rnd = new Random(1990);
        double[] out = new double[2];
        for (int trial = 0; trial < 500; trial++) {
            int n = 1 + rnd.nextInt(7), m = 1 + rnd.nextInt(7), base = 3 * rnd.nextInt(40);
            double[] net = netWithGarbage(rnd, (n + 1) * (m + 1), base);
            for (boolean alongU : new boolean[] {true, false}) {
                double[] e = meanEdge(net, base, n, m, alongU);
                BezierClipper.clipLine(net, base, n, m, alongU, out);
                String where = "trial " + trial + " degree " + n + "x" + m + " base " + base + " alongU " + alongU;
                assertArrayEquals(unit(e[0], e[1]), out, ROUNDING, where);
            }
        }
    }

    /** A 2×1 net (x, y, z per point) whose corners are given; interior points random. */
    private static double[] cornersNet(Random rnd, int n, int m, double[] p00, double[] pn0, double[] p0m, double[] pnm) {
        double[] net = new double[3 * (n + 1) * (m + 1)];
        for (int k = 0; k < net.length; k++) {
            net[k] = rnd.nextGaussian();
        }
        int row = 3 * (n + 1);
        System.arraycopy(p00, 0, net, 0, 2);
        System.arraycopy(pn0, 0, net, 3 * n, 2);
        System.arraycopy(p0m, 0, net, row * m, 2);
        System.arraycopy(pnm, 0, net, row * m + 3 * n, 2);
        return net;
    }

    @Test
    void aCollapsedOtherDirectionGivesThePerpendicularOfTheClippedOne() {
        Random rnd = new Random(5);
        double[] out = new double[2];
        // v edges of zero length (the net is a curve in ray space): clip in u across the u direction (3, 4)
        double[] net = cornersNet(rnd, 3, 2, new double[] {1, 2}, new double[] {4, 6}, new double[] {1, 2}, new double[] {4, 6});
        BezierClipper.clipLine(net, 0, 3, 2, true, out);
        assertArrayEquals(new double[] {-0.8, 0.6}, out, ROUNDING);
        // u edges of zero length: clip in v across the v direction (-5, 12)
        net = cornersNet(rnd, 2, 3, new double[] {1, 2}, new double[] {1, 2}, new double[] {-4, 14}, new double[] {-4, 14});
        BezierClipper.clipLine(net, 0, 2, 3, false, out);
        assertArrayEquals(new double[] {-12 / 13.0, -5 / 13.0}, out, ROUNDING);
        // v edges a vanishing 1e-11 of the u edges (squared 1e-22 < 1e-20): as if collapsed
        net = cornersNet(rnd, 1, 1, new double[] {0, 0}, new double[] {300, 400}, new double[] {1e-9, 0},
                new double[] {300 + 1e-9, 400});
        BezierClipper.clipLine(net, 0, 1, 1, true, out);
        assertArrayEquals(new double[] {-0.8, 0.6}, out, ROUNDING);
        net = cornersNet(rnd, 1, 1, new double[] {0, 0}, new double[] {1e-9, 0}, new double[] {300, 400},
                new double[] {300 + 1e-9, 400});
        BezierClipper.clipLine(net, 0, 1, 1, false, out);
        assertArrayEquals(new double[] {-0.8, 0.6}, out, ROUNDING);
        // ... but 1e-9 of them (squared 1e-18) still counts
        net = cornersNet(rnd, 1, 1, new double[] {0, 0}, new double[] {1, 0}, new double[] {0, 1e-9}, new double[] {1, 1e-9});
        BezierClipper.clipLine(net, 0, 1, 1, true, out);
        assertArrayEquals(new double[] {0, 1}, out, ROUNDING);
    }

    @Test
    void aNetCollapsedToAPointStillGivesAUnitLine() {
        double[] net = new double[3 * 4 * 3];
        for (int k = 0; k < net.length; k += 3) {
            net[k] = 2;
            net[k + 1] = -1;
            net[k + 2] = 7;
        }
        double[] out = new double[2];
        BezierClipper.clipLine(net, 0, 3, 2, true, out);
        assertArrayEquals(new double[] {0, 1}, out, 0);
        BezierClipper.clipLine(net, 0, 3, 2, false, out);
        assertArrayEquals(new double[] {1, 0}, out, 0);
    }

    /**
     * The ray-space net of the parallelogram {@code O + u·U + v·V} at degree n×m (its control
     * points on a regular grid), stored at {@code base} of an array of garbage: its distances to
     * the clip line are exactly linear, so the hull meets zero exactly at the root's parameter.
     */
    private static double[] parallelogram(Random rnd, int n, int m, int base, double[] o, double[] uu, double[] vv) {
        double[] net = netWithGarbage(rnd, (n + 1) * (m + 1), base);
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int p = base + 3 * (j * (n + 1) + i);
                double s = (double) i / n, t = (double) j / m;
                net[p] = o[0] + s * uu[0] + t * vv[0];
                net[p + 1] = o[1] + s * uu[1] + t * vv[1];
                net[p + 2] = 5 + rnd.nextDouble();
            }
        }
        return net;
    }

    @Test
    void aParallelogramIsClippedToItsRootWidenedByTheMargin() {
        Random rnd = new Random(1991);
        TraceContext ctx = new TraceContext();
        int inside = 0, outside = 0;
        for (int trial = 0; trial < 2000; trial++) {
            int n = 1 + rnd.nextInt(8), m = 1 + rnd.nextInt(8), base = 3 * rnd.nextInt(30);
            double[] uu = {2 * rnd.nextGaussian(), 2 * rnd.nextGaussian()}, vv = {2 * rnd.nextGaussian(), 2 * rnd.nextGaussian()};
            double det = uu[0] * vv[1] - uu[1] * vv[0];
            if (Math.abs(det) < 0.5) {
                continue;
            }
            double us = 1.4 * rnd.nextDouble() - 0.2, vs = 1.4 * rnd.nextDouble() - 0.2; // the root, maybe off the piece
            double[] o = {-us * uu[0] - vs * vv[0], -us * uu[1] - vs * vv[1]};
            double[] net = parallelogram(rnd, n, m, base, o, uu, vv);
            double[] before = net.clone();
            for (boolean alongU : new boolean[] {true, false}) {
                double root = alongU ? us : vs;
                String where = "trial " + trial + " degree " + n + "x" + m + " root (" + us + ", " + vs + ") alongU " + alongU;
                boolean meets = BezierClipper.clipInterval(ctx, net, base, n, m, alongU, 0);
                assertArrayEquals(before, net, 0, "the net is only read: " + where);
                if (root < -1e-9 || root > 1 + 1e-9) {
                    assertFalse(meets, where + " gave " + Arrays.toString(ctx.clip));
                    outside++;
                    continue;
                }
                assertTrue(meets, where);
                inside++;
                assertEquals(Math.max(0, root - BezierClipper.WIDEN), ctx.clip[0], 1e-13, where);
                assertEquals(Math.min(1, root + BezierClipper.WIDEN), ctx.clip[1], 1e-13, where);
            }
        }
        assertTrue(inside > 1000 && outside > 400, inside + " inside, " + outside + " outside");
    }

    @Test
    void aRootJustOffThePieceCountsWithinTheSlack() {
        Random rnd = new Random(3);
        TraceContext ctx = new TraceContext();
        double[] uu = {1, 0}, vv = {0, 1};
        // root at u = 1 + 1e-7: its distance from the last column is 1e-7
        double[] net = parallelogram(rnd, 3, 2, 0, new double[] {-(1 + 1e-7), -0.5}, uu, vv);
        assertFalse(BezierClipper.clipInterval(ctx, net, 0, 3, 2, true, 1e-8));
        assertTrue(BezierClipper.clipInterval(ctx, net, 0, 3, 2, true, 1e-6));
        assertEquals(1, ctx.clip[1], 0);
        assertEquals(1 - BezierClipper.WIDEN, ctx.clip[0], 1e-15, "only the touching last column");
    }

    /** The smallest third coordinate of the net's points. */
    private static double minZ(double[] net, int off, int len) {
        double min = Double.POSITIVE_INFINITY;
        for (int p = off + 2; p < off + len; p += 3) {
            min = Math.min(min, net[p]);
        }
        return min;
    }

    @Test
    void aSplitPutsTheNearerHalfOnTopWithItsBox() {
        Random rnd = new Random(1992);
        TraceContext ctx = new TraceContext();
        int swaps = 0, kept = 0;
        for (int trial = 0; trial < 400; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            int len = 3 * (n + 1) * (m + 1), w = 1 + rnd.nextInt(4), base = w * len, b4 = 4 * w;
            double[] arena = new double[(w + 3) * len];
            for (int k = 0; k < arena.length; k++) {
                arena[k] = rnd.nextGaussian();
            }
            // depth grows along one direction (so the halves differ), the heights (y) the other way
            double su = rnd.nextGaussian(), sv = rnd.nextGaussian();
            for (int j = 0; j <= m; j++) {
                for (int i = 0; i <= n; i++) {
                    int p = base + 3 * (j * (n + 1) + i);
                    arena[p + 1] = -10 * (su * i / n + sv * j / m);
                    arena[p + 2] = 5 + su * i / n + sv * j / m + 0.01 * rnd.nextDouble();
                }
            }
            double[] boxes = new double[4 * (w + 3)];
            double u0 = rnd.nextDouble(), v0 = rnd.nextDouble();
            double[] box = {u0, u0 + rnd.nextDouble(), v0, v0 + rnd.nextDouble()};
            System.arraycopy(box, 0, boxes, b4, 4);
            boolean inU = rnd.nextBoolean();
            double[] lower = new double[len], upper = new double[len];
            if (inU) {
                DeCasteljau.splitU(arena.clone(), base, n, m, 3, 0.5, lower, 0, upper, 0);
            } else {
                DeCasteljau.splitV(arena.clone(), base, n, m, 3, 0.5, lower, 0, upper, 0);
            }
            double um = 0.5 * (box[0] + box[1]), vm = 0.5 * (box[2] + box[3]);
            double[] lowerBox = inU ? new double[] {box[0], um, box[2], box[3]} : new double[] {box[0], box[1], box[2], vm};
            double[] upperBox = inU ? new double[] {um, box[1], box[2], box[3]} : new double[] {box[0], box[1], vm, box[3]};
            boolean lowerNearer = minZ(lower, 0, len) < minZ(upper, 0, len);

            boolean swapped = BezierClipper.split(ctx, arena, base, len, n, m, boxes, b4, inU);
            String where = "trial " + trial + " degree " + n + "x" + m + " slot " + w + " inU " + inU;
            assertEquals(lowerNearer, swapped, where);
            double[] top = lowerNearer ? lower : upper, stays = lowerNearer ? upper : lower;
            assertArrayEquals(stays, Arrays.copyOfRange(arena, base, base + len), ROUNDING, "slot " + w + ": " + where);
            assertArrayEquals(top, Arrays.copyOfRange(arena, base + len, base + 2 * len), ROUNDING, "next slot: " + where);
            assertArrayEquals(lowerNearer ? upperBox : lowerBox, Arrays.copyOfRange(boxes, b4, b4 + 4), 0, where);
            assertArrayEquals(lowerNearer ? lowerBox : upperBox, Arrays.copyOfRange(boxes, b4 + 4, b4 + 8), 0, where);
            if (swapped) swaps++; else kept++;
        }
        assertTrue(swaps > 100 && kept > 100, swaps + " swaps, " + kept + " kept");
    }

    /**
     * A parabolic trough: x = u, y = v, z = (u − ½)² (degree 2×1), met by the horizontal ray along
     * +x at y = ½, z = 0.09 at u = 0.2 (t = 1.2) and u = 0.8 (t = 1.8).
     */
    static BezierPatch trough() {
        double[] net = new double[3 * 3 * 2];
        double[] z = {0.25, -0.25, 0.25};
        for (int j = 0; j <= 1; j++) {
            for (int i = 0; i <= 2; i++) {
                int k = 3 * (3 * j + i);
                net[k] = i / 2.0;
                net[k + 1] = j;
                net[k + 2] = z[i];
            }
        }
        return new BezierPatch(2, 1, net);
    }

    private static SubPatchTable whole(BezierPatch p) {
        return SubPatchTable.build(List.of(p), SplitOptions.wholePatches());
    }

    @Test
    void newtonConfinedToAPieceFindsThatPiecesRoot() {
        SubPatchTable tab = whole(trough());
        TraceContext ctx = new TraceContext();
        ctx.setRay(-1, 0.5, 0.09, 1, 0, 0);
        assertTrue(BezierClipper.newtonInPiece(ctx, tab, 0, 0.65, 1, 0, 1, 1e-13));
        assertEquals(0.8, ctx.rootU, ROOT_UV);
        assertEquals(0.5, ctx.rootV, ROOT_UV);
        assertEquals(1.8, ctx.rootT, ROOT_T);
        assertTrue(BezierClipper.newtonInPiece(ctx, tab, 0, 0, 0.45, 0, 1, 1e-13));
        assertEquals(0.2, ctx.rootU, ROOT_UV);
        assertEquals(1.2, ctx.rootT, ROOT_T);
        // a piece between the roots (the trough's bottom) has none
        assertFalse(BezierClipper.newtonInPiece(ctx, tab, 0, 0.4, 0.6, 0, 1, 1e-13));
    }

    @Test
    void aPolishedCandidateIsTheNearbyRootOrElseTheCandidateItself() {
        SubPatchTable tab = whole(trough());
        TraceContext ctx = new TraceContext();
        ctx.setRay(-1, 0.5, 0.09, 1, 0, 0);
        // the root (0.8, 0.5) three boxes away: within the polish's reach, found exactly
        assertTrue(BezierClipper.polish(ctx, tab, 0, 0.803, 0.5, 1e-3, 1e-3, 1e-13));
        assertEquals(0.8, ctx.rootU, 1e-13);
        assertEquals(0.5, ctx.rootV, 1e-13);
        assertEquals(1.8, ctx.rootT, ROOT_T);
        assertTrue(BezierClipper.polish(ctx, tab, 0, 0.8, 0.497, 1e-3, 1e-3, 1e-13));
        assertEquals(0.5, ctx.rootV, 1e-13);
        // five boxes away in u, or in v: Newton would leave the candidate's neighbourhood, so the candidate stands
        assertTrue(BezierClipper.polish(ctx, tab, 0, 0.805, 0.5, 1e-3, 1e-3, 1e-13));
        assertEquals(0.805, ctx.rootU, 0);
        assertEquals(0.5, ctx.rootV, 0);
        assertTrue(BezierClipper.polish(ctx, tab, 0, 0.8, 0.505, 1e-3, 1e-3, 1e-13));
        assertEquals(0.8, ctx.rootU, 0);
        assertEquals(0.505, ctx.rootV, 0);
        assertEquals(1.8, ctx.rootT, ROOT_T, "the candidate's t: its point projected on the ray");
    }

    @Test
    void theNearestOfTwoRootsInTheIntervalIsReturned() {
        SubPatchTable tab = whole(trough());
        TraceContext ctx = new TraceContext();
        double tol = 1e-12;
        ctx.setRay(-1, 0.5, 0.09, 1, 0, 0);
        assertTrue(BezierClipper.intersect(ctx, tab, 0, 0, Double.POSITIVE_INFINITY, tol));
        assertEquals(1.2, ctx.rootT, ROOT_T);
        assertEquals(0.2, ctx.rootU, ROOT_UV);
        assertTrue(BezierClipper.intersect(ctx, tab, 0, 1.5, Double.POSITIVE_INFINITY, tol));
        assertEquals(1.8, ctx.rootT, ROOT_T);
        assertEquals(0.8, ctx.rootU, ROOT_UV);
        assertTrue(BezierClipper.intersect(ctx, tab, 0, 0, 1.5, tol));
        assertEquals(1.2, ctx.rootT, ROOT_T);
        assertFalse(BezierClipper.intersect(ctx, tab, 0, 0, 1.1, tol));
        assertFalse(BezierClipper.intersect(ctx, tab, 0, 1.9, Double.POSITIVE_INFINITY, tol));
        assertFalse(BezierClipper.intersect(ctx, tab, 0, 1.3, 1.7, tol));
        // from the other side the root at u = 0.8 is the nearer one
        ctx.setRay(2, 0.5, 0.09, -1, 0, 0);
        assertTrue(BezierClipper.intersect(ctx, tab, 0, 0, Double.POSITIVE_INFINITY, tol));
        assertEquals(1.2, ctx.rootT, ROOT_T);
        assertEquals(0.8, ctx.rootU, ROOT_UV);
    }

    /**
     * The interval is open at both ends: a root found at t* is not found again with t* as tMin or
     * tMax (the solver is deterministic, so the same root comes out bit for bit).
     */
    @Test
    void theIntervalExcludesItsEnds() {
        Random rnd = new Random(1993);
        TraceContext ctx = new TraceContext();
        double[] s = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int checked = 0;
        for (int trial = 0; trial < 300; trial++) {
            int n = 1 + rnd.nextInt(5), m = 1 + rnd.nextInt(5);
            BezierPatch patch = trial % 3 == 0 ? trough() : RandomPatches.heightField(rnd, n, m, 2, 0.8);
            SubPatchTable tab = SubPatchTable.build(List.of(patch), trial % 2 == 0 ? SplitOptions.wholePatches()
                    : SplitOptions.defaults());
            double tol = 1e-12 * 2;
            DeCasteljau.evaluate(patch.copyNet(), 0, patch.degreeU(), patch.degreeV(), 3, rnd.nextDouble(), rnd.nextDouble(),
                    s, 0, scratch);
            double ox = s[0] + 3 * rnd.nextGaussian(), oy = s[1] + 3 * rnd.nextGaussian(), oz = s[2] + 2 * rnd.nextGaussian();
            ctx.setRay(ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz);
            for (int leaf = 0; leaf < tab.count; leaf++) {
                if (!BezierClipper.intersect(ctx, tab, leaf, 0, Double.POSITIVE_INFINITY, tol)) {
                    continue;
                }
                double t = ctx.rootT;
                String where = "trial " + trial + " leaf " + leaf + " t* " + t;
                checked++;
                if (BezierClipper.intersect(ctx, tab, leaf, t, Double.POSITIVE_INFINITY, tol)) {
                    assertTrue(ctx.rootT > t, "tMin = t*: " + ctx.rootT + " " + where);
                }
                if (BezierClipper.intersect(ctx, tab, leaf, 0, t, tol)) {
                    assertTrue(ctx.rootT < t, "tMax = t*: " + ctx.rootT + " " + where);
                }
            }
        }
        assertTrue(checked > 150, "roots checked " + checked);
    }

    /**
     * A rational quadratic arc of the unit circle from 45° to 135° (weights 1, cos 45°, 1), swept
     * along z over [0, 1]: a cylinder piece whose exact hits are circle–line intersections.
     */
    static BezierPatch arc() {
        double c = Math.sqrt(0.5);
        double[] xy = {c, c, 0, Math.sqrt(2), -c, c};
        double[] net = new double[3 * 6], w = new double[6];
        for (int j = 0; j <= 1; j++) {
            for (int i = 0; i <= 2; i++) {
                int p = 3 * (3 * j + i);
                net[p] = xy[2 * i];
                net[p + 1] = xy[2 * i + 1];
                net[p + 2] = j;
                w[3 * j + i] = i == 1 ? c : 1;
            }
        }
        return new BezierPatch(2, 1, net, w, null, null);
    }

    /** Nearest t in (0, ∞) where the ray meets the unit cylinder within 45°..135° and 0 ≤ z ≤ 1; NaN if none. */
    static double arcHit(double ox, double oy, double oz, double dx, double dy, double dz) {
        double a = dx * dx + dy * dy, b = 2 * (ox * dx + oy * dy), c = ox * ox + oy * oy - 1;
        double disc = b * b - 4 * a * c;
        if (disc < 0) {
            return Double.NaN;
        }
        for (double t : new double[] {(-b - Math.sqrt(disc)) / (2 * a), (-b + Math.sqrt(disc)) / (2 * a)}) {
            double x = ox + t * dx, y = oy + t * dy, z = oz + t * dz;
            if (t > 0 && y > Math.abs(x) && z >= 0 && z <= 1) {
                return t;
            }
        }
        return Double.NaN;
    }

    /**
     * Rays that cross the arc twice (the leaf is not single-root, so it is clipped, restricted and
     * split with its weights) and rays that cross it once: the nearest exact hit, for the whole
     * patch as one leaf and for the default leaves.
     */
    @Test
    void aRationalArcIsClippedWithItsWeights() {
        Random rnd = new Random(1994);
        BezierPatch arc = arc();
        TraceContext ctx = new TraceContext();
        int twice = 0, once = 0;
        for (SplitOptions split : List.of(SplitOptions.wholePatches(), SplitOptions.defaults())) {
            SubPatchTable tab = SubPatchTable.build(List.of(arc), split);
            for (int r = 0; r < 600; r++) {
                double ox, oy, oz = 0.1 + 0.8 * rnd.nextDouble(), dx, dy, dz = 0.2 * rnd.nextGaussian();
                if (r % 2 == 0) { // nearly horizontal at a height where it crosses the arc twice
                    ox = -2;
                    oy = 0.72 + 0.26 * rnd.nextDouble();
                    dx = 1;
                    dy = 0.02 * rnd.nextGaussian();
                } else { // from outside towards the axis
                    double phi = Math.PI * (0.2 + 0.6 * rnd.nextDouble());
                    ox = 3 * Math.cos(phi);
                    oy = 3 * Math.sin(phi);
                    dx = -ox + 0.3 * rnd.nextGaussian();
                    dy = -oy + 0.3 * rnd.nextGaussian();
                }
                dz *= 0.3 / Math.max(1, Math.abs(dz)) * Math.hypot(dx, dy);
                double want = arcHit(ox, oy, oz, dx, dy, dz);
                if (Double.isNaN(want) || oz + want * dz < 0.01 || oz + want * dz > 0.99) {
                    continue;
                }
                ctx.setRay(ox, oy, oz, dx, dy, dz);
                double best = Double.POSITIVE_INFINITY;
                for (int leaf = 0; leaf < tab.count; leaf++) {
                    if (BezierClipper.intersect(ctx, tab, leaf, 0, best, 1e-12)) {
                        best = ctx.rootT;
                    }
                }
                String where = "ray " + r + " o (" + ox + ", " + oy + ", " + oz + ") d (" + dx + ", " + dy + ", " + dz + ")";
                assertEquals(want, best, ROOT_T * 3 / Math.sqrt(dx * dx + dy * dy + dz * dz), where);
                if (r % 2 == 0) twice++; else once++;
            }
        }
        assertTrue(twice > 400 && once > 400, twice + " crossing twice, " + once + " once");
    }

    /**
     * A flat square parametrised by x = 4(u − ½)³, y = 4(v − ½)³ (degree 3×3, z = 0): its
     * parametrisation is singular along u = ½ and v = ½, so Newton from the leaf centre fails at
     * once, and from most other starts steps out of the leaf; from where the ray meets the corners'
     * parallelogram (the leaf's documented start) it converges to the root.
     */
    @Test
    void newtonFromTheCornersStartsWhereTheRayMeetsTheirParallelogram() {
        double[] xs = {-0.5, 0.5, -0.5, 0.5};
        double[] net = new double[3 * 16];
        for (int j = 0; j <= 3; j++) {
            for (int i = 0; i <= 3; i++) {
                net[3 * (4 * j + i)] = xs[i];
                net[3 * (4 * j + i) + 1] = xs[j];
            }
        }
        SubPatchTable tab = whole(new BezierPatch(3, 3, net));
        TraceContext ctx = new TraceContext();
        for (double us : new double[] {0.93, 0.95, 0.05, 0.07}) {
            for (double vs : new double[] {0.95, 0.06, 0.93}) {
                double x = 4 * Math.pow(us - 0.5, 3), y = 4 * Math.pow(vs - 0.5, 3);
                ctx.setRay(x, y, 1, 0, 0, -2);
                String where = "(u*, v*) = (" + us + ", " + vs + ")";
                BezierClipper.cornerStart(ctx, tab, 0);
                assertTrue(BezierClipper.newtonFrom(ctx, tab, 0, ctx.clip[0], ctx.clip[1], 1e-13), where);
                assertEquals(us, ctx.rootU, 1e-9, where);
                assertEquals(vs, ctx.rootV, 1e-9, where);
                assertEquals(0.5, ctx.rootT, 1e-12, where);
            }
        }
    }
}
