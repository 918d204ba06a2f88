package org.beziertracer.math;

import java.util.Arrays;
import java.util.Random;

/**
 * Test fixtures for B-splines: random knot vectors (clamped or not, with multiplicities) and an
 * independent reference evaluator, the Cox–de Boor recursion for the basis functions
 * (Piegl &amp; Tiller, <i>The NURBS Book</i>, eq. 2.5), written without knot insertion.
 */
public final class SplineReference {
    private SplineReference() {}

    /**
     * A random valid knot vector for {@code count} points of degree {@code p}: clamped ends or
     * distinct ones, interior knots with multiplicities 1..p (sometimes p + 1), non-uniform.
     */
    public static double[] randomKnots(Random rnd, int p, int count, boolean clamped) {
        int length = count + p + 1;
        double[] knots = new double[length];
        int k = 0;
        double t = 10 * rnd.nextDouble() - 5;
        if (clamped) {
            for (; k <= p; k++) {
                knots[k] = t;
            }
        }
        while (k < length) {
            t += 0.1 + rnd.nextDouble() * (rnd.nextInt(4) == 0 ? 3 : 1);
            int mult = 1 + rnd.nextInt(rnd.nextInt(5) == 0 ? p + 1 : Math.max(1, p));
            boolean end = clamped && length - k <= p + 1;
            if (end) {
                mult = length - k;
            }
            for (int r = 0; r < mult && k < length; r++) {
                knots[k++] = t;
            }
        }
        if (KnotVector.problem(p, knots, count) != null) {
            return randomKnots(rnd, p, count, clamped); // e.g. an empty range: draw again
        }
        return knots;
    }

    /** Basis function {@code N_{i,p}(t)} by the Cox–de Boor recursion (half-open spans). */
    public static double basis(double[] knots, int i, int p, double t) {
        if (p == 0) {
            return knots[i] <= t && t < knots[i + 1] ? 1 : 0;
        }
        double a = 0, b = 0;
        if (knots[i + p] > knots[i]) {
            a = (t - knots[i]) / (knots[i + p] - knots[i]) * basis(knots, i, p - 1, t);
        }
        if (knots[i + p + 1] > knots[i + 1]) {
            b = (knots[i + p + 1] - t) / (knots[i + p + 1] - knots[i + 1]) * basis(knots, i + 1, p - 1, t);
        }
        return a + b;
    }

    /** {@code Σ N_i(t) P_i} for points of {@code dim} doubles (homogeneous points give the homogeneous curve). */
    public static double[] curve(double[] knots, int p, double[] points, int dim, double t) {
        double[] out = new double[dim];
        for (int i = 0; i < points.length / dim; i++) {
            double b = basis(knots, i, p, t);
            for (int c = 0; c < dim; c++) {
                out[c] += b * points[i * dim + c];
            }
        }
        return out;
    }

    /** Tensor-product surface point, points u fastest, {@code dim} doubles each. */
    public static double[] surface(double[] knotsU, int p, double[] knotsV, int q, int countU, int countV,
                                   double[] points, int dim, double u, double v) {
        double[] out = new double[dim];
        for (int j = 0; j < countV; j++) {
            double bv = basis(knotsV, j, q, v);
            if (bv == 0) {
                continue;
            }
            for (int i = 0; i < countU; i++) {
                double b = basis(knotsU, i, p, u) * bv;
                for (int c = 0; c < dim; c++) {
                    out[c] += b * points[(j * countU + i) * dim + c];
                }
            }
        }
        return out;
    }

    /** A random parameter strictly inside {@code [a,b]}. */
    public static double inside(Random rnd, double a, double b) {
        return a + (b - a) * (0.001 + 0.998 * rnd.nextDouble());
    }

    public static String text(double[] knots) {
        return Arrays.toString(knots);
    }
}
