package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link RationalNets} on its own: a rational leaf's weighted ray-space net, with its weights,
 * is the ray-space image of the rational surface; restricted and split as the clipper and the
 * subdivision solver do it (in arena slots other than 0), it stays the image of the matching part
 * of the surface; divided back it is Euclidean again; its ray-space bounds are those of the
 * weighted distances and of the Euclidean third coordinate, and contain the piece.
 */
class RationalNetsTest {

    private static final double TOL = 64 * ROUNDING;

    /** A random rational patch of degree up to 4×4, weights in [0.3, 3]. */
    private static BezierPatch rationalPatch(Random rnd) {
        int n = 1 + rnd.nextInt(4), m = 1 + rnd.nextInt(4);
        double[] net = new double[3 * (n + 1) * (m + 1)], w = new double[(n + 1) * (m + 1)];
        for (int i = 0; i < net.length; i++) {
            net[i] = 4 * rnd.nextDouble() - 2;
        }
        for (int i = 0; i < w.length; i++) {
            w[i] = 0.3 + 2.7 * rnd.nextDouble();
        }
        return new BezierPatch(n, m, net, w, null, null);
    }

    private static double bernstein(int n, int i, double t) {
        double c = 1;
        for (int k = 0; k < i; k++) {
            c = c * (n - k) / (k + 1);
        }
        return c * Math.pow(t, i) * Math.pow(1 - t, n - i);
    }

    /** The ray-space image of the rational surface at (u,v), by the Bernstein sums (the reference). */
    private static double[] image(TraceContext c, BezierPatch p, double u, double v) {
        double[] s = new double[3];
        double den = 0;
        for (int j = 0; j <= p.degreeV(); j++) {
            for (int i = 0; i <= p.degreeU(); i++) {
                double b = bernstein(p.degreeU(), i, u) * bernstein(p.degreeV(), j, v) * p.weight(i, j);
                den += b;
                for (int k = 0; k < 3; k++) {
                    s[k] += b * p.get(i, j, k);
                }
            }
        }
        double[] point = {s[0] / den, s[1] / den, s[2] / den}, out = new double[3];
        c.project(point, 0, 1, out, 0);
        return out;
    }

    /** The weighted net of arena slot {@code slot} at (u,v), divided by its weights. */
    private static double[] slotAt(TraceContext c, int slot, int n, int m, double u, double v) {
        int points = (n + 1) * (m + 1);
        double[] h = new double[3], w = new double[1], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        DeCasteljau.evaluate(c.arena, slot * 3 * points, n, m, 3, u, v, h, 0, scratch);
        DeCasteljau.evaluate(c.weightArena, slot * points, n, m, 1, u, v, w, 0, scratch);
        return new double[] {h[0] / w[0], h[1] / w[0], h[2] / w[0]};
    }

    private static void assertImage(double[] expected, double[] actual, String where) {
        for (int k = 0; k < 3; k++) {
            assertEquals(expected[k], actual[k], TOL, where + " coordinate " + k);
        }
    }

    /** Sets a random ray, projects and weighs the patch's only leaf into slot 0; returns the table. */
    private static SubPatchTable weighed(Random rnd, TraceContext c, BezierPatch p) {
        SubPatchTable tab = SubPatchTable.build(List.of(p), SplitOptions.wholePatches());
        assertTrue(RationalNets.rational(tab, 0));
        c.setRay(rnd.nextGaussian(), rnd.nextGaussian(), 3 + rnd.nextGaussian(), 0.3 * rnd.nextGaussian(),
                0.3 * rnd.nextGaussian(), -1);
        int points = (p.degreeU() + 1) * (p.degreeV() + 1);
        java.util.Arrays.fill(c.arena, 0, 6 * points + 3, 7.5);
        c.project(tab.nets, tab.netOffset[0], points, c.arena, 0);
        RationalNets.weigh(c, tab, 0, points);
        assertEquals(7.5, c.arena[3 * points], 0, "the next slot is left alone");
        return tab;
    }

    /** Copies slot 0 (net and weights) to {@code slot}. */
    private static void copySlot(TraceContext c, int slot, int points) {
        System.arraycopy(c.arena, 0, c.arena, slot * 3 * points, 3 * points);
        System.arraycopy(c.weightArena, 0, c.weightArena, slot * points, points);
    }

    @Test
    void aPolynomialLeafIsNotRational() {
        BezierPatch plain = new BezierPatch(1, 1, new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
        assertFalse(RationalNets.rational(SubPatchTable.build(List.of(plain), SplitOptions.wholePatches()), 0));
        Random rnd = new Random(80);
        SubPatchTable mixed = SubPatchTable.build(List.of(plain, rationalPatch(rnd)), SplitOptions.wholePatches());
        assertFalse(RationalNets.rational(mixed, 0));
        assertTrue(RationalNets.rational(mixed, 1));
    }

    @Test
    void theWeightedNetIsTheImageOfTheRationalSurface() {
        Random rnd = new Random(81);
        TraceContext c = new TraceContext();
        for (int trial = 0; trial < 100; trial++) {
            BezierPatch p = rationalPatch(rnd);
            weighed(rnd, c, p);
            for (int j = 0; j <= p.degreeV(); j++) {
                for (int i = 0; i <= p.degreeU(); i++) {
                    assertEquals(p.weight(i, j), c.weightArena[j * (p.degreeU() + 1) + i], 0);
                }
            }
            for (int r = 0; r < 10; r++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                assertImage(image(c, p, u, v), slotAt(c, 0, p.degreeU(), p.degreeV(), u, v), "trial " + trial);
            }
        }
    }

    @Test
    void restrictedSlotsAreTheImageOfTheRestrictedSurface() {
        Random rnd = new Random(82);
        TraceContext c = new TraceContext();
        for (int trial = 0; trial < 100; trial++) {
            BezierPatch p = rationalPatch(rnd);
            int n = p.degreeU(), m = p.degreeV(), points = (n + 1) * (m + 1);
            weighed(rnd, c, p);
            double a = 0.6 * rnd.nextDouble(), b = a + 0.05 + (0.95 - a) * rnd.nextDouble();
            int slotU = 1 + rnd.nextInt(3), slotV = slotU + 1;
            copySlot(c, slotU, points);
            copySlot(c, slotV, points);
            DeCasteljau.restrictU(c.arena, slotU * 3 * points, n, m, 3, a, b);
            RationalNets.restrictU(c, slotU, n, m, a, b);
            DeCasteljau.restrictV(c.arena, slotV * 3 * points, n, m, 3, a, b);
            RationalNets.restrictV(c, slotV, n, m, a, b);
            for (int r = 0; r < 10; r++) {
                double s = rnd.nextDouble(), t = rnd.nextDouble(), x = a + s * (b - a);
                String where = "trial " + trial + " [" + a + ", " + b + "]";
                assertImage(image(c, p, x, t), slotAt(c, slotU, n, m, s, t), "in u, " + where);
                assertImage(image(c, p, s, a + t * (b - a)), slotAt(c, slotV, n, m, s, t), "in v, " + where);
            }
            assertImage(image(c, p, 0.5, 0.5), slotAt(c, 0, n, m, 0.5, 0.5), "slot 0 untouched");
        }
    }

    @Test
    void splitSlotsAreTheImagesOfTheTwoHalvesInTheOrderTheArenaWasSplit() {
        Random rnd = new Random(83);
        TraceContext c = new TraceContext();
        double[] tmp = new double[TraceContext.NET_LENGTH];
        for (int trial = 0; trial < 120; trial++) {
            BezierPatch p = rationalPatch(rnd);
            int n = p.degreeU(), m = p.degreeV(), points = (n + 1) * (m + 1);
            weighed(rnd, c, p);
            int slot = 1 + rnd.nextInt(4);
            boolean inU = trial % 2 == 0, swapped = trial % 4 >= 2;
            copySlot(c, slot, points);
            // the arena's own split, as BezierClipper.split does it
            System.arraycopy(c.arena, slot * 3 * points, tmp, 0, 3 * points);
            int lo = (swapped ? slot + 1 : slot) * 3 * points, hi = (swapped ? slot : slot + 1) * 3 * points;
            if (inU) {
                DeCasteljau.splitU(tmp, 0, n, m, 3, 0.5, c.arena, lo, c.arena, hi);
            } else {
                DeCasteljau.splitV(tmp, 0, n, m, 3, 0.5, c.arena, lo, c.arena, hi);
            }
            RationalNets.split(c, slot, n, m, inU, swapped);
            for (int r = 0; r < 10; r++) {
                double s = rnd.nextDouble(), t = rnd.nextDouble();
                String where = "trial " + trial + (inU ? " in u" : " in v") + (swapped ? ", swapped" : "");
                double[] low = inU ? image(c, p, s / 2, t) : image(c, p, s, t / 2);
                double[] high = inU ? image(c, p, 0.5 + s / 2, t) : image(c, p, s, 0.5 + t / 2);
                assertImage(swapped ? high : low, slotAt(c, slot, n, m, s, t), "first slot, " + where);
                assertImage(swapped ? low : high, slotAt(c, slot + 1, n, m, s, t), "second slot, " + where);
            }
        }
    }

    @Test
    void dividedByItsWeightsASlotIsTheEuclideanNetAndItsBoundsContainThePiece() {
        Random rnd = new Random(84);
        TraceContext c = new TraceContext();
        double[] rb = new double[6];
        for (int trial = 0; trial < 100; trial++) {
            BezierPatch p = rationalPatch(rnd);
            int n = p.degreeU(), m = p.degreeV(), points = (n + 1) * (m + 1);
            SubPatchTable tab = weighed(rnd, c, p);
            int slot = 1 + rnd.nextInt(3);
            copySlot(c, slot, points);
            double a = 0.5 * rnd.nextDouble(), b = a + 0.5;
            DeCasteljau.restrictU(c.arena, slot * 3 * points, n, m, 3, a, b);
            RationalNets.restrictU(c, slot, n, m, a, b);
            // bounds: the weighted first two coordinates, the Euclidean third, over the slot's points
            RationalNets.rayBounds(c, slot, points, rb);
            double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
            double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
            for (int k = 0; k < points; k++) {
                int q = slot * 3 * points + 3 * k;
                double[] d = {c.arena[q], c.arena[q + 1], c.arena[q + 2] / c.weightArena[slot * points + k]};
                for (int i = 0; i < 3; i++) {
                    lo[i] = Math.min(lo[i], d[i]);
                    hi[i] = Math.max(hi[i], d[i]);
                }
            }
            for (int i = 0; i < 3; i++) {
                assertEquals(lo[i], rb[i], 0, "trial " + trial + " min " + i);
                assertEquals(hi[i], rb[3 + i], 0, "trial " + trial + " max " + i);
            }
            for (int r = 0; r < 20; r++) {
                double z = image(c, p, a + (b - a) * rnd.nextDouble(), rnd.nextDouble())[2];
                assertTrue(z >= rb[2] - TOL && z <= rb[5] + TOL, "the piece's distances lie within the bounds");
            }
            // back to Euclidean: the corners are surface points of the restricted piece
            int next = (slot + 1) * 3 * points;
            c.arena[next] = 7.5;
            c.weightArena[(slot + 1) * points] = 2;
            RationalNets.toEuclidean(c, slot, points);
            assertEquals(7.5, c.arena[next], 0, "the next slot is left alone");
            int base = slot * 3 * points, last = base + 3 * (points - 1);
            assertImage(image(c, p, a, 0), new double[] {c.arena[base], c.arena[base + 1], c.arena[base + 2]}, "P00");
            assertImage(image(c, p, b, 1), new double[] {c.arena[last], c.arena[last + 1], c.arena[last + 2]}, "Pnm");
            // slot 0 divided back is the leaf's own projected net
            RationalNets.toEuclidean(c, 0, points);
            double[] own = new double[3 * points];
            c.project(tab.nets, tab.netOffset[0], points, own, 0);
            for (int k = 0; k < 3 * points; k++) {
                assertEquals(own[k], c.arena[k], TOL, "trial " + trial);
            }
        }
    }
}
