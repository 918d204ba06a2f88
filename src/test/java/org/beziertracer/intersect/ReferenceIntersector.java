package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;

/**
 * A slow, independent reference for tests: split the patch into a dense G×G grid of cells with
 * de Casteljau, and in every cell whose control box the ray meets, run a 3×3 world-space Newton
 * iteration on {@code S(u,v) − o − t d = 0} from the cell centre. Returns the nearest converged
 * root in (tMin, tMax) inside its cell (grown by a margin), as {t, u, v}, or null.
 */
final class ReferenceIntersector {
    private ReferenceIntersector() {}

    static double[] nearest(BezierPatch p, double ox, double oy, double oz, double dx, double dy, double dz,
                            double tMin, double tMax, int grid) {
        int n = p.degreeU(), m = p.degreeV();
        double[] net = p.copyNet();
        double[] cell = new double[net.length];
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        double[] e = new double[9];
        double[] best = null;
        for (int a = 0; a < grid; a++) {
            for (int b = 0; b < grid; b++) {
                double u0 = (double) a / grid, u1 = (double) (a + 1) / grid;
                double v0 = (double) b / grid, v1 = (double) (b + 1) / grid;
                DeCasteljau.subPatch(net, 0, n, m, 3, u0, u1, v0, v1, cell, 0);
                if (!rayMeetsBox(cell, ox, oy, oz, dx, dy, dz, tMin, tMax)) {
                    continue;
                }
                double[] root = cellRoot(net, n, m, u0, u1, v0, v1, ox, oy, oz, dx, dy, dz, tMin, tMax, e, scratch);
                if (root != null && (best == null || root[0] < best[0])) {
                    best = root;
                }
            }
        }
        return best;
    }

    /**
     * The 3×3 world-space Newton iteration from the centre of cell {@code [u0,u1]×[v0,v1]} of
     * the degree {@code n}×{@code m} net: the converged root {t, u, v} when it lies in the cell
     * grown by 1 % (clamped to the patch) and in (tMin, tMax), else null.
     */
    static double[] cellRoot(double[] net, int n, int m, double u0, double u1, double v0, double v1,
                             double ox, double oy, double oz, double dx, double dy, double dz,
                             double tMin, double tMax, double[] e, double[] scratch) {
        double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1), t = 0;
        boolean ok = false;
        for (int it = 0; it < 40; it++) {
            DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, e, scratch);
            double fx = e[0] - ox - t * dx, fy = e[1] - oy - t * dy, fz = e[2] - oz - t * dz;
            // J = [Su Sv -d]
            double[][] j = {{e[3], e[6], -dx}, {e[4], e[7], -dy}, {e[5], e[8], -dz}};
            double[] step = solve3(j, new double[] {-fx, -fy, -fz});
            if (step == null) {
                break;
            }
            u += step[0];
            v += step[1];
            t += step[2];
            if (Math.abs(step[0]) < 1e-15 && Math.abs(step[1]) < 1e-15) {
                ok = true;
                break;
            }
            if (Math.abs(step[0]) < 1e-12 && Math.abs(step[1]) < 1e-12) {
                // Converged to rounding (Newton squares the error, so the next step is noise):
                // the remaining steps polish; near a root at u ~ 0.5 they may dither just above 1e-15
                ok = true;
            }
        }
        double mu = 0.01 * (u1 - u0);
        if (ok && u >= Math.max(0, u0 - mu) - 1e-12 && u <= Math.min(1, u1 + mu) + 1e-12
                && v >= Math.max(0, v0 - mu) - 1e-12 && v <= Math.min(1, v1 + mu) + 1e-12
                && t > tMin && t < tMax) {
            return new double[] {t, u, v};
        }
        return null;
    }

    static boolean rayMeetsBox(double[] net, double ox, double oy, double oz, double dx, double dy, double dz,
                               double tMin, double tMax) {
        double lo = tMin, hi = tMax;
        double[] o = {ox, oy, oz}, d = {dx, dy, dz};
        for (int axis = 0; axis < 3; axis++) {
            double mn = Double.POSITIVE_INFINITY, mx = Double.NEGATIVE_INFINITY;
            for (int k = axis; k < net.length; k += 3) {
                mn = Math.min(mn, net[k]);
                mx = Math.max(mx, net[k]);
            }
            double pad = 1e-9 * (1 + Math.abs(mn) + Math.abs(mx));
            mn -= pad;
            mx += pad;
            if (d[axis] == 0) {
                if (o[axis] < mn || o[axis] > mx) return false;
                continue;
            }
            double t0 = (mn - o[axis]) / d[axis], t1 = (mx - o[axis]) / d[axis];
            lo = Math.max(lo, Math.min(t0, t1));
            hi = Math.min(hi, Math.max(t0, t1));
        }
        return lo <= hi;
    }

    /** Gaussian elimination with partial pivoting; null when singular. */
    static double[] solve3(double[][] a, double[] b) {
        int n = 3;
        for (int c = 0; c < n; c++) {
            int piv = c;
            for (int r = c + 1; r < n; r++) if (Math.abs(a[r][c]) > Math.abs(a[piv][c])) piv = r;
            if (Math.abs(a[piv][c]) < 1e-300) return null;
            double[] tr = a[c]; a[c] = a[piv]; a[piv] = tr;
            double tb = b[c]; b[c] = b[piv]; b[piv] = tb;
            for (int r = c + 1; r < n; r++) {
                double f = a[r][c] / a[c][c];
                for (int k = c; k < n; k++) a[r][k] -= f * a[c][k];
                b[r] -= f * b[c];
            }
        }
        double[] x = new double[n];
        for (int r = n - 1; r >= 0; r--) {
            double s = b[r];
            for (int k = r + 1; k < n; k++) s -= a[r][k] * x[k];
            x[r] = s / a[r][r];
        }
        return x;
    }
}
