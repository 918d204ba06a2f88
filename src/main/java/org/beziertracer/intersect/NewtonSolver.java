package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * Ray–patch intersection by Newton iteration alone (memoir ch. I 3.3.3.3; Toth 1985; Martin et
 * al., "Practical ray tracing of trimmed NURBS surfaces", JGT 2000, who also start Newton from
 * the centre of a BVH leaf's parameter box).
 *
 * <p>Starts at the leaf's parameter-box centre, iterates on the parent patch in ray space and
 * rejects the result when it leaves the leaf's box (grown by a small margin, so that a root on
 * the border between two leaves is not lost) or does not converge. It finds at most one root
 * per leaf: fast, but it can miss where a leaf holds two roots or where the start is far from
 * the root. Kept for comparison with clipping.
 */
final class NewtonSolver {
    private NewtonSolver() {}

    static final int MAX_STEPS = 12;
    /** Margin around the leaf box, as a fraction of its width. */
    static final double MARGIN = 0.02;

    static boolean intersect(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tMax,
                             double tolerance) {
        double u0 = tab.boxes[4 * s], u1 = tab.boxes[4 * s + 1];
        double v0 = tab.boxes[4 * s + 2], v1 = tab.boxes[4 * s + 3];
        double mu = MARGIN * (u1 - u0), mv = MARGIN * (v1 - v0);
        int r = RayPatchNewton.solve(ctx, tab, tab.parent[s], 0.5 * (u0 + u1), 0.5 * (v0 + v1), MAX_STEPS,
                Math.max(-1e-9, u0 - mu), Math.min(1 + 1e-9, u1 + mu),
                Math.max(-1e-9, v0 - mv), Math.min(1 + 1e-9, v1 + mv), tolerance);
        if (r != RayPatchNewton.CONVERGED || !(ctx.rootT > tMin && ctx.rootT < tMax)) {
            return false;
        }
        ctx.rootU = Math.min(1, Math.max(0, ctx.rootU));
        ctx.rootV = Math.min(1, Math.max(0, ctx.rootV));
        return true;
    }
}
