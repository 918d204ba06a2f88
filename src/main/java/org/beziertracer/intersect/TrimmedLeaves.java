package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.geometry.TrimCurves;

/**
 * Sub-patch leaves of a scene with trimmed patches: the scene's solver ({@code inner}), with hits
 * counting only inside the trim region. A root the solver finds in a leaf that needs the test
 * ({@link SubPatchTable#trimTest}; leaves wholly inside do not, leaves wholly outside are not in
 * the table at all) is tested on the exact trim curves ({@link TrimCurves#contains}, in the
 * surface's parameters). A rejected root makes the solver search the same leaf again beyond it,
 * so a farther root of the leaf (a ray through a hole that meets the surface again) is still
 * found; the retries are capped. The solvers themselves know nothing of trimming, and a scene
 * without trims never gets these leaves.
 *
 * <p>Immutable; shared by render threads, each with its own {@link TraceContext}.
 */
final class TrimmedLeaves extends PatchLeaves {

    /** Roots rejected per leaf before giving up. */
    static final int MAX_REJECTED = 8;
    /** A search after a rejected root starts this far beyond it, relative to its t. */
    static final double BEYOND = 1e-10;

    private final PatchLeaves inner;

    TrimmedLeaves(PatchLeaves inner) {
        super(inner.table, inner.tolerance);
        this.inner = inner;
    }

    /** {@code leaves} themselves when their table has no trimmed patch, else wrapped. */
    static PatchLeaves ifTrimmed(PatchLeaves leaves) {
        return leaves.table.trimTest == null || leaves instanceof TrimmedLeaves ? leaves : new TrimmedLeaves(leaves);
    }

    /**
     * A leaf wholly inside the trim region needs no test for a root in its own parameter box; but
     * a solver may return a root beyond it (Newton accepts roots in the leaf's overlapped domain,
     * {@link NewtonSolver#OVERLAP}), and there the trim curves decide as for any other leaf.
     */
    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        int k = table.parent[s];
        TrimCurves trim = table.patchTrim[k];
        if (trim == null) {
            return inner.solve(ctx, s, tMin, tMax);
        }
        double lo = tMin;
        for (int attempt = 0; attempt <= MAX_REJECTED; attempt++) {
            if (!inner.solve(ctx, s, lo, tMax)) {
                return false;
            }
            if (!table.trimTest[s] && inLeafBox(table.boxes, s, ctx.rootU, ctx.rootV)
                    || inside(table.patchDomain, k, trim, ctx.rootU, ctx.rootV, ctx.trimScratch)) {
                return true;
            }
            lo = ctx.rootT + BEYOND * Math.max(Math.abs(ctx.rootT), Double.MIN_NORMAL);
        }
        return false;
    }

    /** True when {@code (u, v)} lies in leaf {@code s}'s parameter box (its parent patch's parameters). */
    static boolean inLeafBox(float[] boxes, int s, double u, double v) {
        return u >= boxes[4 * s] && u <= boxes[4 * s + 1] && v >= boxes[4 * s + 2] && v <= boxes[4 * s + 3];
    }

    /**
     * True when patch {@code k}'s own parameters {@code (s,t)} lie inside its trim region, decided
     * as for a point just inside the patch: {@code (s,t)} is clamped to {@code [0,1]²} (a solver
     * may stop a rounding error beyond it), a surface parameter that maps onto or past the
     * domain's {@code u1} or {@code v1} is that edge exactly, and a point there that lies on a trim
     * curve is taken a step toward the patch ({@link TrimCurves#contains(double, double, boolean,
     * boolean, double[])}). So a loop along the surface's border trims nothing, and of two pieces
     * that share an edge with a trim curve on it the one on the curve's inner side keeps the hit.
     */
    static boolean inside(double[] domain, int k, TrimCurves trim, double s, double t, double[] scratch) {
        double u1 = domain[4 * k + 1], v1 = domain[4 * k + 3];
        double u = SurfaceParameters.u(domain, k, Math.min(Math.max(s, 0), 1));
        double v = SurfaceParameters.v(domain, k, Math.min(Math.max(t, 0), 1));
        boolean uBefore = u >= u1, vBefore = v >= v1;
        return trim.contains(uBefore ? u1 : u, vBefore ? v1 : v, uBefore, vBefore, scratch);
    }

    @Override
    PatchLeaves with(SubPatchTable edited, double editedTolerance) {
        return ifTrimmed(inner.with(edited, editedTolerance));
    }

    @Override
    PatchLeaves with(SubPatchTable edited, double editedTolerance, int[] editedPatches) {
        return ifTrimmed(inner.with(edited, editedTolerance, editedPatches));
    }
}
