package org.beziertracer.app;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Builds the {@link OverlayGeometry} of a request, off the UI thread: one pass projects every
 * control point (the only work that grows with the model), thins the handles by screen-space
 * density ({@link HandleGrid}) and measures each patch on screen; a second pass draws the
 * control polygon and iso-curves of the patches that fit the budgets ({@link ExtentBudget}),
 * biggest first. Whatever the model's size, the result holds at most {@link #HANDLE_BUDGET}
 * handles, {@link #SEGMENT_BUDGET} polygon segments and {@link #CURVE_POINT_BUDGET} curve points,
 * so painting it takes bounded time. Stateless; {@link #build} is a pure function.
 */
public final class OverlayBuilder {
    private OverlayBuilder() {}

    /** Handle radius in user-space pixels (device pixels at scale 1). */
    public static final double HANDLE_RADIUS = 3.5;
    /** Most handles drawn (a handle is one small image: about 5 µs each). */
    public static final int HANDLE_BUDGET = 4_000;
    /** Most control-polygon segments drawn (anti-aliased and dashed: the dearest shapes). */
    public static final long SEGMENT_BUDGET = 8_000;
    /** Most iso-curve polyline points drawn. */
    public static final long CURVE_POINT_BUDGET = 100_000;

    public static OverlayGeometry build(OverlayRequest r) {
        Scene scene = r.scene();
        ScreenProjector projector = r.projector();
        double cell = Math.ceil(2 * HANDLE_RADIUS * r.unit());
        double margin = 2 * cell;
        HandleGrid grid = r.points() ? new HandleGrid(projector.width(), projector.height(), cell, margin) : null;
        PatchProjection projection = new PatchProjection(projector);
        float[] extent = new float[scene.patchCount()];
        long pointCount = 0;
        // Pass 1: every control point, once
        for (int p = 0; p < extent.length; p++) {
            BezierPatch patch = scene.patches().get(p);
            pointCount += patch.pointCount();
            extent[p] = projection.project(patch) ? (float) projection.extent(margin) : -1;
            if (grid != null && extent[p] >= 0) {
                for (int k = 0; k < patch.pointCount(); k++) {
                    grid.offer(projection.xy[2 * k], projection.xy[2 * k + 1], projection.depth[k], p, k);
                }
            }
        }
        HandleGrid.Kept kept = grid == null ? new HandleGrid(1, 1, 1, 0).collect(0) : grid.collect(HANDLE_BUDGET);
        // Pass 2: detail for the patches that fit the budgets
        OverlayDetails details = new OverlayDetails(projection);
        double polygonFrom = r.polygon()
                ? ExtentBudget.threshold(extent, p -> OverlayDetails.polygonCost(scene.patches().get(p)), SEGMENT_BUDGET)
                : Double.POSITIVE_INFINITY;
        double curvesFrom = r.isoCurves() > 0
                ? ExtentBudget.threshold(extent, p -> OverlayDetails.curveCost(OverlayDetails.subdivisions(r.isoCurves(),
                        extent[p])), CURVE_POINT_BUDGET)
                : Double.POSITIVE_INFINITY;
        details.add(scene, extent, polygonFrom, curvesFrom, r.isoCurves());
        return new OverlayGeometry(scene, projector, kept.xy(), kept.depth(), kept.patch(), kept.point(), kept.count(),
                kept.thinned(), details.polygon(), details.curves(), pointCount);
    }
}
