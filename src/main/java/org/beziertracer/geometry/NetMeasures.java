package org.beziertracer.geometry;

import org.beziertracer.math.Bounds;

/**
 * Cheap measures of a control net (layout as in {@link DeCasteljau}): its axis-aligned box and
 * its flatness. Allocation-free and thread-safe.
 *
 * <p>Both rest on the convex-hull property of Bézier patches: the surface lies in the convex
 * hull of its control points, hence in their box, and it deviates from any bilinear patch by at
 * most the largest deviation of the control points from that patch sampled at the Greville
 * abscissae {@code (i/n, j/m)} (linear precision; G. Farin, <i>Curves and Surfaces for CAGD</i>,
 * 5th ed.; the flatness test of J. Lane, L. Carpenter, "A generalized scan line
 * algorithm for the computer display of parametrically defined surfaces", CGIP 11, 1979).
 */
public final class NetMeasures {

    private NetMeasures() {}

    /**
     * Box of the 3-D net's control points into {@code dest6 = minX, minY, minZ, maxX, maxY, maxZ}
     * (via {@link Bounds#ofPoints}).
     */
    public static void controlBounds(double[] net, int off, int n, int m, double[] dest6) {
        Bounds.ofPoints(net, off, (n + 1) * (m + 1), dest6);
    }

    /**
     * Box of a net with {@code dim} coordinates per point: minima into
     * {@code dest[destOff .. +dim)}, maxima into {@code dest[destOff+dim .. +2dim)}.
     */
    public static void controlBounds(double[] net, int off, int n, int m, int dim, double[] dest, int destOff) {
        int count = (n + 1) * (m + 1);
        for (int c = 0; c < dim; c++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int k = 0, p = off + c; k < count; k++, p += dim) {
                double x = net[p];
                if (x < lo) lo = x;
                if (x > hi) hi = x;
            }
            dest[destOff + c] = lo;
            dest[destOff + dim + c] = hi;
        }
    }

    /**
     * Flatness of a 3-D net: the largest Euclidean distance of a control point {@code P_ij} from
     * the bilinear patch through the four corner points evaluated at {@code (i/n, j/m)}. Zero
     * exactly when the surface is that bilinear patch (for any degree); an upper bound on the
     * distance between the surface and the bilinear patch.
     */
    public static double flatness(double[] net, int off, int n, int m) {
        return flatness(net, off, n, m, 3);
    }

    /** Scratch doubles {@link #flatness(double[], int, int, int, double[])} needs at degree {@code n} in u. */
    public static int flatnessScratch(int n) {
        return 6 * (n + 1);
    }

    /**
     * {@link #flatness(double[], int, int, int)}, the same value to the last bit, with the
     * bilinear patch's two terms of each column {@code i} ({@code (1−u)·P_00 + u·P_n0} and
     * {@code (1−u)·P_0m + u·P_nm}) computed once instead of once a row: the pre-split calls it at
     * every node. {@code scratch}: at least {@link #flatnessScratch} doubles.
     */
    public static double flatness(double[] net, int off, int n, int m, double[] scratch) {
        int row = 3 * (n + 1);
        int c00 = off, cn0 = off + 3 * n, c0m = off + m * row, cnm = c0m + 3 * n;
        for (int i = 0; i <= n; i++) {
            double u = (double) i / n, su = 1 - u;
            for (int c = 0; c < 3; c++) {
                scratch[6 * i + c] = su * net[c00 + c] + u * net[cn0 + c];
                scratch[6 * i + 3 + c] = su * net[c0m + c] + u * net[cnm + c];
            }
        }
        double maxSq = 0;
        for (int j = 0; j <= m; j++) {
            double v = (double) j / m, sv = 1 - v;
            for (int i = 0, p = off + j * row, q = 0; i <= n; i++, p += 3, q += 6) {
                double dx = net[p] - (sv * scratch[q] + v * scratch[q + 3]);
                double dy = net[p + 1] - (sv * scratch[q + 1] + v * scratch[q + 4]);
                double dz = net[p + 2] - (sv * scratch[q + 2] + v * scratch[q + 5]);
                double dSq = dx * dx + dy * dy + dz * dz;
                if (dSq > maxSq) maxSq = dSq;
            }
        }
        return Math.sqrt(maxSq);
    }

    /** {@link #flatness(double[], int, int, int)} for any {@code dim}. */
    public static double flatness(double[] net, int off, int n, int m, int dim) {
        int row = (n + 1) * dim;
        int c00 = off, cn0 = off + n * dim, c0m = off + m * row, cnm = c0m + n * dim;
        double maxSq = 0;
        for (int j = 0; j <= m; j++) {
            double v = (double) j / m, sv = 1 - v;
            for (int i = 0; i <= n; i++) {
                double u = (double) i / n, su = 1 - u;
                int p = off + j * row + i * dim;
                double dSq = 0;
                for (int c = 0; c < dim; c++) {
                    double bilinear = sv * (su * net[c00 + c] + u * net[cn0 + c])
                            + v * (su * net[c0m + c] + u * net[cnm + c]);
                    double d = net[p + c] - bilinear;
                    dSq += d * d;
                }
                if (dSq > maxSq) maxSq = dSq;
            }
        }
        return Math.sqrt(maxSq);
    }

    /**
     * Length of the corner points' twist {@code T = P00 − Pn0 − P0m + Pnm} of a 3-D net. The
     * bilinear patch through the corners is the parallelogram spanned at their centroid plus
     * {@code (u − ½)(v − ½) T}, so it lies within {@code |T| / 4} of that plane parallelogram, and
     * the surface within {@link #flatness} {@code + |T| / 4}.
     */
    public static double twist(double[] net, int off, int n, int m) {
        int row = 3 * (n + 1);
        int c00 = off, cn0 = off + 3 * n, c0m = off + m * row, cnm = c0m + 3 * n;
        double x = net[c00] - net[cn0] - net[c0m] + net[cnm];
        double y = net[c00 + 1] - net[cn0 + 1] - net[c0m + 1] + net[cnm + 1];
        double z = net[c00 + 2] - net[cn0 + 2] - net[c0m + 2] + net[cnm + 2];
        return Math.sqrt(x * x + y * y + z * z);
    }

    /**
     * A bound {@code M} on the second derivatives of the patch of the 3-D net: for every
     * {@code (u,v)} in {@code [0,1]²}, {@code |S_uu|}, {@code |S_uv|} and {@code |S_vv|} are at most
     * {@code M}, hence for any step {@code (a,b)} the Taylor remainder
     * {@code |S(u+a,v+b) − S(u,v) − a·S_u − b·S_v| ≤ ½·M·(|a|+|b|)²} (integral form, segment inside
     * the domain). The second derivatives are Bézier patches whose control points are
     * {@code n(n−1)·Δ²_u P}, {@code n·m·Δ_uΔ_v P} and {@code m(m−1)·Δ²_v P} (Farin, <i>Curves and
     * Surfaces for CAGD</i>, the derivatives of tensor-product patches), so by the convex-hull
     * property each is at most the largest length among its control points. Rounded up a little
     * for the rounding of the differences.
     */
    public static double secondDerivativeBound(double[] net, int off, int n, int m) {
        int row = 3 * (n + 1);
        double uu = 0, uv = 0, vv = 0;
        for (int j = 0; j <= m; j++) {
            for (int i = 0, p = off + j * row; i <= n; i++, p += 3) {
                double x, y, z;
                if (i + 2 <= n) {
                    x = net[p] - 2 * net[p + 3] + net[p + 6];
                    y = net[p + 1] - 2 * net[p + 4] + net[p + 7];
                    z = net[p + 2] - 2 * net[p + 5] + net[p + 8];
                    uu = Math.max(uu, x * x + y * y + z * z);
                }
                if (j + 2 <= m) {
                    x = net[p] - 2 * net[p + row] + net[p + 2 * row];
                    y = net[p + 1] - 2 * net[p + row + 1] + net[p + 2 * row + 1];
                    z = net[p + 2] - 2 * net[p + row + 2] + net[p + 2 * row + 2];
                    vv = Math.max(vv, x * x + y * y + z * z);
                }
                if (i < n && j < m) {
                    x = net[p] - net[p + 3] - net[p + row] + net[p + row + 3];
                    y = net[p + 1] - net[p + 4] - net[p + row + 1] + net[p + row + 4];
                    z = net[p + 2] - net[p + 5] - net[p + row + 2] + net[p + row + 5];
                    uv = Math.max(uv, x * x + y * y + z * z);
                }
            }
        }
        double bound = Math.max(Math.max(n * (n - 1) * Math.sqrt(uu), m * (m - 1) * Math.sqrt(vv)), n * m * Math.sqrt(uv));
        return bound * (1 + 1e-9) + 1e-300;
    }
}
