package org.beziertracer.model.io;

import java.util.List;

/**
 * Polynomials and curves in Bernstein (Bézier) form on {@code [0, 1]}, as coefficient arrays
 * ({@code dim} doubles a point where said): de Casteljau evaluation and splitting, roots that
 * change sign (isolated by subdivision and Descartes' rule of signs, then bisected), products
 * (R. Farouki, V. Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5, 1988, 1–26),
 * and exact degree reduction of 4-D (homogeneous) curves checked by degree elevation (G. Farin,
 * <i>Curves and Surfaces for CAGD</i>, 5th ed., 2002, §6.9). For {@link CurveOnSurface}. Stateless.
 */
final class Bernstein {
    private Bernstein() {}

    /** Sign-changing roots of the Bernstein polynomial {@code f} (on {@code [a, b]} of the original parameter). */
    static void roots(double[] f, double a, double b, int depth, List<Double> out) {
        int changes = 0, last = 0;
        for (double c : f) {
            int sign = c > 0 ? 1 : c < 0 ? -1 : 0;
            if (sign != 0) {
                changes += last != 0 && sign != last ? 1 : 0;
                last = sign;
            }
        }
        if (changes == 0) {
            return;
        }
        int n = f.length - 1;
        if (changes == 1 && f[0] != 0 && f[n] != 0 && (f[0] > 0) != (f[n] > 0) || depth >= 60) {
            if ((f[0] > 0) != (f[n] > 0) && f[0] != 0 && f[n] != 0) {
                out.add(bisect(f, a, b));
            }
            return;
        }
        double[] left = f.clone(), right = f.clone();
        split(left, right, 1, n, 0.5);
        double m = (a + b) / 2;
        roots(left, a, m, depth + 1, out);
        roots(right, m, b, depth + 1, out);
    }

    /** The root of {@code f} (one sign change, ends of opposite signs) by bisection, in {@code [a, b]}. */
    private static double bisect(double[] f, double a, double b) {
        double lo = 0, hi = 1;
        boolean startPositive = f[0] > 0;
        for (int k = 0; k < 200; k++) {
            double mid = (lo + hi) / 2;
            if (!(mid > lo && mid < hi)) {
                break;
            }
            double value = value(f, mid);
            if (value == 0) {
                lo = hi = mid;
                break;
            }
            if ((value > 0) == startPositive) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return a + (b - a) * ((lo + hi) / 2);
    }

    /** The value at {@code s} of the polynomial of coefficients {@code f} (de Casteljau). */
    static double value(double[] f, double s) {
        double[] c = f.clone();
        for (int r = 1; r < c.length; r++) {
            for (int i = 0; i < c.length - r; i++) {
                c[i] = (1 - s) * c[i] + s * c[i + 1];
            }
        }
        return c[0];
    }

    /**
     * De Casteljau at {@code s} on points of {@code dim} doubles: {@code left} (a copy of the
     * points) becomes the piece on {@code [0, s]}, {@code right} the piece on {@code [s, 1]}.
     */
    static void split(double[] left, double[] right, int dim, int n, double s) {
        double[] c = left.clone();
        for (int a = 0; a < dim; a++) {
            left[a] = c[a];
            right[n * dim + a] = c[n * dim + a];
        }
        for (int r = 1; r <= n; r++) {
            for (int i = 0; i <= n - r; i++) {
                for (int a = 0; a < dim; a++) {
                    c[i * dim + a] = (1 - s) * c[i * dim + a] + s * c[(i + 1) * dim + a];
                }
            }
            for (int a = 0; a < dim; a++) {
                left[r * dim + a] = c[a];
                right[(n - r) * dim + a] = c[(n - r) * dim + a];
            }
        }
    }

    /**
     * The lowest degree every piece has exactly (to rounding): a piece of degree {@code n} is of
     * degree {@code n − 1} when its n-th difference {@code Σ (−1)^i C(n,i) P_i} vanishes (an
     * iso-parameter segment of a polygon trim is an iso-curve of the surface's degree), checked
     * by reducing and raising back (Farin, <i>Curves and Surfaces for CAGD</i>, 5th ed., §6.9).
     */
    static int reducedDegree(List<double[]> bez, int degree) {
        int m = degree;
        while (m > 1) {
            boolean all = true;
            for (int b = 0; b < bez.size() && all; b++) {
                double[] h = bez.get(b), q = reduce(h, degree, m - 1);
                all = sameAfterRaising(q, m - 1, h, degree);
                for (int k = 3; k < q.length && all; k += 4) {
                    all = q[k] > 0; // a positive weight for every point of the lower degree too
                }
            }
            if (!all) {
                break;
            }
            m--;
        }
        return m;
    }

    /**
     * The points of degree {@code m} that raise to {@code h} (degree {@code n}), when it is of
     * degree {@code m}: the degree-elevation relation solved from both ends and blended (the
     * forward solution is exact near the start, the backward one near the end).
     */
    static double[] reduce(double[] h, int n, int m) {
        double[] cur = h;
        for (int d = n; d > m; d--) {
            double[] fwd = new double[4 * d], bwd = new double[4 * d];
            for (int c = 0; c < 4; c++) {
                fwd[c] = cur[c];
                for (int i = 1; i < d; i++) {
                    fwd[4 * i + c] = (d * cur[4 * i + c] - i * fwd[4 * (i - 1) + c]) / (d - i);
                }
                bwd[4 * (d - 1) + c] = cur[4 * d + c];
                for (int i = d - 1; i >= 1; i--) {
                    bwd[4 * (i - 1) + c] = (d * cur[4 * i + c] - (d - i) * bwd[4 * i + c]) / i;
                }
            }
            double[] out = new double[4 * d];
            for (int i = 0; i < d; i++) {
                boolean first = 2 * i < d - 1;
                System.arraycopy(first ? fwd : bwd, 4 * i, out, 4 * i, 4);
            }
            cur = out;
        }
        return cur;
    }

    /** Whether {@code q} (degree {@code m}) raised to degree {@code n} is {@code h} within 1e-12 of its size. */
    private static boolean sameAfterRaising(double[] q, int m, double[] h, int n) {
        double[] cur = q;
        for (int d = m; d < n; d++) {
            double[] up = new double[4 * (d + 2)];
            for (int c = 0; c < 4; c++) {
                up[c] = cur[c];
                up[4 * (d + 1) + c] = cur[4 * d + c];
                for (int i = 1; i <= d; i++) {
                    double a = (double) i / (d + 1);
                    up[4 * i + c] = a * cur[4 * (i - 1) + c] + (1 - a) * cur[4 * i + c];
                }
            }
            cur = up;
        }
        double size = 0, err = 0;
        for (int k = 0; k < h.length; k++) {
            size = Math.max(size, Math.abs(h[k]));
            err = Math.max(err, Math.abs(cur[k] - h[k]));
        }
        return err <= 1e-12 * Math.max(size, Double.MIN_NORMAL);
    }

    /** The product of two Bernstein polynomials (Farouki &amp; Rajan 1988, eq. 7). */
    static double[] product(double[] f, double[] g) {
        int m = f.length - 1, n = g.length - 1;
        double[] h = new double[m + n + 1];
        for (int k = 0; k <= m + n; k++) {
            double sum = 0;
            for (int i = Math.max(0, k - n); i <= Math.min(m, k); i++) {
                sum += binomial(m, i) * binomial(n, k - i) * f[i] * g[k - i];
            }
            h[k] = sum / binomial(m + n, k);
        }
        return h;
    }

    /** Pascal's triangle up to the largest degree a product reaches, exact (below 2^53). */
    private static final double[][] BINOMIAL = new double[CurveOnSurface.MAX_DEGREE + 1][];

    static {
        for (int n = 0; n <= CurveOnSurface.MAX_DEGREE; n++) {
            BINOMIAL[n] = new double[n + 1];
            BINOMIAL[n][0] = BINOMIAL[n][n] = 1;
            for (int k = 1; k < n; k++) {
                BINOMIAL[n][k] = BINOMIAL[n - 1][k - 1] + BINOMIAL[n - 1][k];
            }
        }
    }

    static double binomial(int n, int k) {
        return BINOMIAL[n][k];
    }
}
