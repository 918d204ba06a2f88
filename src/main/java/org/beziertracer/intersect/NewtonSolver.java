package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * Ray–patch intersection by Newton iteration alone (memoir ch. I 3.3.3.3; Toth 1985; Martin et
 * al., "Practical ray tracing of trimmed NURBS surfaces", JGT 2000, who also start Newton from
 * the centre of a BVH leaf's parameter box).
 *
 * <p>Starts at the leaf's parameter-box centre, iterates on the parent patch in ray space and
 * rejects the result when it leaves the leaf's box (grown by a small margin, so that a root on
 * the border between two leaves is not lost) or does not converge. When the centre start fails,
 * the quarter points of the box are tried in turn and the first converged root kept. When every
 * start fails and the centre start left the box, one more start is made where it left, clamped
 * into the box: a root just inside the box's border (a patch border, where the box cannot grow)
 * that the first step overshoots is found that way. It still finds at most the roots those starts lead to: fast, but it can miss where a
 * leaf holds two roots or where every start is far from the root (and at singular points such
 * as the teapot's collapsed lid top, where the Jacobian vanishes). Kept for comparison with
 * clipping.
 */
final class NewtonSolver {
    private NewtonSolver() {}

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
        double escapeU = Double.NaN, escapeV = Double.NaN;
        ctx.escapeU = Double.NaN; // set only when the centre start leaves the box (not when it runs out of steps)
        for (int k = 0; k < STARTS.length; k += 2) {
            double u = u0 + STARTS[k] * (u1 - u0), v = v0 + STARTS[k + 1] * (v1 - v0);
            int r = RayPatchNewton.solve(ctx, tab, tab.parent[s], u, v, MAX_STEPS, uLo, uHi, vLo, vHi, tolerance);
            if (accept(ctx, r, tMin, tMax)) {
                return true;
            }
            if (k == 0 && !Double.isNaN(ctx.escapeU)) {
                escapeU = Math.min(uHi, Math.max(uLo, ctx.escapeU));
                escapeV = Math.min(vHi, Math.max(vLo, ctx.escapeV));
            }
        }
        return !Double.isNaN(escapeU) && accept(ctx, RayPatchNewton.solve(ctx, tab, tab.parent[s], escapeU, escapeV,
                MAX_STEPS, uLo, uHi, vLo, vHi, tolerance), tMin, tMax);
    }

    /** A converged root in {@code (tMin, tMax)}, its parameters clamped to the patch. */
    private static boolean accept(TraceContext ctx, int result, double tMin, double tMax) {
        if (result == RayPatchNewton.CONVERGED && ctx.rootT > tMin && ctx.rootT < tMax) {
            ctx.rootU = Math.min(1, Math.max(0, ctx.rootU));
            ctx.rootV = Math.min(1, Math.max(0, ctx.rootV));
            return true;
        }
        return false;
    }
}
