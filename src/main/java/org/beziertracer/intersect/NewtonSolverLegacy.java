package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.geometry.DeCasteljau;

/**
 * Ray–patch intersection by Newton iteration alone (memoir ch. I 3.3.3.3; Toth 1985; Martin et
 * al., "Practical ray tracing of trimmed NURBS surfaces", JGT 2000, who also start Newton from
 * the centre of a BVH leaf's parameter box).
 *
 * <p>Starts at the leaf's parameter-box centre, iterates on the parent patch in ray space and
 * rejects the result when it leaves the leaf's box (grown by a small margin, so that a root on
 * the border between two leaves is not lost) or does not converge. When the centre start fails,
 * the quarter points of the box are tried in turn and the first converged root kept. It still finds at most the roots those starts lead to: fast, but it can miss where a
 * leaf holds two roots or where every start is far from the root (and at singular points such
 * as the teapot's collapsed lid top, where the Jacobian vanishes). Kept for comparison with
 * clipping.
 */
final class NewtonSolverLegacy {
    private NewtonSolverLegacy() {}

    static final int MAX_STEPS = 12;
    /** Margin around the leaf box, as a fraction of its width. */
    static final double MARGIN = 0.02;
    /** Start points as fractions of the leaf box: the centre first, then the quarter points. */
    private static final double[] STARTS = {0.5, 0.5, 0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75};

    static boolean intersect(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tMax,
                             double tolerance) {
        double u0 = tab.boxes[4 * s], u1 = tab.boxes[4 * s + 1];
        double v0 = tab.boxes[4 * s + 2], v1 = tab.boxes[4 * s + 3];
        double mu = MARGIN * (u1 - u0), mv = MARGIN * (v1 - v0);
        double uLo = Math.max(-1e-9, u0 - mu), uHi = Math.min(1 + 1e-9, u1 + mu);
        double vLo = Math.max(-1e-9, v0 - mv), vHi = Math.min(1 + 1e-9, v1 + mv);
        for (int k = 0; k < STARTS.length; k += 2) {
            double u = u0 + STARTS[k] * (u1 - u0), v = v0 + STARTS[k + 1] * (v1 - v0);
            int r = solveCounted(ctx, tab, tab.parent[s], u, v, MAX_STEPS, uLo, uHi, vLo, vHi, tolerance);
            if (r == RayPatchNewton.CONVERGED && ctx.rootT > tMin && ctx.rootT < tMax) {
                ctx.rootU = Math.min(1, Math.max(0, ctx.rootU));
                ctx.rootV = Math.min(1, Math.max(0, ctx.rootV));
                return true;
            }
        }
        return false;
    }
    static int solveCounted(TraceContext ctx, SubPatchTable table, int k, double u, double v, int maxSteps,
                     double uLo, double uHi, double vLo, double vHi, double tolerance) {
        double[] net = table.patchNets;
        int off = table.patchNetOffset[k], n = table.patchDegreeU[k], m = table.patchDegreeV[k];
        double[] e = ctx.eval;
        ctx.evalPatch = k; // from here on ctx.eval holds S, Su, Sv of patch k at (ctx.evalU, ctx.evalV)
        int result = RayPatchNewton.DIVERGED;
        for (int step = 0; step <= maxSteps; step++) {
            NewtonSolver.EVALS++; DeCasteljau.evaluateWithDerivatives(net, off, n, m, u, v, e, ctx.scratch);
            double qx = e[0] - ctx.ox, qy = e[1] - ctx.oy, qz = e[2] - ctx.oz;
            double f1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
            double f2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
            ctx.rootU = u;
            ctx.rootV = v;
            ctx.evalU = u;
            ctx.evalV = v;
            ctx.rootT = (ctx.n3x * qx + ctx.n3y * qy + ctx.n3z * qz) * ctx.invLength;
            if (Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance && step > 0) {
                return RayPatchNewton.CONVERGED;
            }
            if (step == maxSteps) {
                break;
            }
            double a = ctx.n1x * e[3] + ctx.n1y * e[4] + ctx.n1z * e[5];
            double b = ctx.n1x * e[6] + ctx.n1y * e[7] + ctx.n1z * e[8];
            double c = ctx.n2x * e[3] + ctx.n2y * e[4] + ctx.n2z * e[5];
            double d = ctx.n2x * e[6] + ctx.n2y * e[7] + ctx.n2z * e[8];
            double det = a * d - b * c;
            double scale = Math.abs(a * d) + Math.abs(b * c);
            if (!(Math.abs(det) > 1e-300) || Math.abs(det) <= 1e-14 * scale) {
                return Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance ? RayPatchNewton.CONVERGED : RayPatchNewton.SINGULAR;
            }
            double du = (b * f2 - d * f1) / det;
            double dv = (c * f1 - a * f2) / det;
            if (Math.abs(du) < 1e-15 && Math.abs(dv) < 1e-15
                    && Math.max(Math.abs(f1), Math.abs(f2)) <= 1e-3 * tolerance) {
                // Already a root to rounding (as in refine): the step could not move the point
                // by more than rounding, so the evaluation here stands and none is repeated
                return RayPatchNewton.CONVERGED;
            }
            u += du;
            v += dv;
            if (!(u >= uLo && u <= uHi && v >= vLo && v <= vHi)) {
                return RayPatchNewton.DIVERGED;
            }
            if (Math.abs(du) < 1e-15 && Math.abs(dv) < 1e-15) {
                result = RayPatchNewton.CONVERGED;
                // one more evaluation at the final iterate for t
                NewtonSolver.EVALS++; DeCasteljau.evaluateWithDerivatives(net, off, n, m, u, v, e, ctx.scratch);
                qx = e[0] - ctx.ox; qy = e[1] - ctx.oy; qz = e[2] - ctx.oz;
                f1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
                f2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
                ctx.rootU = u;
                ctx.rootV = v;
                ctx.evalU = u;
                ctx.evalV = v;
                ctx.rootT = (ctx.n3x * qx + ctx.n3y * qy + ctx.n3z * qz) * ctx.invLength;
                return Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance ? result : RayPatchNewton.DIVERGED;
            }
        }
        return result;
    }

}
