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

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        if (!table.trimTest[s]) {
            return inner.solve(ctx, s, tMin, tMax);
        }
        int k = table.parent[s];
        TrimCurves trim = table.patchTrim[k];
        double lo = tMin;
        for (int attempt = 0; attempt <= MAX_REJECTED; attempt++) {
            if (!inner.solve(ctx, s, lo, tMax)) {
                return false;
            }
            if (inside(table.patchDomain, k, trim, ctx.rootU, ctx.rootV, ctx.trimScratch)) {
                return true;
            }
            lo = ctx.rootT + BEYOND * Math.max(Math.abs(ctx.rootT), Double.MIN_NORMAL);
        }
        return false;
    }

    /** True when patch {@code k}'s own parameters {@code (s,t)} lie inside its trim region. */
    static boolean inside(double[] domain, int k, TrimCurves trim, double s, double t, double[] scratch) {
        return trim.contains(SurfaceParameters.u(domain, k, s), SurfaceParameters.v(domain, k, t), scratch);
    }

    @Override
    PatchLeaves with(SubPatchTable edited, double editedTolerance) {
        return ifTrimmed(inner.with(edited, editedTolerance));
    }
}
