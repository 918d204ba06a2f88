package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;

/**
 * Sub-patch leaves solved by Newton iteration alone ({@link NewtonSolver}), over the Newton
 * method's own leaves ({@link NewtonRefinement}), with the per-leaf records the solver reads
 * ({@link NewtonLeafRecords}: {@value NewtonLeafRecords#STRIDE} floats a leaf).
 */
final class NewtonLeaves extends PatchLeaves {

    private final float[] records;

    NewtonLeaves(SubPatchTable table, double tolerance) {
        this(table, tolerance, NewtonLeafRecords.build(table));
    }

    private NewtonLeaves(SubPatchTable table, double tolerance, float[] records) {
        super(table, tolerance);
        this.records = records;
    }

    /** About the bytes these leaves keep beside the table ({@link Method#solverBytes}): every leaf's record. */
    static long estimateBytes(List<BezierPatch> patches, long leaves) {
        return 4L * NewtonLeafRecords.STRIDE * leaves;
    }

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        return NewtonSolver.intersect(ctx, table, records, s, tMin, tMax, tolerance);
    }

    @Override
    NewtonLeaves with(SubPatchTable edited, double editedTolerance) {
        return new NewtonLeaves(edited, editedTolerance);
    }

    /** The records of the patches not edited are copied, not recomputed. */
    @Override
    NewtonLeaves with(SubPatchTable edited, double editedTolerance, int[] editedPatches) {
        return new NewtonLeaves(edited, editedTolerance, NewtonLeafRecords.edited(records, table, edited, editedPatches));
    }

    @Override
    long solverBytes() { return HeapBytes.of(records); }
}
