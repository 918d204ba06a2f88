package org.beziertracer.geometry;

import org.beziertracer.model.BezierPatch;

/**
 * Degree elevation of tensor-product Bézier nets: the same surface described by one more
 * control point per row (u) or per column (v). For a curve of degree {@code n},
 * {@code Q_i = (i/(n+1))·P_{i-1} + (1 − i/(n+1))·P_i}, {@code i = 0..n+1}
 * (G. Farin, <i>Curves and Surfaces for CAGD</i>, 5th ed., section "Degree elevation"; applied
 * row- or column-wise for patches).
 */
public final class DegreeElevation {

    private DegreeElevation() {}

    /**
     * The patch with degree in u raised by one (a rational patch through its homogeneous net; the
     * domain is kept, the origin dropped); throws if it is already {@link BezierPatch#MAX_DEGREE}.
     */
    public static BezierPatch elevateU(BezierPatch p) {
        int n = p.degreeU(), m = p.degreeV(), dim = Patches.dim(p);
        BezierPatch.checkDegree("u", n + 1);
        double[] dest = new double[(n + 2) * (m + 1) * dim];
        elevateU(Patches.workingNet(p), 0, n, m, dim, dest, 0);
        return BezierPatch.fromNet(n + 1, m, dest, dim, p.domain(), null);
    }

    /** The patch with degree in v raised by one; as {@link #elevateU}. */
    public static BezierPatch elevateV(BezierPatch p) {
        int n = p.degreeU(), m = p.degreeV(), dim = Patches.dim(p);
        BezierPatch.checkDegree("v", m + 1);
        double[] dest = new double[(n + 1) * (m + 2) * dim];
        elevateV(Patches.workingNet(p), 0, n, m, dim, dest, 0);
        return BezierPatch.fromNet(n, m + 1, dest, dim, p.domain(), null);
    }

    /**
     * Allocation-free: writes the degree {@code (n+1, m)} net of the degree {@code (n, m)} net
     * {@code src} into {@code dest} ({@code (n+2)(m+1)*dim} doubles, must not overlap src).
     */
    public static void elevateU(double[] src, int srcOff, int n, int m, int dim, double[] dest, int destOff) {
        for (int j = 0; j <= m; j++) {
            elevateCurve(src, srcOff + j * (n + 1) * dim, dim, n, dim, dest, destOff + j * (n + 2) * dim, dim);
        }
    }

    /**
     * Allocation-free: writes the degree {@code (n, m+1)} net of {@code src} into {@code dest}
     * ({@code (n+1)(m+2)*dim} doubles, must not overlap src).
     */
    public static void elevateV(double[] src, int srcOff, int n, int m, int dim, double[] dest, int destOff) {
        int row = (n + 1) * dim;
        for (int i = 0; i <= n; i++) {
            elevateCurve(src, srcOff + i * dim, row, m, dim, dest, destOff + i * dim, row);
        }
    }

    private static void elevateCurve(double[] src, int srcOff, int srcStride, int deg, int dim,
                                     double[] dest, int destOff, int destStride) {
        for (int i = 0; i <= deg + 1; i++) {
            double a = (double) i / (deg + 1);
            int d = destOff + i * destStride, s = srcOff + i * srcStride;
            for (int c = 0; c < dim; c++) {
                double prev = i > 0 ? src[s - srcStride + c] : 0;
                double cur = i <= deg ? src[s + c] : 0;
                dest[d + c] = a * prev + (1 - a) * cur;
            }
        }
    }
}
