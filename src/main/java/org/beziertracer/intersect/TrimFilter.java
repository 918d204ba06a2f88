package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.geometry.TrimCurves;

/**
 * Hits on trimmed patches count only inside the trim region: a root a solver finds in a leaf
 * that needs the test ({@link SubPatchTable#trimTest}; leaves wholly inside do not, leaves wholly
 * outside are not in the table) is tested on the exact trim curves ({@link TrimCurves#contains}, in
 * the surface's parameters). A rejected root makes the solver search the same leaf again beyond
 * it, so a farther root of the leaf (a ray through a hole that meets the surface again) is still
 * found; the number of retries is capped. The solvers themselves know nothing of trimming.
 */
final class TrimFilter {
    private TrimFilter() {}

    /** Roots rejected per leaf before giving up. */
    static final int MAX_REJECTED = 8;
    /** A search after a rejected root starts this far beyond it, relative to its t. */
    static final double BEYOND = 1e-10;

    /** Root solving of one leaf, as {@link SceneIntersector} runs it for an untrimmed leaf. */
    @FunctionalInterface
    interface Solver {
        boolean solve(TraceContext ctx, int s, double tMin, double tMax);
    }

    /**
     * The nearest root of leaf {@code s} in {@code (tMin, tMax)} inside the trim region, into
     * {@code ctx.root*} as any solver leaves it; true when there is one.
     */
    static boolean solve(Solver solver, SubPatchTable tab, TraceContext ctx, int s, double tMin, double tMax) {
        int k = tab.parent[s];
        TrimCurves trim = tab.patchTrim[k];
        double lo = tMin;
        for (int attempt = 0; attempt <= MAX_REJECTED; attempt++) {
            if (!solver.solve(ctx, s, lo, tMax)) {
                return false;
            }
            if (inside(tab, ctx, k, trim, ctx.rootU, ctx.rootV)) {
                return true;
            }
            lo = ctx.rootT + BEYOND * Math.max(Math.abs(ctx.rootT), Double.MIN_NORMAL);
        }
        return false;
    }

    /** True when patch {@code k}'s own parameters {@code (s,t)} are inside its trim region. */
    static boolean inside(SubPatchTable tab, TraceContext ctx, int k, TrimCurves trim, double s, double t) {
        return trim.contains(SurfaceParameters.u(tab, k, s), SurfaceParameters.v(tab, k, t), ctx.trimScratch);
    }
}
