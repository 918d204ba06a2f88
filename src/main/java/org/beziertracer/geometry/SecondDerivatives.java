package org.beziertracer.geometry;

/**
 * A Bézier patch's point with its first and second partial derivatives, exact (to rounding) for
 * any degree 1..15, polynomial or rational:
 * <pre>
 *   S, S_u, S_v, S_uu, S_uv, S_vv
 * </pre>
 * from the Bernstein basis and its derivatives in each direction,
 * {@code (B_i^n)' = n (B_{i−1}^{n−1} − B_i^{n−1})} and
 * {@code (B_i^n)'' = n(n−1) (B_{i−2}^{n−2} − 2 B_{i−1}^{n−2} + B_i^{n−2})}, summed over the net row by row
 * (G. Farin, <i>Curves and Surfaces for CAGD</i>, 5th ed., 2002, the chapters on derivatives of
 * Bézier curves and of tensor-product patches). A rational patch is evaluated on its homogeneous
 * net {@code (wx, wy, wz, w)} and brought to Euclidean derivatives by the quotient rule:
 * <pre>
 *   S = p / w,   S_u = (p_u − w_u S) / w,
 *   S_uu = (p_uu − 2 w_u S_u − w_uu S) / w,   S_uv = (p_uv − w_u S_v − w_v S_u − w_uv S) / w
 * </pre>
 * (the same for {@code v}). The basis values are computed by the triangle
 * {@code B_i^k = (1−t) B_i^{k−1} + t B_{i−1}^{k−1}}: convex combinations, as well conditioned as
 * de Casteljau.
 *
 * <p>Allocation-free; thread-safe with one scratch array per thread ({@link #SCRATCH} doubles).
 */
public final class SecondDerivatives {
    private SecondDerivatives() {}

    private static final int ORDER = DeCasteljau.MAX_ORDER;

    /** Doubles of {@code out}: S, S_u, S_v, S_uu, S_uv, S_vv, three each. */
    public static final int LENGTH = 18;

    // scratch layout: three basis rows (value, first, second derivative) per direction, the
    // triangle's working row, then the row sums (value, d/du, d²/du² per row j, 4 coordinates each),
    // then the homogeneous results
    private static final int BU = 0, BV = 3 * ORDER, TRI = 6 * ORDER, ROWS = 7 * ORDER, HOM = ROWS + 12 * ORDER;

    /** Scratch doubles {@link #evaluate} uses. */
    public static final int SCRATCH = HOM + 24;

    /**
     * Writes S, S_u, S_v, S_uu, S_uv, S_vv (Euclidean) of the degree {@code n}×{@code m} net at
     * {@code net[off..]} at {@code (u,v)} into {@code out[0..18)}.
     *
     * @param dim 3 for a polynomial net, 4 for a homogeneous rational one ({@link RationalDeCasteljau})
     */
    public static void evaluate(double[] net, int off, int n, int m, int dim, double u, double v, double[] out,
                                double[] scratch) {
        evaluate(net, off, n, m, dim, u, v, out, 0, scratch, 0);
    }

    /** As {@link #evaluate(double[], int, int, int, int, double, double, double[], double[])}, into {@code out[outOff..]}, scratch from {@code so}. */
    public static void evaluate(double[] net, int off, int n, int m, int dim, double u, double v, double[] out,
                                int outOff, double[] scratch, int so) {
        basis(n, u, scratch, so + BU, so + TRI);
        basis(m, v, scratch, so + BV, so + TRI);
        final int ROWS = so + SecondDerivatives.ROWS, HOM = so + SecondDerivatives.HOM, BU = so, BV = so + SecondDerivatives.BV;
        // Row sums in u: r0_j = Σ_i P_ij B_i(u), r1_j = Σ_i P_ij B_i'(u), r2_j = Σ_i P_ij B_i''(u)
        for (int j = 0; j <= m; j++) {
            int row = ROWS + 12 * j;
            for (int c = 0; c < 12; c++) {
                scratch[row + c] = 0;
            }
            for (int i = 0; i <= n; i++) {
                int p = off + dim * (j * (n + 1) + i);
                double b0 = scratch[BU + i], b1 = scratch[BU + ORDER + i], b2 = scratch[BU + 2 * ORDER + i];
                for (int c = 0; c < dim; c++) {
                    double x = net[p + c];
                    scratch[row + c] += x * b0;
                    scratch[row + 4 + c] += x * b1;
                    scratch[row + 8 + c] += x * b2;
                }
            }
        }
        // Homogeneous H, H_u, H_v, H_uu, H_uv, H_vv, 4 coordinates each
        for (int k = 0; k < 24; k++) {
            scratch[HOM + k] = 0;
        }
        for (int j = 0; j <= m; j++) {
            int row = ROWS + 12 * j;
            double c0 = scratch[BV + j], c1 = scratch[BV + ORDER + j], c2 = scratch[BV + 2 * ORDER + j];
            for (int c = 0; c < dim; c++) {
                double r0 = scratch[row + c], r1 = scratch[row + 4 + c], r2 = scratch[row + 8 + c];
                scratch[HOM + c] += r0 * c0;
                scratch[HOM + 4 + c] += r1 * c0;
                scratch[HOM + 8 + c] += r0 * c1;
                scratch[HOM + 12 + c] += r2 * c0;
                scratch[HOM + 16 + c] += r1 * c1;
                scratch[HOM + 20 + c] += r0 * c2;
            }
        }
        if (dim == 3) {
            for (int d = 0; d < 6; d++) {
                System.arraycopy(scratch, HOM + 4 * d, out, outOff + 3 * d, 3);
            }
            return;
        }
        double w = scratch[HOM + 3], wu = scratch[HOM + 7], wv = scratch[HOM + 11];
        double wuu = scratch[HOM + 15], wuv = scratch[HOM + 19], wvv = scratch[HOM + 23];
        for (int c = 0; c < 3; c++) {
            double s = scratch[HOM + c] / w;
            double su = (scratch[HOM + 4 + c] - wu * s) / w;
            double sv = (scratch[HOM + 8 + c] - wv * s) / w;
            out[outOff + c] = s;
            out[outOff + 3 + c] = su;
            out[outOff + 6 + c] = sv;
            out[outOff + 9 + c] = (scratch[HOM + 12 + c] - 2 * wu * su - wuu * s) / w;
            out[outOff + 12 + c] = (scratch[HOM + 16 + c] - wu * sv - wv * su - wuv * s) / w;
            out[outOff + 15 + c] = (scratch[HOM + 20 + c] - 2 * wv * sv - wvv * s) / w;
        }
    }

    /**
     * The degree-{@code n} Bernstein basis at {@code t} and its first and second derivatives into
     * {@code s[at ..]}, {@code s[at+ORDER ..]}, {@code s[at+2·ORDER ..]}.
     */
    private static void basis(int n, double t, double[] b, int at, int tri) {
        int first = at + ORDER, second = at + 2 * ORDER;
        // The triangle B^k = (1−t) B^{k−1} + t B^{k−1} shifted, degree by degree; at the start of
        // step k it holds degree k−1: keep degree n−2 and n−1 on the way
        b[tri] = 1;
        for (int k = 1; k <= n; k++) {
            if (k == n - 1) {
                System.arraycopy(b, tri, b, second, n - 1);
            }
            if (k == n) {
                System.arraycopy(b, tri, b, first, n);
            }
            b[tri + k] = t * b[tri + k - 1];
            for (int i = k - 1; i > 0; i--) {
                b[tri + i] = (1 - t) * b[tri + i] + t * b[tri + i - 1];
            }
            b[tri] = (1 - t) * b[tri];
        }
        // The derivative rows, from i = n down (each reads only its own and lower indices)
        for (int i = n; i >= 0; i--) {
            double d2 = 0;
            if (n >= 2) {
                double a = i >= 2 ? b[second + i - 2] : 0;
                double c = i >= 1 && i - 1 <= n - 2 ? b[second + i - 1] : 0;
                double d = i <= n - 2 ? b[second + i] : 0;
                d2 = n * (n - 1) * (a - 2 * c + d);
            }
            double a1 = i >= 1 ? b[first + i - 1] : 0;
            double d1 = i <= n - 1 ? b[first + i] : 0;
            b[second + i] = d2;
            b[first + i] = n * (a1 - d1);
        }
        System.arraycopy(b, tri, b, at, n + 1);
    }
}
