package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/** Sub-patch leaves solved by Bézier clipping ({@link BezierClipper}): exact, the default. */
final class ClippingLeaves extends PatchLeaves {

    ClippingLeaves(SubPatchTable table, double tolerance) {
        super(table, tolerance);
    }

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        return BezierClipper.intersect(ctx, table, s, tMin, tMax, tolerance);
    }

    @Override
    ClippingLeaves with(SubPatchTable edited, double editedTolerance) {
        return new ClippingLeaves(edited, editedTolerance);
    }
}
