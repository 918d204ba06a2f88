package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/** Sub-patch leaves solved by Newton iteration alone ({@link NewtonSolver}): fast, may miss roots. */
final class NewtonLeaves extends PatchLeaves {

    NewtonLeaves(SubPatchTable table, double tolerance) {
        super(table, tolerance);
    }

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        return NewtonSolver.intersect(ctx, table, s, tMin, tMax, tolerance);
    }

    @Override
    NewtonLeaves with(SubPatchTable edited, double editedTolerance) {
        return new NewtonLeaves(edited, editedTolerance);
    }
}
