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

    // scratch layout: three basis rows (value, first, second derivative) per direction, then the
    // triangle's working row
    private static final int BU = 0, BV = 3 * ORDER, TRI = 6 * ORDER;

    /** Scratch doubles {@link #evaluate} uses. */
    public static final int SCRATCH = 7 * ORDER;

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
        int bu = so + BU, bv = so + BV;
        basis(n, u, scratch, bu, so + TRI);
        basis(m, v, scratch, bv, so + TRI);
        // Homogeneous H, H_u, H_v, H_uu, H_uv, H_vv (x, y, z, w each) in locals: the row sums in u
        // (value, first and second derivative), then their sums in v
        double hx = 0, hy = 0, hz = 0, hw = 0, ux = 0, uy = 0, uz = 0, uw = 0, vx = 0, vy = 0, vz = 0, vw = 0;
        double uux = 0, uuy = 0, uuz = 0, uuw = 0, uvx = 0, uvy = 0, uvz = 0, uvw = 0, vvx = 0, vvy = 0, vvz = 0, vvw = 0;
        boolean rational = dim == 4;
        for (int j = 0; j <= m; j++) {
            double ax = 0, ay = 0, az = 0, aw = 0, dx = 0, dy = 0, dz = 0, dw = 0, ex = 0, ey = 0, ez = 0, ew = 0;
            int p = off + dim * j * (n + 1);
            for (int i = 0; i <= n; i++, p += dim) {
                double b0 = scratch[bu + i], b1 = scratch[bu + ORDER + i], b2 = scratch[bu + 2 * ORDER + i];
                double x = net[p], y = net[p + 1], z = net[p + 2], w = rational ? net[p + 3] : 1;
                ax += x * b0; ay += y * b0; az += z * b0; aw += w * b0;
                dx += x * b1; dy += y * b1; dz += z * b1; dw += w * b1;
                ex += x * b2; ey += y * b2; ez += z * b2; ew += w * b2;
            }
            double c0 = scratch[bv + j], c1 = scratch[bv + ORDER + j], c2 = scratch[bv + 2 * ORDER + j];
            hx += ax * c0; hy += ay * c0; hz += az * c0; hw += aw * c0;
            ux += dx * c0; uy += dy * c0; uz += dz * c0; uw += dw * c0;
            vx += ax * c1; vy += ay * c1; vz += az * c1; vw += aw * c1;
            uux += ex * c0; uuy += ey * c0; uuz += ez * c0; uuw += ew * c0;
            uvx += dx * c1; uvy += dy * c1; uvz += dz * c1; uvw += dw * c1;
            vvx += ax * c2; vvy += ay * c2; vvz += az * c2; vvw += aw * c2;
        }
        double[] o = out;
        int k = outOff;
        if (!rational) {
            o[k] = hx; o[k + 1] = hy; o[k + 2] = hz;
            o[k + 3] = ux; o[k + 4] = uy; o[k + 5] = uz;
            o[k + 6] = vx; o[k + 7] = vy; o[k + 8] = vz;
            o[k + 9] = uux; o[k + 10] = uuy; o[k + 11] = uuz;
            o[k + 12] = uvx; o[k + 13] = uvy; o[k + 14] = uvz;
            o[k + 15] = vvx; o[k + 16] = vvy; o[k + 17] = vvz;
            return;
        }
        quotient(hx, ux, vx, uux, uvx, vvx, hw, uw, vw, uuw, uvw, vvw, o, k);
        quotient(hy, uy, vy, uuy, uvy, vvy, hw, uw, vw, uuw, uvw, vvw, o, k + 1);
        quotient(hz, uz, vz, uuz, uvz, vvz, hw, uw, vw, uuw, uvw, vvw, o, k + 2);
    }

    /** One Euclidean coordinate's S, S_u, S_v, S_uu, S_uv, S_vv from its homogeneous ones (quotient rule), stride 3. */
    private static void quotient(double p, double pu, double pv, double puu, double puv, double pvv, double w, double wu,
                                 double wv, double wuu, double wuv, double wvv, double[] out, int k) {
        double s = p / w;
        double su = (pu - wu * s) / w;
        double sv = (pv - wv * s) / w;
        out[k] = s;
        out[k + 3] = su;
        out[k + 6] = sv;
        out[k + 9] = (puu - 2 * wu * su - wuu * s) / w;
        out[k + 12] = (puv - wu * sv - wv * su - wuv * s) / w;
        out[k + 15] = (pvv - 2 * wv * sv - wvv * s) / w;
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
                for (int i = 0; i < n - 1; i++) {
                    b[second + i] = b[tri + i];
                }
            }
            if (k == n) {
                for (int i = 0; i < n; i++) {
                    b[first + i] = b[tri + i];
                }
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
        for (int i = 0; i <= n; i++) {
            b[at + i] = b[tri + i];
        }
    }
}
