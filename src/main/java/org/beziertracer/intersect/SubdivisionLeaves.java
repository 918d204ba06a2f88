package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/** Sub-patch leaves solved by recursive subdivision ({@link SubdivisionSolver}): approximate. */
final class SubdivisionLeaves extends PatchLeaves {

    SubdivisionLeaves(SubPatchTable table, double tolerance) {
        super(table, tolerance);
    }

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        return SubdivisionSolver.intersect(ctx, table, s, tMin, tMax, tolerance);
    }

    @Override
    SubdivisionLeaves with(SubPatchTable edited, double editedTolerance) {
        return new SubdivisionLeaves(edited, editedTolerance);
    }
}
