package org.beziertracer.geometry;

/**
 * Ray-independent data for a cheap single-root test of a sub-patch (see
 * {@code intersect.RootUniqueness#atMostOneRoot(TraceContext, SubPatchTable, int)}):
 * the first-derivative directions of the net, bounded by balls.
 *
 * <p>The control points of the u-hodograph of a degree n×m net are {@code n·(P[i+1][j] − P[i][j])}
 * and those of the v-hodograph {@code m·(P[i][j+1] − P[i][j])} (Farin, "Curves and Surfaces for
 * CAGD", 5th ed., §16.6); by the convex-hull property {@code Su/n} lies, everywhere on the patch,
 * in the ball of centre {@code a} (centre of the differences' bounding box) and radius
 * {@code ra} (largest distance of a difference from {@code a}), and {@code Sv/m} in the ball
 * {@code (b, rb)}. Stored per sub-patch, {@link #STRIDE} doubles: {@code a, b, ra, rb} and a
 * margin for rounding.
 */
final class HodographBounds {
    private HodographBounds() {}

    /** Doubles per sub-patch in {@link SubPatchTable#uniqueness}. */
    static final int STRIDE = 9;

    /**
     * Writes {@code (a, b, ra, rb, margin)} of the degree {@code n}×{@code m} net at
     * {@code net[off..]} to {@code out[o..o+9)}; {@code ab} is scratch of 6 doubles.
     */
    static void compute(double[] net, int off, int n, int m, double[] out, int o, double[] ab) {
        int row = 3 * (n + 1);
        double ra = ballOf(net, off, n, m, 3, row, ab, 0);
        double rb = ballOf(net, off, n + 1, m - 1, row, row, ab, 3);
        System.arraycopy(ab, 0, out, o, 6);
        double la = Math.sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
        double lb = Math.sqrt(ab[3] * ab[3] + ab[4] * ab[4] + ab[5] * ab[5]);
        out[o + 6] = ra;
        out[o + 7] = rb;
        // Rounding of the differences, of the centres' projections and of the products (generous)
        out[o + 8] = 1e-10 * (la + ra) * (lb + rb);
    }

    /**
     * The same data for a rational net: Euclidean points {@code xyz[off..]} and their weights
     * {@code w[wOff..]}. The first derivative of the rational patch {@code S = A/W} (homogeneous
     * parts {@code A = Σ w P B}, {@code W = Σ w B}) is {@code S_u = N_u / W} with
     * {@code N_u = (A_u·W − A·W_u) / W}. The single-root test only asks whether
     * {@code F1u(ξ1)·F2v(ξ2) − F1v(ξ1)·F2u(ξ2)} can vanish, and dividing the derivatives at
     * {@code ξ1} and at {@code ξ2} by the positive {@code W} there does not change its sign; so
     * the balls here bound {@code N_u/n} and {@code N_v/m}. Expanding the products of Bernstein
     * sums, {@code A_u·W − A·W_u = n·Σ c·V} with non-negative coefficients {@code c} summing to
     * {@code W} and the vectors {@code V = w_q·(P_q − P_k) − w_p·(P_p − P_k)} for every pair
     * {@code p, q} of u-neighbours and every point {@code k}; so {@code N_u/n} lies in the convex
     * hull of those {@code V} (for equal weights they are the polynomial hodograph's differences).
     * The ball is the one around their box.
     */
    static void computeRational(double[] xyz, int off, double[] w, int wOff, int n, int m, double[] out, int o) {
        double ra = rationalBall(xyz, off, w, wOff, n, m, 1, out, o);
        double rb = rationalBall(xyz, off, w, wOff, n, m, n + 1, out, o + 3);
        double la = Math.sqrt(out[o] * out[o] + out[o + 1] * out[o + 1] + out[o + 2] * out[o + 2]);
        double lb = Math.sqrt(out[o + 3] * out[o + 3] + out[o + 4] * out[o + 4] + out[o + 5] * out[o + 5]);
        out[o + 6] = ra;
        out[o + 7] = rb;
        out[o + 8] = 1e-10 * (la + ra) * (lb + rb);
    }

    /**
     * Centre (to {@code out[o..o+3)}) and radius of the ball around the box of the vectors
     * {@code V} of {@link #computeRational} for neighbours {@code step} apart (1: along u; the
     * points of a row: along v).
     */
    private static double rationalBall(double[] xyz, int off, double[] w, int wOff, int n, int m, int step,
                                       double[] out, int o) {
        int row = n + 1, points = (n + 1) * (m + 1);
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int p = j * row + i, q = p + step;
                if ((step == 1 && i == n) || (step != 1 && j == m)) {
                    continue;
                }
                double wp = w[wOff + p], wq = w[wOff + q], d = wq - wp;
                for (int c = 0; c < 3; c++) {
                    double a = wq * xyz[off + 3 * q + c] - wp * xyz[off + 3 * p + c];
                    for (int k = 0; k < points; k++) {
                        double v = a - d * xyz[off + 3 * k + c];
                        lo[c] = Math.min(lo[c], v);
                        hi[c] = Math.max(hi[c], v);
                    }
                }
            }
        }
        double r2 = 0;
        for (int c = 0; c < 3; c++) {
            out[o + c] = 0.5 * (lo[c] + hi[c]);
            r2 += 0.25 * (hi[c] - lo[c]) * (hi[c] - lo[c]);
        }
        return Math.sqrt(r2);
    }

    /**
     * Ball around the differences {@code net[p + step] − net[p]} for {@code cols} points per row
     * and {@code rows + 1} rows ({@code rowStride} doubles apart): centre to {@code ab[c..c+3)},
     * returns the radius. With {@code step = 3} and n columns of differences per row this is the
     * u-hodograph; with {@code step = rowStride} the v-hodograph.
     */
    private static double ballOf(double[] net, int off, int cols, int rows, int step, int rowStride,
                                 double[] ab, int c) {
        double loX = Double.POSITIVE_INFINITY, loY = loX, loZ = loX;
        double hiX = Double.NEGATIVE_INFINITY, hiY = hiX, hiZ = hiX;
        for (int pass = 0; pass < 2; pass++) {
            double cx = 0.5 * (loX + hiX), cy = 0.5 * (loY + hiY), cz = 0.5 * (loZ + hiZ), r2 = 0;
            for (int j = 0; j <= rows; j++) {
                for (int i = 0, p = off + j * rowStride; i < cols; i++, p += 3) {
                    double x = net[p + step] - net[p], y = net[p + step + 1] - net[p + 1];
                    double z = net[p + step + 2] - net[p + 2];
                    if (pass == 0) {
                        // comparisons, not Math.min/max: the split of 100 teapots takes 10–20 % less
                        // (JDK 17; the nets hold no NaN, and the sign of a zero bound changes nothing)
                        if (x < loX) loX = x;
                        if (x > hiX) hiX = x;
                        if (y < loY) loY = y;
                        if (y > hiY) hiY = y;
                        if (z < loZ) loZ = z;
                        if (z > hiZ) hiZ = z;
                    } else {
                        double ex = x - cx, ey = y - cy, ez = z - cz;
                        double d2 = ex * ex + ey * ey + ez * ez;
                        if (d2 > r2) r2 = d2;
                    }
                }
            }
            if (pass == 1) {
                ab[c] = cx; ab[c + 1] = cy; ab[c + 2] = cz;
                return Math.sqrt(r2);
            }
        }
        throw new AssertionError();
    }
}
