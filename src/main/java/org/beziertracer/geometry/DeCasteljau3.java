package org.beziertracer.geometry;

/**
 * Three-coordinate ({@code dim = 3}) specialisations of the {@link DeCasteljau} kernels for the
 * ray tracer's hot path: restriction of a curve to {@code [a,b]} (both ends in one call, the
 * cubic case in straight-line code on locals) and evaluation with first derivatives without
 * per-row copies. The restriction and the de Casteljau evaluation are bit-identical to the
 * generic kernel: the same convex combinations {@code (1-t)·P + t·Q} are evaluated in the same
 * order, only the loads, stores, copies and loop overhead are gone; evaluation of higher
 * degrees goes to {@link BernsteinEval}.
 *
 * <p>Source: the de Casteljau algorithm, subdivision and derivatives from the intermediate
 * points, G. Farin, <i>Curves and Surfaces for CAGD</i>, 5th ed., 2002 (as for
 * {@link DeCasteljau}).
 */
final class DeCasteljau3 {
    private DeCasteljau3() {}

    /**
     * Restricts the 3-D curve of degree {@code deg} at {@code p[off + k*stride]} in place to
     * {@code [a,b]}, {@code 0 ≤ a < b ≤ 1}: split at {@code b} keeping the low part (backward,
     * in place), then at {@code a/b} keeping the high part (forward), as
     * {@link DeCasteljau#restrictU} describes.
     */
    static void restrictCurve(double[] p, int off, int stride, int deg, double a, double b) {
        if (deg == 3) {
            int i1 = off + stride, i2 = i1 + stride, i3 = i2 + stride;
            double ta = a > 0 ? Math.min(1, a / b) : 0;
            restrictCubic(p, off, i1, i2, i3, a, b, ta);
            restrictCubic(p, off + 1, i1 + 1, i2 + 1, i3 + 1, a, b, ta);
            restrictCubic(p, off + 2, i1 + 2, i2 + 2, i3 + 2, a, b, ta);
            return;
        }
        int last = off + deg * stride;
        if (b < 1) {
            double s = 1 - b;
            for (int r = 1; r <= deg; r++) {
                for (int k = deg, q = last; k >= r; k--, q -= stride) {
                    int o = q - stride;
                    p[q] = s * p[o] + b * p[q];
                    p[q + 1] = s * p[o + 1] + b * p[q + 1];
                    p[q + 2] = s * p[o + 2] + b * p[q + 2];
                }
            }
        }
        if (a > 0) {
            double t = Math.min(1, a / b), s = 1 - t;
            for (int r = 1; r <= deg; r++) {
                for (int k = 0, q = off; k <= deg - r; k++, q += stride) {
                    int o = q + stride;
                    p[q] = s * p[q] + t * p[o];
                    p[q + 1] = s * p[q + 1] + t * p[o + 1];
                    p[q + 2] = s * p[q + 2] + t * p[o + 2];
                }
            }
        }
    }

    /** One coordinate of a cubic restricted to {@code [a,b]}; {@code ta = a/b} (clamped to 1). */
    private static void restrictCubic(double[] p, int i0, int i1, int i2, int i3, double a, double b,
                                      double ta) {
        double p0 = p[i0], p1 = p[i1], p2 = p[i2], p3 = p[i3];
        if (b < 1) {
            double s = 1 - b;
            double q01 = s * p0 + b * p1, q12 = s * p1 + b * p2, q23 = s * p2 + b * p3;
            double q012 = s * q01 + b * q12, q123 = s * q12 + b * q23;
            p1 = q01;
            p2 = q012;
            p3 = s * q012 + b * q123;
        }
        if (a > 0) {
            double s = 1 - ta;
            double r01 = s * p0 + ta * p1, r12 = s * p1 + ta * p2, r23 = s * p2 + ta * p3;
            double r012 = s * r01 + ta * r12, r123 = s * r12 + ta * r23;
            p0 = s * r012 + ta * r123;
            p1 = r123;
            p2 = r23;
        }
        p[i0] = p0;
        p[i1] = p1;
        p[i2] = p2;
        p[i3] = p3;
    }

    /** Nets with {@code n + m} above this are evaluated by {@link BernsteinEval} (bicubics excepted). */
    static final int BERNSTEIN_FROM = 4;

    /**
     * {@link DeCasteljau#evaluateWithDerivatives(double[], int, int, int, int, double, double,
     * double[], int, double[], int)} for {@code dim = 3}: bicubics in straight-line code; nets with
     * {@code n + m > }{@value #BERNSTEIN_FROM} by the {@code O(n·m)} Bernstein sums of
     * {@link BernsteinEval} (equal to de Casteljau within a few ulps of the net size per degree,
     * not bit for bit); the rest by de Casteljau, the first u level of every row read straight
     * from the net (no row copy), the two level-{@code (n-1)} points in two columns of
     * {@code scratch}, which are then reduced in v. Degrees must be ≥ 1.
     */
    static void evaluateWithDerivatives(double[] net, int off, int n, int m, double u, double v,
                                        double[] out, int outOff, double[] scratch, int scratchOff) {
        if (n == 3 && m == 3) {
            for (int c = 0; c < 3; c++) {
                bicubicWithDerivatives(net, off + c, 3, u, v, out, outOff + c, 3);
            }
            return;
        }
        if (n + m > BERNSTEIN_FROM) {
            // O(n·m) instead of O(n²·m): faster from biquadratic-and-a-bit up (KernelBench)
            BernsteinEval.evaluateWithDerivatives(net, off, n, m, u, v, out, outOff, scratch, scratchOff);
            return;
        }
        final int dim = 3, rowStride = (n + 1) * dim;
        int work = scratchOff;
        int colA = scratchOff + DeCasteljau.MAX_ORDER * dim;
        int colB = colA + DeCasteljau.MAX_ORDER * dim;
        double su = 1 - u;
        for (int j = 0; j <= m; j++) {
            int row = off + j * rowStride;
            int ca = colA + j * dim, cb = colB + j * dim;
            if (n == 1) {
                for (int c = 0; c < dim; c++) {
                    scratch[ca + c] = net[row + c];
                    scratch[cb + c] = net[row + dim + c];
                }
                continue;
            }
            // level 1 from the net into the work row
            for (int k = 0, q = row, w = work; k < n; k++, q += dim, w += dim) {
                scratch[w] = su * net[q] + u * net[q + dim];
                scratch[w + 1] = su * net[q + 1] + u * net[q + dim + 1];
                scratch[w + 2] = su * net[q + 2] + u * net[q + dim + 2];
            }
            // levels 2 .. n-1 in place
            for (int r = 2; r < n; r++) {
                for (int k = 0, w = work; k <= n - r; k++, w += dim) {
                    scratch[w] = su * scratch[w] + u * scratch[w + dim];
                    scratch[w + 1] = su * scratch[w + 1] + u * scratch[w + dim + 1];
                    scratch[w + 2] = su * scratch[w + 2] + u * scratch[w + dim + 2];
                }
            }
            scratch[ca] = scratch[work];
            scratch[ca + 1] = scratch[work + 1];
            scratch[ca + 2] = scratch[work + 2];
            scratch[cb] = scratch[work + dim];
            scratch[cb + 1] = scratch[work + dim + 1];
            scratch[cb + 2] = scratch[work + dim + 2];
        }
        DeCasteljau.reduceForward(scratch, colA, dim, m, dim, v, m - 1);
        DeCasteljau.reduceForward(scratch, colB, dim, m, dim, v, m - 1);
        double sv = 1 - v;
        for (int c = 0; c < dim; c++) {
            double b00 = scratch[colA + c], b01 = scratch[colA + dim + c];
            double b10 = scratch[colB + c], b11 = scratch[colB + dim + c];
            double lo = sv * b00 + v * b01;
            double hi = sv * b10 + v * b11;
            out[outOff + c] = su * lo + u * hi;
            out[outOff + dim + c] = n * (hi - lo);
            out[outOff + 2 * dim + c] = m * (su * (b01 - b00) + u * (b11 - b10));
        }
    }

    /**
     * {@link DeCasteljau#evaluateWithDerivatives(double[], int, int, int, int, double, double,
     * double[], int, double[], int)} of a bicubic homogeneous net ({@code dim = 4}): the value and
     * both derivatives of each of the four coordinates, in the generic layout, with the same
     * operations on locals.
     */
    static void bicubic4WithDerivatives(double[] net, int off, double u, double v, double[] out, int outOff) {
        for (int c = 0; c < 4; c++) {
            bicubicWithDerivatives(net, off + c, 4, u, v, out, outOff + c, 4);
        }
    }

    /**
     * One coordinate of a bicubic net (points {@code ps} doubles apart, rows {@code 4·ps}) at
     * {@code (u,v)}: value, {@code ∂/∂u} and {@code ∂/∂v} into {@code out[oo]},
     * {@code out[oo+os]}, {@code out[oo+2·os]}; the same operations as the generic path, on locals.
     */
    private static void bicubicWithDerivatives(double[] p, int o, int ps, double u, double v, double[] out, int oo,
                                               int os) {
        int p1 = ps, p2 = 2 * ps, p3 = 3 * ps, rs = 4 * ps;
        double su = 1 - u;
        // Every row in u down to level 2: a_j = b_0^2, b_j = b_1^2 of row j
        double a0, a1, a2, a3, b0, b1, b2, b3;
        {
            double l0 = su * p[o] + u * p[o + p1], l1 = su * p[o + p1] + u * p[o + p2], l2 = su * p[o + p2] + u * p[o + p3];
            a0 = su * l0 + u * l1;
            b0 = su * l1 + u * l2;
        }
        {
            int r = o + rs;
            double l0 = su * p[r] + u * p[r + p1], l1 = su * p[r + p1] + u * p[r + p2], l2 = su * p[r + p2] + u * p[r + p3];
            a1 = su * l0 + u * l1;
            b1 = su * l1 + u * l2;
        }
        {
            int r = o + 2 * rs;
            double l0 = su * p[r] + u * p[r + p1], l1 = su * p[r + p1] + u * p[r + p2], l2 = su * p[r + p2] + u * p[r + p3];
            a2 = su * l0 + u * l1;
            b2 = su * l1 + u * l2;
        }
        {
            int r = o + 3 * rs;
            double l0 = su * p[r] + u * p[r + p1], l1 = su * p[r + p1] + u * p[r + p2], l2 = su * p[r + p2] + u * p[r + p3];
            a3 = su * l0 + u * l1;
            b3 = su * l1 + u * l2;
        }
        // Both columns in v down to level 2
        double sv = 1 - v;
        double ca0 = sv * a0 + v * a1, ca1 = sv * a1 + v * a2, ca2 = sv * a2 + v * a3;
        double cb0 = sv * b0 + v * b1, cb1 = sv * b1 + v * b2, cb2 = sv * b2 + v * b3;
        double b00 = sv * ca0 + v * ca1, b01 = sv * ca1 + v * ca2;
        double b10 = sv * cb0 + v * cb1, b11 = sv * cb1 + v * cb2;
        double lo = sv * b00 + v * b01;
        double hi = sv * b10 + v * b11;
        out[oo] = su * lo + u * hi;
        out[oo + os] = 3 * (hi - lo);
        out[oo + 2 * os] = 3 * (su * (b01 - b00) + u * (b11 - b10));
    }
}
