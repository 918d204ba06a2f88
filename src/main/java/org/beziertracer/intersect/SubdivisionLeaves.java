package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;

/** Sub-patch leaves solved by recursive subdivision ({@link SubdivisionSolver}): approximate. */
final class SubdivisionLeaves extends PatchLeaves {

    SubdivisionLeaves(SubPatchTable table, double tolerance) {
        super(table, tolerance);
    }

    /** Nothing beside the table ({@link Method#solverBytes}): the solver reads the sub-patch nets alone. */
    static long estimateBytes(List<BezierPatch> patches, long leaves) {
        return 0;
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
