package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link BorderContinuity}: exact answers on constructed borders (a de Casteljau split, a crease
 * of known angle, a gap of known distance), and the certified bounds never below an independent
 * oracle's samples on random border pairs.
 */
class BorderContinuityTest {

    /** Bounds of a split patch, relative to the model size (G0 × 1/size, G2 × size) or in radians (G1). */
    private static final double SPLIT_BOUND = 1e-12;
    /** Crease angles and gaps are reproduced to this (relative for the gap). */
    private static final double EXACT = 1e-9;

    // ---- A patch split in two by de Casteljau is G2 to rounding

    @Test
    void aPatchSplitByDeCasteljauIsG2ToRounding() {
        Random rnd = new Random(33);
        for (int trial = 0; trial < 20; trial++) {
            int n = 2 + rnd.nextInt(4), m = 2 + rnd.nextInt(4);
            BezierPatch p = bumpyGraph(rnd, n, m);
            double size = p.controlBounds().diagonal();
            double t = 0.2 + 0.6 * rnd.nextDouble();
            boolean inU = rnd.nextBoolean();
            BezierPatch[] halves = inU ? Patches.splitU(p, t) : Patches.splitV(p, t);
            // the second half transposed and turned, so that the border is v against u and reversed
            BezierPatch b = transposed(halves[1]);
            int sideA = inU ? 1 : 3, sideB = inU ? 2 : 0;
            BorderContinuity.Report r = BorderContinuity.analyze(halves[0], sideA, b, sideB, false, size);
            String where = "trial " + trial + ", degree " + n + "x" + m + ", split " + (inU ? "u" : "v") + " at " + t;
            assertTrue(r.g0().bound() <= SPLIT_BOUND * size, where + ": g0 " + r.g0());
            assertTrue(r.g1().bound() <= SPLIT_BOUND, where + ": g1 " + r.g1());
            assertTrue(r.g2().bound() * size <= SPLIT_BOUND, where + ": g2 " + r.g2());
            assertTrue(r.g0().certified() && r.g1().certified() && r.g2().certified(), where);
            assertTrue(r.flipped(), where + ": transposing a patch turns its normal");
        }
    }

    @Test
    void aReversedSplitIsFoundOnlyWhenTheSidesRunTheSameWay() {
        BezierPatch p = bumpyGraph(new Random(5), 3, 3);
        BezierPatch[] halves = Patches.splitU(p, 0.5);
        BezierPatch turned = rotatedHalfTurn(halves[1]); // u → 1 − u, v → 1 − v: its u=0 side is now u=1, reversed
        double size = p.controlBounds().diagonal();
        BorderContinuity.Report right = BorderContinuity.analyze(halves[0], 1, turned, 1, true, size);
        BorderContinuity.Report wrong = BorderContinuity.analyze(halves[0], 1, turned, 1, false, size);
        assertTrue(right.g0().bound() <= SPLIT_BOUND * size && right.g1().bound() <= SPLIT_BOUND, right.toString());
        assertFalse(right.flipped(), "a half turn keeps the normal");
        assertTrue(wrong.g0().bound() > 0.1 * size, "sides compared against their direction part: " + wrong.g0());
    }

    // ---- A crease of known angle

    @Test
    void aCreaseOfKnownAngleGivesThatAngle() {
        Random rnd = new Random(7);
        for (double degrees : new double[] {0.25, 3, 30, 90, 150, 179}) {
            double theta = Math.toRadians(degrees);
            BezierPatch[] pair = crease(rnd, theta);
            BorderContinuity.Report r = BorderContinuity.analyze(pair[0], 1, pair[1], 2, true, 2);
            assertEquals(theta, r.g1().bound(), EXACT, degrees + "°: " + r.g1());
            assertTrue(r.g1().tight(), degrees + "°: " + r.g1());
            assertTrue(r.g0().bound() <= 1e-14, degrees + "°: " + r.g0());
        }
    }

    // ---- A gap of known distance

    @Test
    void aTranslatedNeighbourGivesItsDistanceAsTheGap() {
        BezierPatch[] halves = Patches.splitU(bumpyGraph(new Random(11), 3, 2), 0.4);
        double[] delta = {0.003, -0.004, 0.012}; // |delta| = 0.013
        BezierPatch moved = translated(halves[1], delta);
        BorderContinuity.Report r = BorderContinuity.analyze(halves[0], 1, moved, 0, false, 3);
        assertEquals(0.013, r.g0().bound(), EXACT * 0.013, r.g0().toString());
        assertTrue(r.g0().tight(), r.g0().toString());
    }

    @Test
    void innerBorderPointsMovedApartGiveThreeQuartersOfTheirDistanceAtTheMiddle() {
        BezierPatch[] halves = Patches.splitU(bumpyGraph(new Random(12), 3, 3), 0.5);
        double[] delta = {0, 0, 0.02};
        // move the two inner points of B's u=0 side (and the row beside them, to keep the shape)
        double[] net = halves[1].copyNet();
        for (int j = 1; j <= 2; j++) {
            for (int i = 0; i <= 1; i++) {
                net[halves[1].index(i, j, 2)] += delta[2];
            }
        }
        BezierPatch b = halves[1].withNet(net);
        BorderContinuity.Report r = BorderContinuity.analyze(halves[0], 1, b, 0, false, 3);
        // gap(t) = |delta| (B_1^3 + B_2^3)(t) = |delta| (1 − (1−t)³ − t³): 0.75 |delta| at t = ½
        assertEquals(0.75 * 0.02, r.g0().bound(), EXACT * 0.015, r.g0().toString());
        assertEquals(0.5, r.g0().t(), 1e-12, r.g0().toString());
    }

    @Test
    void aRationalSplitIsG1ToRoundingAndItsG2IsMarkedSampled() {
        Random rnd = new Random(21);
        BezierPatch g = bumpyGraph(rnd, 3, 2);
        double[] w = new double[g.pointCount()];
        for (int k = 0; k < w.length; k++) {
            w[k] = 0.5 + 1.5 * rnd.nextDouble();
        }
        BezierPatch p = new BezierPatch(3, 2, g.copyNet(), w, null, null);
        BezierPatch[] halves = Patches.splitU(p, 0.3);
        BorderContinuity.Report r = BorderContinuity.analyze(halves[0], 1, halves[1], 0, false, 3);
        assertTrue(r.g0().bound() <= SPLIT_BOUND * 3 && r.g0().certified(), r.g0().toString());
        assertTrue(r.g1().bound() <= SPLIT_BOUND && r.g1().certified(), r.g1().toString());
        assertFalse(r.g2().certified(), "rational G2 is sampled");
        assertTrue(r.g2().bound() * 3 <= 1e-9, r.g2().toString());
    }

    @Test
    void aNormalVanishingAtAPoleIsReplacedByItsLimitAndReported() {
        // two quarter-cones meeting along a generator, both collapsed to the apex at v = 0
        BezierPatch a = cone(0, Math.PI / 2), b = cone(Math.PI / 2, Math.PI);
        BorderContinuity.Report r = BorderContinuity.analyze(a, 1, b, 0, false, 2);
        assertArrayEquals(new double[] {0}, r.g1().degenerate(), r.g1().toString());
        assertTrue(r.g1().bound() < Math.toRadians(10), "the quarter arcs are approximations of a circle: " + r.g1());
        assertTrue(Double.isFinite(r.g1().bound()) && Double.isFinite(r.g2().bound()), r.toString());
    }

    // ---- Never below sampled values

    @Test
    void theCertifiedBoundsAreNeverBelowTenThousandSamplesOnRandomBorderPairs() {
        Random rnd = new Random(2024);
        int pairs = 40, samplesEach = 250; // 10,000 samples
        for (int pair = 0; pair < pairs; pair++) {
            boolean rational = pair % 4 == 3;
            Border bd = randomBorder(rnd, rational);
            BorderContinuity.Report r = BorderContinuity.analyze(bd.a, bd.sideA, bd.b, bd.sideB, bd.reversed, 3);
            double[] max = new double[3];
            for (int k = 0; k < samplesEach; k++) {
                double t = rnd.nextDouble();
                double[] v = Oracle.measures(bd.a, bd.sideA, bd.b, bd.sideB, bd.reversed, t);
                for (int q = 0; q < 3; q++) {
                    if (!Double.isNaN(v[q])) {
                        max[q] = Math.max(max[q], v[q]);
                    }
                }
            }
            String where = "pair " + pair + (rational ? " (rational)" : "") + ": " + bd;
            assertAtLeast(r.g0(), max[0], where + ", g0");
            assertAtLeast(r.g1(), max[1], where + ", g1");
            if (!rational) {
                assertAtLeast(r.g2(), max[2], where + ", g2");
            }
        }
    }

    private static void assertAtLeast(BorderContinuity.Bound b, double sampled, String where) {
        assertTrue(b.certified(), where);
        assertTrue(b.bound() >= sampled * (1 - 1e-9) - 1e-12, where + ": bound " + b.bound() + " < sampled " + sampled);
        assertTrue(b.bound() <= Math.max(1.01 * b.worst(), 1e-12) || !b.tight(), where + ": " + b);
    }

    // ---- Fixtures

    record Border(BezierPatch a, int sideA, BezierPatch b, int sideB, boolean reversed) {
        @Override
        public String toString() {
            return a + " side " + sideA + " / " + b + " side " + sideB + (reversed ? " reversed" : "");
        }
    }

    /**
     * A random border: A a bumpy graph over {@code [-1,0]×[0,1]} (side u=1 at x = 0), B over
     * {@code [0,1]×[0,1]} whose first row is A's border moved a little (a gap), whose second row
     * continues A's cross direction more or less (a crease), with random degrees, then B turned to
     * a random side and direction.
     */
    static Border randomBorder(Random rnd, boolean rational) {
        int n = 1 + rnd.nextInt(4), m = 1 + rnd.nextInt(4), nb = 1 + rnd.nextInt(4);
        double[] a = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                a[k] = -1 + (double) i / n + 0.05 * rnd.nextGaussian() * (i < n ? 1 : 0);
                a[k + 1] = (double) j / m + 0.05 * rnd.nextGaussian();
                a[k + 2] = 0.3 * rnd.nextGaussian();
            }
        }
        double noise = rnd.nextBoolean() ? 0 : 0.02;
        double[] b = new double[(nb + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= nb; i++) {
                int k = 3 * (j * (nb + 1) + i), ka = 3 * (j * (n + 1) + n), kIn = 3 * (j * (n + 1) + n - 1);
                for (int c = 0; c < 3; c++) {
                    double border = a[ka + c] + noise * rnd.nextGaussian();
                    double step = (a[ka + c] - a[kIn + c]) * (1 + 0.3 * rnd.nextGaussian()) + 0.1 * rnd.nextGaussian();
                    b[k + c] = i == 0 ? border : a[ka + c] + i * step + (i > 1 ? 0.2 * rnd.nextGaussian() : 0);
                }
            }
        }
        BezierPatch pa = patch(n, m, a, rnd, rational), pb = patch(nb, m, b, rnd, rational);
        // turn B: maybe reverse v (then the border runs against A's), maybe transpose (u ↔ v)
        boolean reversed = rnd.nextBoolean(), swap = rnd.nextBoolean();
        if (reversed) {
            pb = flippedV(pb);
        }
        if (swap) {
            pb = transposed(pb);
        }
        return new Border(pa, 1, pb, swap ? 2 : 0, reversed);
    }

    private static BezierPatch patch(int n, int m, double[] net, Random rnd, boolean rational) {
        if (!rational) {
            return new BezierPatch(n, m, net);
        }
        double[] w = new double[(n + 1) * (m + 1)];
        for (int k = 0; k < w.length; k++) {
            w[k] = 0.5 + rnd.nextDouble();
        }
        return new BezierPatch(n, m, net, w, null, null);
    }

    /** A graph {@code z(x, y)} over a slightly jittered grid on {@code [0,1]²}: a regular surface. */
    static BezierPatch bumpyGraph(Random rnd, int n, int m) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                net[k] = (double) i / n + 0.03 * rnd.nextGaussian();
                net[k + 1] = (double) j / m + 0.03 * rnd.nextGaussian();
                net[k + 2] = 0.4 * rnd.nextGaussian();
            }
        }
        return new BezierPatch(n, m, net);
    }

    /**
     * Two bicubic patches meeting along the y axis at dihedral angle {@code π − theta} (their normals
     * {@code theta} apart): A in the plane z = 0 over x ≤ 0, curved away from the border; B the same
     * half-plane turned by {@code theta} about the y axis, transposed and running down y, with its
     * own bumps from the third row on (which leave the angle at the border alone).
     */
    static BezierPatch[] crease(Random rnd, double theta) {
        double[] a = new double[16 * 3], b = new double[16 * 3];
        for (int j = 0; j <= 3; j++) {
            for (int i = 0; i <= 3; i++) {
                int k = 3 * (j * 4 + i);
                double x = -1 + i / 3.0, y = j / 3.0;
                a[k] = x;
                a[k + 1] = y;
                a[k + 2] = i >= 2 ? 0 : 0.2 * Math.sin(3 * y + i);
                // B's point P_ij: i runs down y (reversed against A), j runs away from the border (v)
                double s = j / 3.0, h = j >= 2 ? 0.15 * Math.cos(2 * i + j) : 0;
                double bx = s, by = 1 - i / 3.0;
                b[k] = bx * Math.cos(theta) - h * Math.sin(theta);
                b[k + 1] = by;
                b[k + 2] = -bx * Math.sin(theta) - h * Math.cos(theta);
            }
        }
        return new BezierPatch[] {new BezierPatch(3, 3, a), new BezierPatch(3, 3, b)};
    }

    /** A quarter of a cone's mantle over the angles {@code [phi0, phi1]}: apex at v = 0 (a collapsed side). */
    static BezierPatch cone(double phi0, double phi1) {
        double k = 4.0 / 3 * Math.tan((phi1 - phi0) / 4);
        double[][] arc = {{Math.cos(phi0), Math.sin(phi0)}, {Math.cos(phi0) - k * Math.sin(phi0), Math.sin(phi0) + k * Math.cos(phi0)},
                {Math.cos(phi1) + k * Math.sin(phi1), Math.sin(phi1) - k * Math.cos(phi1)}, {Math.cos(phi1), Math.sin(phi1)}};
        double[] net = new double[4 * 2 * 3];
        for (int i = 0; i <= 3; i++) {
            // v = 0: the apex (0, 0, 1); v = 1: the arc at z = 0
            net[3 * i + 2] = 1;
            net[3 * (4 + i)] = arc[i][0];
            net[3 * (4 + i) + 1] = arc[i][1];
        }
        return new BezierPatch(3, 1, net);
    }

    static BezierPatch transposed(BezierPatch p) {
        int n = p.degreeU(), m = p.degreeV();
        double[] net = new double[p.pointCount() * 3], w = p.isRational() ? new double[p.pointCount()] : null;
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = i * (m + 1) + j; // P'_ji = P_ij
                for (int c = 0; c < 3; c++) {
                    net[3 * k + c] = p.get(i, j, c);
                }
                if (w != null) {
                    w[k] = p.weight(i, j);
                }
            }
        }
        return new BezierPatch(m, n, net, w, null, null);
    }

    static BezierPatch flippedV(BezierPatch p) {
        return remapped(p, false, true);
    }

    static BezierPatch rotatedHalfTurn(BezierPatch p) {
        return remapped(p, true, true);
    }

    private static BezierPatch remapped(BezierPatch p, boolean flipU, boolean flipV) {
        int n = p.degreeU(), m = p.degreeV();
        double[] net = new double[p.pointCount() * 3], w = p.isRational() ? new double[p.pointCount()] : null;
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int si = flipU ? n - i : i, sj = flipV ? m - j : j, k = j * (n + 1) + i;
                for (int c = 0; c < 3; c++) {
                    net[3 * k + c] = p.get(si, sj, c);
                }
                if (w != null) {
                    w[k] = p.weight(si, sj);
                }
            }
        }
        return new BezierPatch(n, m, net, w, null, null);
    }

    static BezierPatch translated(BezierPatch p, double[] d) {
        double[] net = p.copyNet();
        for (int k = 0; k < net.length; k++) {
            net[k] += d[k % 3];
        }
        return p.withNet(net);
    }

    /**
     * The three measures at one border parameter, computed independently of the Bernstein forms:
     * points and derivatives from {@link SecondDerivatives} at the sides' (u, v), the cross
     * direction's curvature from the first and second fundamental forms in (u, v).
     */
    static final class Oracle {
        private Oracle() {}

        static double[] measures(BezierPatch a, int sideA, BezierPatch b, int sideB, boolean reversed, double t) {
            double[][] fa = frame(a, sideA, t, true), fb = frame(b, sideB, reversed ? 1 - t : t, false);
            if (reversed) {
                fb[1] = scale(fb[1], -1);
            }
            double gap = norm(sub(fa[0], fb[0]));
            double[] na = cross(fa[1], fa[2]), nb = cross(fb[1], fb[2]);
            double angle = norm(na) == 0 || norm(nb) == 0 ? Double.NaN : Math.atan2(norm(cross(na, nb)), dot(na, nb));
            double mismatch = Math.abs(kappa(a, sideA, t, na, fa[1]) - kappa(b, sideB, reversed ? 1 - t : t, nb, fb[1]));
            return new double[] {gap, angle, mismatch};
        }

        /** Point, tangent along the side's own parameter, cross derivative (outward when asked). */
        private static double[][] frame(BezierPatch p, int side, double t, boolean outward) {
            double[] d = derivatives(p, side, t);
            double[] su = {d[3], d[4], d[5]}, sv = {d[6], d[7], d[8]};
            boolean alongV = side < 2;
            double[] inward = alongV ? (side == 0 ? su : scale(su, -1)) : (side == 2 ? sv : scale(sv, -1));
            return new double[][] {{d[0], d[1], d[2]}, alongV ? sv : su, outward ? scale(inward, -1) : inward};
        }

        private static double[] derivatives(BezierPatch p, int side, double t) {
            double u = side == 0 ? 0 : side == 1 ? 1 : t, v = side == 2 ? 0 : side == 3 ? 1 : t;
            double[] out = new double[SecondDerivatives.LENGTH], scratch = new double[SecondDerivatives.SCRATCH];
            SecondDerivatives.evaluate(Patches.homogeneousNet(p), 0, p.degreeU(), p.degreeV(), 4, u, v, out, scratch);
            return out;
        }

        /** Normal curvature along {@code w = n × tangent}, signed by {@code n}. */
        private static double kappa(BezierPatch p, int side, double t, double[] n, double[] tangent) {
            double[] d = derivatives(p, side, t);
            double[] su = {d[3], d[4], d[5]}, sv = {d[6], d[7], d[8]};
            double[] w = cross(n, tangent), unit = scale(n, 1 / norm(n));
            double e = dot(su, su), f = dot(su, sv), g = dot(sv, sv), det = e * g - f * f;
            double wu = dot(w, su), wv = dot(w, sv);
            double x = (g * wu - f * wv) / det, y = (e * wv - f * wu) / det;
            double l = d[9] * unit[0] + d[10] * unit[1] + d[11] * unit[2];
            double mm = d[12] * unit[0] + d[13] * unit[1] + d[14] * unit[2];
            double nn = d[15] * unit[0] + d[16] * unit[1] + d[17] * unit[2];
            return (x * x * l + 2 * x * y * mm + y * y * nn) / (x * x * e + 2 * x * y * f + y * y * g);
        }

        private static double[] cross(double[] a, double[] b) {
            return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        }

        private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

        private static double norm(double[] a) { return Math.sqrt(dot(a, a)); }

        private static double[] sub(double[] a, double[] b) { return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

        private static double[] scale(double[] a, double s) { return new double[] {a[0] * s, a[1] * s, a[2] * s}; }
    }
}
