package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.DERIVED;
import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.beziertracer.math.Bounds;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

class NetMeasuresTest {

    /** Slack for "inside the box", relative to the net size (evaluation rounding). */
    private static final double BOX_REL = 1e-13;
    /** Flatness of an exactly bilinear net after elevation, relative to the net size. */
    private static final double FLAT_REL = 1e-13;
    private static final int TRIALS = 100;

    @Test
    void everySampledSurfacePointLiesInTheControlPointBox() {
        Random rnd = new Random(31);
        int[] dims = {1, 2, 3};
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = TestNets.randomDegree(rnd), m = TestNets.randomDegree(rnd), dim = dims[trial % 3];
            double[] net = TestNets.randomNet(rnd, n, m, dim, 50);
            double[] box = new double[2 * dim];
            NetMeasures.controlBounds(net, 0, n, m, dim, box, 0);
            double eps = BOX_REL * TestNets.size(net, 0, net.length);
            for (int s = 0; s < 50; s++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                double[] p = TestNets.eval(net, 0, n, m, dim, u, v);
                for (int c = 0; c < dim; c++) {
                    assertTrue(p[c] >= box[c] - eps && p[c] <= box[dim + c] + eps,
                            TestNets.degrees(n, m, dim) + " at (" + u + "," + v + "): point " + Arrays.toString(p)
                                    + " outside box " + Arrays.toString(box));
                }
            }
        }
    }

    @Test
    void threeDimensionalBoundsAgreeWithMathBoundsAndTheGenericForm() {
        Random rnd = new Random(32);
        int n = 5, m = 2, pad = 3;
        double[] net = TestNets.randomNet(rnd, n, m, 3, 1);
        double[] padded = new double[net.length + pad];
        System.arraycopy(net, 0, padded, pad, net.length);
        double[] a = new double[6], b = new double[6], generic = new double[6];
        NetMeasures.controlBounds(padded, pad, n, m, a);
        Bounds.ofPoints(net, 0, (n + 1) * (m + 1), b);
        NetMeasures.controlBounds(net, 0, n, m, 3, generic, 0);
        assertArrayEquals(b, a, 0);
        assertArrayEquals(b, generic, 0);
    }

    /** A random bilinear patch (degree 1×1) elevated to degree n×m. */
    private static BezierPatch elevatedBilinear(Random rnd, int n, int m) {
        BezierPatch p = new BezierPatch(1, 1, TestNets.randomNet(rnd, 1, 1, 3, 10));
        while (p.degreeU() < n) p = DegreeElevation.elevateU(p);
        while (p.degreeV() < m) p = DegreeElevation.elevateV(p);
        return p;
    }

    @Test
    void flatnessIsZeroForABilinearPatchOfAnyDegree() {
        Random rnd = new Random(33);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = TestNets.randomDegree(rnd), m = TestNets.randomDegree(rnd);
            BezierPatch p = elevatedBilinear(rnd, n, m);
            double[] net = p.copyNet();
            double f = NetMeasures.flatness(net, 0, n, m);
            assertTrue(f <= FLAT_REL * TestNets.size(net, 0, net.length),
                    "bilinear elevated to " + n + "x" + m + ": flatness " + f);
        }
    }

    @Test
    void flatnessGrowsWithTheDisplacementOfAnInnerControlPoint() {
        Random rnd = new Random(34);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = 2 + rnd.nextInt(14), m = 2 + rnd.nextInt(14);
            double[] net = elevatedBilinear(rnd, n, m).copyNet();
            int i = 1 + rnd.nextInt(n - 1), j = rnd.nextInt(m + 1), c = rnd.nextInt(3);
            double previous = NetMeasures.flatness(net, 0, n, m);
            for (double d : new double[] {0.01, 0.1, 1, 10}) {
                double[] moved = net.clone();
                moved[3 * (j * (n + 1) + i) + c] += d;
                double f = NetMeasures.flatness(moved, 0, n, m);
                String what = n + "x" + m + ", P(" + i + "," + j + ") moved by " + d + " along axis " + c;
                // Only that point deviates, by exactly d (the corners, hence the bilinear patch, are unchanged)
                assertEquals(d, f, DERIVED * (1 + d), what);
                assertTrue(f > previous, what + ": flatness " + f + " not above " + previous);
                previous = f;
            }
        }
    }

    @Test
    void flatnessBoundsTheDistanceFromTheBilinearCornerPatch() {
        Random rnd = new Random(35);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = TestNets.randomDegree(rnd), m = TestNets.randomDegree(rnd);
            double[] net = TestNets.randomNet(rnd, n, m, 3, 5);
            double f = NetMeasures.flatness(net, 0, n, m);
            double[] corners = new double[12];
            int[] idx = {0, n, m * (n + 1), m * (n + 1) + n};
            for (int k = 0; k < 4; k++) {
                System.arraycopy(net, 3 * idx[k], corners, 3 * k, 3);
            }
            for (int s = 0; s < 20; s++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                double[] p = TestNets.eval(net, 0, n, m, 3, u, v), b = TestNets.eval(corners, 0, 1, 1, 3, u, v);
                double dist = Math.sqrt(Math.pow(p[0] - b[0], 2) + Math.pow(p[1] - b[1], 2) + Math.pow(p[2] - b[2], 2));
                assertTrue(dist <= f * (1 + ROUNDING), n + "x" + m + " at (" + u + "," + v + "): distance " + dist
                        + " exceeds flatness " + f);
            }
        }
    }

    /**
     * The second-derivative bound M makes the Taylor remainder of a step {@code (a, b)} at most
     * {@code ½·M·(|a|+|b|)²}: random nets of degree 1..15 in each direction, random points and steps
     * of every size (the step kept in the domain), the remainder measured against the surface
     * itself. The bound is also attained where it must be: on a bilinear net (S_uv is the constant
     * twist, S_uu = S_vv = 0) M is the twist's length.
     */
    @Test
    void theSecondDerivativeBoundHoldsForTheTaylorRemainder() {
        Random rnd = new Random(2026_12_02);
        double[] e0 = new double[9], e1 = new double[9], scratch = new double[4096];
        double tightest = 0;
        for (int trial = 0; trial < 400; trial++) {
            int n = 1 + rnd.nextInt(15), m = 1 + rnd.nextInt(15);
            double[] net = new double[3 * (n + 1) * (m + 1)];
            for (int k = 0; k < net.length; k++) {
                net[k] = 4 * (rnd.nextDouble() - 0.5);
            }
            double bound = NetMeasures.secondDerivativeBound(net, 0, n, m);
            for (int sample = 0; sample < 20; sample++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                double scale = Math.pow(10, -4 * rnd.nextDouble());
                double a = scale * (rnd.nextDouble() - 0.5), b = scale * (rnd.nextDouble() - 0.5);
                a = Math.max(-u, Math.min(1 - u, a));
                b = Math.max(-v, Math.min(1 - v, b));
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, e0, scratch);
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u + a, v + b, e1, scratch);
                double sq = 0;
                for (int c = 0; c < 3; c++) {
                    double r = e1[c] - e0[c] - a * e0[3 + c] - b * e0[6 + c];
                    sq += r * r;
                }
                double remainder = Math.sqrt(sq), allowed = 0.5 * bound * (Math.abs(a) + Math.abs(b)) * (Math.abs(a) + Math.abs(b));
                // the evaluations' own rounding (a few ulps of the net's size times the degree)
                assertTrue(remainder <= allowed + 1e-13 * (n + m), "degree " + n + "x" + m + ": remainder " + remainder
                        + " above " + allowed);
                if (allowed > 1e-9) {
                    tightest = Math.max(tightest, remainder / allowed);
                }
            }
        }
        assertTrue(tightest > 0.05, "the bound is never approached: " + tightest);
        double[] bilinear = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5};
        assertEquals(0.5, NetMeasures.secondDerivativeBound(bilinear, 0, 1, 1), 1e-9);
    }

    @Test
    void flatnessWithColumnTermsIsTheSameNumberAsThePlainOne() {
        Random rnd = new Random(515);
        for (int trial = 0; trial < 300; trial++) {
            int n = TestNets.randomDegree(rnd), m = TestNets.randomDegree(rnd);
            double[] net = TestNets.randomNet(rnd, n, m, 3, Math.pow(10, -3 + 6 * rnd.nextDouble()));
            if (trial % 3 == 0) {
                // nearly flat: a plane plus a tiny bump, where the value is small and rounding matters
                for (int k = 2; k < net.length; k += 3) {
                    net[k] = 0.3 * net[k - 2] - 0.2 * net[k - 1] + 1e-9 * rnd.nextDouble();
                }
            }
            double[] padded = new double[net.length + 7];
            System.arraycopy(net, 0, padded, 7, net.length);
            double[] scratch = new double[NetMeasures.flatnessScratch(n)];
            assertEquals(NetMeasures.flatness(net, 0, n, m), NetMeasures.flatness(padded, 7, n, m, scratch), 0,
                    "trial " + trial + ", degree " + n + "x" + m);
        }
    }
}
