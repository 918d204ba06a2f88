package org.beziertracer.geometry;

/**
 * Curvature of a Bézier patch at a point, from its exact first and second derivatives
 * ({@link SecondDerivatives}): the first fundamental form {@code E = S_u·S_u, F = S_u·S_v,
 * G = S_v·S_v}, the second {@code L = S_uu·n, M = S_uv·n, N = S_vv·n} with the unit normal
 * {@code n = S_u × S_v / |S_u × S_v|}, and
 * <pre>
 *   K = (LN − M²) / (EG − F²),   H = (EN − 2FM + GL) / (2 (EG − F²)),   k1,2 = H ± √(H² − K)
 * </pre>
 * (M. P. do Carmo, <i>Differential Geometry of Curves and Surfaces</i>, 1976, §3-3). The
 * curvatures are signed against {@code n} (a surface that bends toward its normal has positive
 * curvature; a sphere with outward normals has {@code k1 = k2 = −1/r}), {@code k1 ≥ k2}. The
 * principal directions are the eigenvectors of the shape operator: for {@code k1},
 * {@code a S_u + b S_v} with {@code (L − k E) a + (M − k F) b = 0} (the better conditioned of its two
 * rows), and the second is {@code n × d1}. At an umbilic (both rows vanish) any direction is
 * principal: {@code d1} is then {@code S_u} made unit.
 *
 * <p><b>Degenerate points</b> (a collapsed edge, a pole, where {@code S_u × S_v} vanishes or is
 * too small for the fundamental forms to be accurate, {@link #CONDITIONED}) are handled
 * as {@link PatchNormals} handles the normal: the curvature there is the limit from inside the
 * patch, taken toward the patch's centre at the first step {@code δ} (a growing fraction of the
 * way) where the cross product is large enough, extrapolated from {@code δ} and {@code 2δ}
 * (Richardson) so that the change over the step cancels to first order. The results are always finite.
 *
 * <p>Allocation-free; thread-safe with one scratch array per thread ({@link #SCRATCH} doubles).
 */
public final class SurfaceCurvature {
    private SurfaceCurvature() {}

    /** Doubles of {@code out}: K, H, k1, k2, d1 (3), d2 (3), n (3). */
    public static final int LENGTH = 13;
    /** Offsets in {@code out}. */
    public static final int GAUSSIAN = 0, MEAN = 1, K1 = 2, K2 = 3, D1 = 4, D2 = 7, NORMAL = 10;

    private static final int DERIV = 0;
    /** Scratch doubles {@link #at} uses. */
    public static final int SCRATCH = SecondDerivatives.LENGTH + SecondDerivatives.SCRATCH;

    /** Fractions of the way to the patch centre tried, in order, at a degenerate point (as {@link PatchNormals}). */
    private static final double[] INWARD_STEPS = {1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 0.25, 0.5, 1.0};

    /**
     * Curvature of the degree {@code n}×{@code m} net at {@code net[off..]} ({@code dim} 3, or 4
     * homogeneous rational) at {@code (u,v)} into {@code out[0..LENGTH)}.
     */
    public static void at(double[] net, int off, int n, int m, int dim, double u, double v, double[] out,
                          double[] scratch) {
        at(net, off, n, m, dim, u, v, PatchNormals.squaredExtent(net, off, n, m, dim), out, scratch);
    }

    /**
     * As {@link #at(double[], int, int, int, int, double, double, double[], double[])}, with the net's
     * {@link PatchNormals#squaredExtent} computed once by the caller (a property of the patch).
     */
    public static void at(double[] net, int off, int n, int m, int dim, double u, double v, double squaredExtent,
                          double[] out, double[] scratch) {
        double threshold = PatchNormals.DEGENERATE_RELATIVE * n * m * squaredExtent;
        if (curvatureAt(net, off, n, m, dim, u, v, out, scratch, threshold)) {
            return;
        }
        // degenerate or ill-conditioned here: keep a finite answer of this point, if any, as the last resort
        boolean here = fromDerivatives(scratch, DERIV, threshold, 0, out);
        double[] kept = here ? java.util.Arrays.copyOf(out, LENGTH) : null;
        double tu = 0.5, tv = 0.5;
        if (Math.abs(u - 0.5) + Math.abs(v - 0.5) < 1e-3) {
            tu = 0.75;
            tv = 0.625;
        }
        for (double delta : INWARD_STEPS) {
            if (curvatureAt(net, off, n, m, dim, u + delta * (tu - u), v + delta * (tv - v), out, scratch, threshold)) {
                // the limit by Richardson extrapolation from δ and 2δ (the O(δ) change cancels)
                double k = out[GAUSSIAN], h = out[MEAN], k1 = out[K1], k2 = out[K2];
                double d2 = 2 * delta;
                if (d2 <= 1 && curvatureAt(net, off, n, m, dim, u + d2 * (tu - u), v + d2 * (tv - v), out, scratch,
                        threshold)) {
                    k = 2 * k - out[GAUSSIAN];
                    h = 2 * h - out[MEAN];
                    k1 = 2 * k1 - out[K1];
                    k2 = 2 * k2 - out[K2];
                    curvatureAt(net, off, n, m, dim, u + delta * (tu - u), v + delta * (tv - v), out, scratch, threshold);
                }
                out[GAUSSIAN] = k;
                out[MEAN] = h;
                out[K1] = Math.max(k1, k2);
                out[K2] = Math.min(k1, k2);
                return;
            }
        }
        if (kept != null) {
            System.arraycopy(kept, 0, out, 0, LENGTH);
            return;
        }
        // a patch degenerate everywhere (a point, a curve): no surface to bend
        java.util.Arrays.fill(out, 0, LENGTH, 0);
        out[D1] = 1;
        out[D2 + 1] = 1;
        out[NORMAL + 2] = 1;
    }

    /**
     * Where the parametrisation's speeds differ by more than this squared ratio ({@code E/G} or
     * {@code G/E}, as next to a pole, where one tangent shrinks to nothing) or its tangents are this
     * close to parallel ({@code sin²} of their angle), the terms of {@code LN − M²} cancel and the
     * rounding grows as the inverse of the ratio: the curvature is then the limit from inside.
     * At 1e-6 the rounding stays near 1e-10 relative.
     */
    static final double CONDITIONED = 1e-6;

    private static boolean curvatureAt(double[] net, int off, int n, int m, int dim, double u, double v, double[] out,
                                       double[] scratch, double threshold) {
        SecondDerivatives.evaluate(net, off, n, m, dim, u, v, scratch, DERIV, scratch, SecondDerivatives.LENGTH);
        return fromDerivatives(scratch, DERIV, threshold, CONDITIONED, out);
    }

    /**
     * Curvature from {@code d[o..o+18)} = S, S_u, S_v, S_uu, S_uv, S_vv into {@code out}; false
     * (out unspecified) when {@code |S_u × S_v|} is not above {@code threshold} or not finite, or
     * the point is ill-conditioned by {@code conditioned} ({@link #CONDITIONED}; 0 accepts any).
     */
    public static boolean fromDerivatives(double[] d, int o, double threshold, double conditioned, double[] out) {
        double ux = d[o + 3], uy = d[o + 4], uz = d[o + 5];
        double vx = d[o + 6], vy = d[o + 7], vz = d[o + 8];
        double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
        double len = Math.sqrt(cx * cx + cy * cy + cz * cz);
        if (!(len > threshold) || !Double.isFinite(len)) {
            return false;
        }
        double nx = cx / len, ny = cy / len, nz = cz / len;
        double e = ux * ux + uy * uy + uz * uz, f = ux * vx + uy * vy + uz * vz, g = vx * vx + vy * vy + vz * vz;
        if (Math.min(e, g) < conditioned * Math.max(e, g) || len * len < conditioned * e * g) {
            return false;
        }
        double l = d[o + 9] * nx + d[o + 10] * ny + d[o + 11] * nz;
        double mm = d[o + 12] * nx + d[o + 13] * ny + d[o + 14] * nz;
        double nn = d[o + 15] * nx + d[o + 16] * ny + d[o + 17] * nz;
        // EG − F² = |S_u × S_v|² (Lagrange's identity), better conditioned than the difference
        double det = len * len;
        double k = (l * nn - mm * mm) / det;
        double h = (e * nn - 2 * f * mm + g * l) / (2 * det);
        // H² − K as a sum of squares, in the orthonormal frame e1 = S_u/|S_u|, e2 = n × e1, where
        // the shape operator is symmetric [[a, b], [b, c]]: H² − K = ((a − c)/2)² + b², free of the
        // cancellation that makes √(H² − K) lose half the digits near an umbilic
        double a = l / e, s2 = e / det;
        double b = Math.sqrt(s2 / e) * (mm - f * l / e), c = s2 * (l * f * f / (e * e) - 2 * mm * f / e + nn);
        double half = 0.5 * (a - c);
        double root = Math.sqrt(half * half + b * b);
        double k1 = h + root, k2 = h - root;
        if (!(Double.isFinite(k) && Double.isFinite(h))) {
            return false;
        }
        // Principal direction of k1: (L − kE) a + (M − kF) b = 0, or (M − kF) a + (N − kG) b = 0
        double r1a = l - k1 * e, r1b = mm - k1 * f, r2a = mm - k1 * f, r2b = nn - k1 * g;
        double pa, pb;
        if (r1a * r1a + r1b * r1b >= r2a * r2a + r2b * r2b) {
            pa = -r1b;
            pb = r1a;
        } else {
            pa = -r2b;
            pb = r2a;
        }
        double dx = pa * ux + pb * vx, dy = pa * uy + pb * vy, dz = pa * uz + pb * vz;
        double dl = Math.sqrt(dx * dx + dy * dy + dz * dz);
        // an umbilic (k1 = k2: both rows vanish to rounding) has every direction principal
        double scale = Math.abs(l) + Math.abs(mm) + Math.abs(nn) + Math.abs(k1) * (e + Math.abs(f) + g);
        if (!(dl > 1e-9 * scale * Math.sqrt(e + g)) || !Double.isFinite(dl)) {
            dx = ux;
            dy = uy;
            dz = uz;
            dl = Math.sqrt(e);
        }
        store(k, h, k1, k2, nx, ny, nz, dx / dl, dy / dl, dz / dl, out);
        return true;
    }

    /**
     * Writes a curvature record: K, H, k1, k2, the unit normal n, the unit principal direction d1
     * and d2 = n × d1.
     */
    public static void store(double k, double h, double k1, double k2, double nx, double ny, double nz, double dx,
                             double dy, double dz, double[] out) {
        out[GAUSSIAN] = k;
        out[MEAN] = h;
        out[K1] = k1;
        out[K2] = k2;
        out[NORMAL] = nx;
        out[NORMAL + 1] = ny;
        out[NORMAL + 2] = nz;
        out[D1] = dx;
        out[D1 + 1] = dy;
        out[D1 + 2] = dz;
        out[D2] = ny * dz - nz * dy;
        out[D2 + 1] = nz * dx - nx * dz;
        out[D2 + 2] = nx * dy - ny * dx;
    }
}
