package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** {@link BernsteinPoly} against the power form evaluated point by point. */
class BernsteinPolyTest {

    private static final double TOL = 1e-12;

    private static BernsteinPoly random(Random rnd, int degree, int dim) {
        double[] c = new double[(degree + 1) * dim];
        for (int k = 0; k < c.length; k++) {
            c[k] = 2 * rnd.nextDouble() - 1;
        }
        return BernsteinPoly.of(degree, dim, c);
    }

    /** Σ c_k C(d,k) t^k (1−t)^(d−k), coordinate {@code q}: the definition. */
    private static double direct(BernsteinPoly p, double t, int q) {
        double s = 0;
        int d = p.degree();
        for (int k = 0; k <= d; k++) {
            double binom = 1;
            for (int r = 1; r <= k; r++) {
                binom = binom * (d - k + r) / r;
            }
            s += p.coefficient(k, q) * binom * Math.pow(t, k) * Math.pow(1 - t, d - k);
        }
        return s;
    }

    @Test
    void productsDotsAndCrossesMatchThePointwiseProducts() {
        Random rnd = new Random(1);
        for (int trial = 0; trial < 50; trial++) {
            BernsteinPoly a = random(rnd, rnd.nextInt(9), 3), b = random(rnd, rnd.nextInt(9), 3);
            BernsteinPoly s = random(rnd, rnd.nextInt(6), 1);
            BernsteinPoly dot = a.dot(b), cross = a.cross(b), scaled = a.scaledBy(s);
            for (double t : new double[] {0, 0.13, 0.5, 0.77, 1}) {
                double[] x = a.value(t), y = b.value(t);
                double sv = s.value(t)[0];
                assertEquals(x[0] * y[0] + x[1] * y[1] + x[2] * y[2], dot.value(t)[0], TOL, "dot at " + t);
                assertEquals(x[1] * y[2] - x[2] * y[1], cross.value(t)[0], TOL, "cross x at " + t);
                assertEquals(x[0] * y[1] - x[1] * y[0], cross.value(t)[2], TOL, "cross z at " + t);
                assertEquals(sv * x[1], scaled.value(t)[1], TOL, "scaled at " + t);
                assertEquals(direct(a, t, 2), x[2], TOL, "value at " + t);
            }
        }
    }

    @Test
    void elevationDerivativeAndHalvesKeepThePolynomial() {
        Random rnd = new Random(2);
        for (int trial = 0; trial < 30; trial++) {
            BernsteinPoly p = random(rnd, 1 + rnd.nextInt(12), 2);
            BernsteinPoly e = p.elevateTo(p.degree() + 1 + rnd.nextInt(5)), d = p.derivative();
            BernsteinPoly[] h = p.halves();
            for (double t : new double[] {0, 0.3, 0.61, 1}) {
                assertEquals(p.value(t)[1], e.value(t)[1], TOL);
                assertEquals(p.value(t / 2)[0], h[0].value(t)[0], TOL, "left half at " + t);
                assertEquals(p.value(0.5 + t / 2)[1], h[1].value(t)[1], TOL, "right half at " + t);
                double x = Math.min(Math.max(t, 1e-3), 1 - 1e-3), step = 1e-6;
                double fd = (p.value(x + step)[0] - p.value(x - step)[0]) / (2 * step);
                assertEquals(fd, d.value(x)[0], 1e-5 * (1 + Math.abs(fd)), "derivative at " + x);
                assertEquals(p.value(1 - t)[0], p.reversed().value(t)[0], TOL);
                assertEquals(p.value(0.2 + 0.5 * t)[1], p.restricted(0.2, 0.7).value(t)[1], TOL, "restricted at " + t);
            }
        }
    }

    @Test
    void dividingOutAFactorTAtARootLeavesTheQuotient() {
        BernsteinPoly q = BernsteinPoly.of(2, 1, 1, -2, 3);
        BernsteinPoly t = BernsteinPoly.of(1, 1, 0, 1), oneMinusT = BernsteinPoly.of(1, 1, 1, 0);
        BernsteinPoly byT = q.scaledBy(t).dividedByT(), byOneMinusT = q.scaledBy(oneMinusT).dividedByOneMinusT();
        for (double x : new double[] {0, 0.25, 0.9, 1}) {
            assertEquals(q.value(x)[0], byT.value(x)[0], TOL);
            assertEquals(q.value(x)[0], byOneMinusT.value(x)[0], TOL);
        }
    }

    @Test
    void coefficientBoundsContainEveryValue() {
        Random rnd = new Random(3);
        for (int trial = 0; trial < 30; trial++) {
            BernsteinPoly p = random(rnd, rnd.nextInt(15), 1), v = random(rnd, rnd.nextInt(15), 3);
            for (int k = 0; k <= 100; k++) {
                double t = k / 100.0, x = p.value(t)[0];
                double[] y = v.value(t);
                assertTrue(p.min() <= x + TOL && x <= p.max() + TOL, "scalar at " + t);
                assertTrue(Math.sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]) <= v.maxNorm() + TOL, "norm at " + t);
            }
        }
    }

    @Test
    void splittingGivesTheTextbookDeCasteljauTriangleBitForBit() {
        Random rnd = new Random(71);
        for (int n = 0; n < 500; n++) {
            int degree = rnd.nextInt(31), dim = 1 + rnd.nextInt(3);
            BernsteinPoly p = random(rnd, degree, dim);
            double t = n % 3 == 0 ? 0.5 : rnd.nextDouble();
            // the triangle row by row: level r from level r − 1
            double[][] level = new double[degree + 1][];
            level[0] = p.coefficients();
            for (int r = 1; r <= degree; r++) {
                level[r] = new double[(degree - r + 1) * dim];
                for (int k = 0; k < level[r].length; k++) {
                    double a = level[r - 1][k], b = level[r - 1][k + dim];
                    level[r][k] = t == 0.5 ? 0.5 * (a + b) : (1 - t) * a + t * b;
                }
            }
            double[] left = new double[(degree + 1) * dim], right = new double[(degree + 1) * dim];
            for (int r = 0; r <= degree; r++) {
                System.arraycopy(level[r], 0, left, r * dim, dim);
                System.arraycopy(level[degree - r], r * dim, right, r * dim, dim);
            }
            BernsteinPoly[] split = p.splitAt(t);
            org.junit.jupiter.api.Assertions.assertArrayEquals(left, split[0].coefficients());
            org.junit.jupiter.api.Assertions.assertArrayEquals(right, split[1].coefficients());
        }
    }
}
