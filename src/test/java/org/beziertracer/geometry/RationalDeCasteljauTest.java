package org.beziertracer.geometry;

import static org.beziertracer.geometry.TestNets.basis;
import static org.beziertracer.geometry.TestNets.randomDegree;
import static org.beziertracer.geometry.TestNets.randomNet;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

class RationalDeCasteljauTest {

    /** Homogeneous de Casteljau against the direct quotient of Bernstein sums, relative to the net size. */
    private static final double DIRECT_REL = 1e-11;
    private static final int TRIALS = 200;

    /** A random rational patch: Euclidean net in [-10,10]³, weights in [0.2, 5]. */
    private record Rational(int n, int m, double[] xyz, double[] w, double[] h) {
        static Rational random(Random rnd) {
            int n = randomDegree(rnd), m = randomDegree(rnd);
            double[] xyz = randomNet(rnd, n, m, 3, 10);
            double[] w = new double[(n + 1) * (m + 1)];
            for (int k = 0; k < w.length; k++) {
                w[k] = 0.2 * Math.pow(25, rnd.nextDouble());
            }
            double[] h = new double[4 * w.length];
            RationalDeCasteljau.toHomogeneous(xyz, 0, w, 0, w.length, h, 0);
            return new Rational(n, m, xyz, w, h);
        }
    }

    @Test
    void evaluationAndDerivativesMatchTheDirectFormula() {
        Random rnd = new Random(21);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < TRIALS; trial++) {
            Rational r = Rational.random(rnd);
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            double[] expected = direct(r, u, v);
            double[] point = new double[3], all = new double[9];
            RationalDeCasteljau.evaluate(r.h, 0, r.n, r.m, u, v, point, 0, scratch);
            RationalDeCasteljau.evaluateWithDerivatives(r.h, 0, r.n, r.m, u, v, all, 0, scratch, 0);
            double size = 10 * Math.max(r.n, r.m) * 25; // derivatives grow with degree and weight ratio
            for (int c = 0; c < 9; c++) {
                int cc = c, t = trial;
                double tol = DIRECT_REL * (c < 3 ? 10 : size);
                assertEquals(expected[c], all[c], tol, () -> "trial " + t + " component " + cc + " degree " + r.n + "x" + r.m);
                if (c < 3) {
                    assertEquals(all[c], point[c], tol);
                }
            }
        }
    }

    @Test
    void withAllWeightsOneEveryResultIsThePolynomialKernels() {
        Random rnd = new Random(22);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd);
            double[] xyz = randomNet(rnd, n, m, 3, 10), ones = new double[(n + 1) * (m + 1)];
            Arrays.fill(ones, 1);
            double[] h = new double[4 * ones.length];
            RationalDeCasteljau.toHomogeneous(xyz, 0, ones, 0, ones.length, h, 0);
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            double[] poly = new double[9], rat = new double[9];
            DeCasteljau.evaluateWithDerivatives(xyz, 0, n, m, u, v, poly, scratch);
            RationalDeCasteljau.evaluateWithDerivatives(h, 0, n, m, u, v, rat, 0, scratch, 0);
            // The polynomial kernel takes O(n·m) Bernstein sums above n + m = 4 (bicubics excepted),
            // whose bases sum to 1 only to rounding: there the rational result (divided by that
            // weight) agrees to a few ulps of the net size per degree instead of bit for bit
            boolean bernstein = n + m > 4 && !(n == 3 && m == 3);
            String where = "trial " + trial + " degree " + n + "x" + m;
            double ulps = 4 * (n + m) * Math.ulp(10.0);
            assertClose(poly, rat, bernstein ? ulps : 0, where);
            double[] p3 = new double[3], r3 = new double[3];
            DeCasteljau.evaluate(xyz, 0, n, m, 3, u, v, p3, 0, scratch);
            RationalDeCasteljau.evaluate(h, 0, n, m, u, v, r3, 0, scratch);
            assertArrayEquals(p3, r3);
            double[] pn = new double[3], rn = new double[3];
            PatchNormals.unitNormal(xyz, 0, n, m, u, v, pn, 0, scratch);
            PatchNormals.unitNormal(h, 0, n, m, 4, u, v, rn, 0, scratch);
            assertClose(pn, rn, bernstein ? ulps : 0, where);
            // a sub-patch, back in Euclidean form
            double a = 0.5 * u, b = 0.5 + 0.5 * v;
            DeCasteljau.subPatch(xyz, 0, n, m, 3, a, b, a, b, xyz, 0);
            DeCasteljau.subPatch(h, 0, n, m, 4, a, b, a, b, h, 0);
            double[] back = new double[xyz.length], w = new double[ones.length];
            RationalDeCasteljau.toEuclidean(h, 0, ones.length, back, 0, w, 0);
            assertArrayEquals(xyz, back);
            assertArrayEquals(ones, w);
        }
    }

    /** Equal bit for bit when {@code tol} is 0, else within {@code tol}. */
    private static void assertClose(double[] expected, double[] actual, double tol, String where) {
        if (tol == 0) {
            assertArrayEquals(expected, actual, where);
        } else {
            assertArrayEquals(expected, actual, tol, where);
        }
    }

    @Test
    void theBicubicHomogeneousPathIsBitIdenticalToTheGenericOne() {
        Random rnd = new Random(25);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < TRIALS; trial++) {
            double[] h = randomNet(rnd, 3, 3, 4, 10);
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            double[] fast = new double[12], generic = new double[12];
            DeCasteljau3.bicubic4WithDerivatives(h, 0, u, v, fast, 0);
            DeCasteljau.evaluateWithDerivatives(h, 0, 3, 3, 4, u, v, generic, 0, scratch, 0);
            assertArrayEquals(generic, fast, "trial " + trial);
        }
        // and the bicubic rational patch with unit weights is the polynomial one bit for bit
        for (int trial = 0; trial < TRIALS; trial++) {
            double[] xyz = randomNet(rnd, 3, 3, 3, 10), ones = new double[16], h = new double[64];
            Arrays.fill(ones, 1);
            RationalDeCasteljau.toHomogeneous(xyz, 0, ones, 0, 16, h, 0);
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            double[] poly = new double[9], rat = new double[9];
            DeCasteljau.evaluateWithDerivatives(xyz, 0, 3, 3, u, v, poly, scratch);
            RationalDeCasteljau.evaluateWithDerivatives(h, 0, 3, 3, u, v, rat, 0, scratch, 0);
            assertArrayEquals(poly, rat, "trial " + trial);
        }
    }

    @Test
    void aSplitRationalNetReproducesTheSurface() {
        Random rnd = new Random(23);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < TRIALS; trial++) {
            Rational r = Rational.random(rnd);
            double t = 0.1 + 0.8 * rnd.nextDouble();
            double[] lo = new double[r.h.length], hi = new double[r.h.length];
            DeCasteljau.splitU(r.h, 0, r.n, r.m, 4, t, lo, 0, hi, 0);
            double s = rnd.nextDouble(), v = rnd.nextDouble();
            double[] whole = new double[3], half = new double[3];
            RationalDeCasteljau.evaluate(r.h, 0, r.n, r.m, t * s, v, whole, 0, scratch);
            RationalDeCasteljau.evaluate(lo, 0, r.n, r.m, s, v, half, 0, scratch);
            assertArrayEquals(whole, half, 1e-11 * 10, "trial " + trial);
            RationalDeCasteljau.evaluate(r.h, 0, r.n, r.m, t + (1 - t) * s, v, whole, 0, scratch);
            RationalDeCasteljau.evaluate(hi, 0, r.n, r.m, s, v, half, 0, scratch);
            assertArrayEquals(whole, half, 1e-11 * 10, "trial " + trial);
        }
    }

    @Test
    void theEuclideanControlBoxBoundsTheRationalPatch() {
        Random rnd = new Random(24);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < TRIALS; trial++) {
            Rational r = Rational.random(rnd);
            double[] box = new double[6], p = new double[3];
            NetMeasures.controlBounds(r.xyz, 0, r.n, r.m, box);
            for (int k = 0; k < 20; k++) {
                RationalDeCasteljau.evaluate(r.h, 0, r.n, r.m, rnd.nextDouble(), rnd.nextDouble(), p, 0, scratch);
                for (int c = 0; c < 3; c++) {
                    assertTrue(p[c] >= box[c] - 1e-12 && p[c] <= box[c + 3] + 1e-12, "trial " + trial);
                }
            }
        }
    }

    /** S, S_u, S_v from N = Σ w P B, D = Σ w B and the Bernstein derivatives, by the quotient rule. */
    private static double[] direct(Rational r, double u, double v) {
        double[] num = new double[3], nu = new double[3], nv = new double[3];
        double den = 0, du = 0, dv = 0;
        for (int j = 0; j <= r.m; j++) {
            for (int i = 0; i <= r.n; i++) {
                int k = j * (r.n + 1) + i;
                double bu = basis(r.n, i, u), bv = basis(r.m, j, v);
                double dbu = derivative(r.n, i, u), dbv = derivative(r.m, j, v);
                double w = r.w[k];
                den += w * bu * bv;
                du += w * dbu * bv;
                dv += w * bu * dbv;
                for (int c = 0; c < 3; c++) {
                    double wp = w * r.xyz[3 * k + c];
                    num[c] += wp * bu * bv;
                    nu[c] += wp * dbu * bv;
                    nv[c] += wp * bu * dbv;
                }
            }
        }
        double[] out = new double[9];
        for (int c = 0; c < 3; c++) {
            out[c] = num[c] / den;
            out[3 + c] = (nu[c] * den - num[c] * du) / (den * den);
            out[6 + c] = (nv[c] * den - num[c] * dv) / (den * den);
        }
        return out;
    }

    /** d/dt of the Bernstein polynomial {@code B_i^n}: {@code n (B_{i-1}^{n-1} − B_i^{n-1})}. */
    private static double derivative(int n, int i, double t) {
        double a = i > 0 ? basis(n - 1, i - 1, t) : 0, b = i < n ? basis(n - 1, i, t) : 0;
        return n * (a - b);
    }
}
