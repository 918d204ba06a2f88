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
}
