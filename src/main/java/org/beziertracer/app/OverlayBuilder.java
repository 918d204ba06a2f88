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
 * so painting it takes bounded time.
 *
 * <p><b>Focus.</b> When the handles are dense — more than {@link #FOCUS_HANDLES} kept and each
 * standing for more than {@link #FOCUS_POINTS_PER_HANDLE} points on average, so that they would
 * cover the surface like a texture — only the handles of the patch under the mouse (the nearest
 * whose projected control net's box holds it) and of the patches with selected points are drawn
 * (and pickable), thinned the same way; this is what modellers do for dense meshes (Rhino,
 * Blender's edit mode show points for the selected or hovered element). Zoomed in, where each
 * handle is one point (shared borders give about two), every handle is drawn again. Stateless;
 * {@link #build} is a pure function.
 */
public final class OverlayBuilder {
    private OverlayBuilder() {}

    /** Handle radius in user-space pixels (device pixels at scale 1). */
    public static final double HANDLE_RADIUS = 3.5;
    /** Most handles drawn (a handle is one small image: about 5 µs each). */
    public static final int HANDLE_BUDGET = 4_000;
    /** Most control-polygon segments drawn (anti-aliased and dashed: the dearest shapes). */
    public static final long SEGMENT_BUDGET = 8_000;
    /** Handles kept above which, when they are also dense ({@link #FOCUS_POINTS_PER_HANDLE}), only the focus patches' are drawn. */
    public static final int FOCUS_HANDLES = 1_000;
    /** Points offered per kept handle above which the handles count as dense. */
    public static final double FOCUS_POINTS_PER_HANDLE = 3;
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
        // Per patch on screen: its net's pixel box and nearest depth, for refocusing without projecting again
        float[] boxes = grid != null ? new float[5 * extent.length] : null;
        long pointCount = 0;
        int underMouse = -1;
        double nearest = Double.POSITIVE_INFINITY;
        // Pass 1: every control point, once
        for (int p = 0; p < extent.length; p++) {
            BezierPatch patch = scene.patches().get(p);
            pointCount += patch.pointCount();
            extent[p] = projection.project(patch) ? (float) projection.extent(margin) : -1;
            if (boxes != null) {
                if (extent[p] >= 0) {
                    projection.box(boxes, 5 * p);
                } else {
                    boxes[5 * p] = Float.NaN; // off screen: never under the mouse
                }
            }
            if (extent[p] >= 0 && projection.covers(r.mouseX(), r.mouseY()) && projection.nearestDepth() < nearest) {
                nearest = projection.nearestDepth();
                underMouse = p;
            }
            if (grid != null && extent[p] >= 0) {
                for (int k = 0; k < patch.pointCount(); k++) {
                    grid.offer(projection.xy[2 * k], projection.xy[2 * k + 1], projection.depth[k], p, k);
                }
            }
        }
        HandleGrid.Kept kept = grid == null ? new HandleGrid(1, 1, 1, 0).collect(0) : grid.collect(HANDLE_BUDGET);
        boolean focused = grid != null && kept.count() > FOCUS_HANDLES
                && grid.offered() > FOCUS_POINTS_PER_HANDLE * kept.count();
        if (focused) {
            kept = focusHandles(r, projection, cell, margin, underMouse);
        }
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
                kept.thinned(), details.polygon(), details.curves(), pointCount, focused, focused ? underMouse : -1)
                .withFocusIndex(focused ? new OverlayGeometry.FocusIndex(r, boxes) : null);
    }

    /**
     * The overlay for {@code r}: when {@code previous} was focused and was built for the same scene,
     * view and switches (only the mouse or the selection moved), its polygon, curves and per-patch
     * boxes are reused and only the focus handles are found again — a scan of the boxes, O(patches),
     * instead of projecting every control point; otherwise {@link #build}.
     */
    public static OverlayGeometry build(OverlayGeometry previous, OverlayRequest r) {
        OverlayGeometry.FocusIndex index = previous == null ? null : previous.focusIndex();
        if (index == null || !index.sameView(r)) {
            return build(r);
        }
        float[] boxes = index.boxes();
        int underMouse = -1;
        double nearest = Double.POSITIVE_INFINITY;
        double x = r.mouseX(), y = r.mouseY();
        for (int p = 0, n = boxes.length / 5; p < n; p++) {
            int o = 5 * p;
            if (x >= boxes[o] && x <= boxes[o + 2] && y >= boxes[o + 1] && y <= boxes[o + 3] && boxes[o + 4] < nearest) {
                nearest = boxes[o + 4];
                underMouse = p;
            }
        }
        double cell = Math.ceil(2 * HANDLE_RADIUS * r.unit());
        HandleGrid.Kept kept = focusHandles(r, new PatchProjection(r.projector()), cell, 2 * cell, underMouse);
        return new OverlayGeometry(r.scene(), r.projector(), kept.xy(), kept.depth(), kept.patch(), kept.point(), kept.count(),
                kept.thinned(), previous.polygon(), previous.isoCurves(), previous.pointCount(), true, underMouse)
                .withFocusIndex(index);
    }

    /** The handles of the patch under the mouse and of the focus patches, thinned by density. */
    private static HandleGrid.Kept focusHandles(OverlayRequest r, PatchProjection projection, double cell, double margin,
                                                int underMouse) {
        ScreenProjector projector = r.projector();
        HandleGrid grid = new HandleGrid(projector.width(), projector.height(), cell, margin);
        int count = r.scene().patchCount();
        offer(r.scene(), underMouse, projection, margin, grid);
        for (int p : r.focusPatches()) {
            if (p != underMouse && p >= 0 && p < count) {
                offer(r.scene(), p, projection, margin, grid);
            }
        }
        return grid.collect(HANDLE_BUDGET);
    }

    private static void offer(Scene scene, int p, PatchProjection projection, double margin, HandleGrid grid) {
        if (p < 0) {
            return;
        }
        BezierPatch patch = scene.patches().get(p);
        if (projection.project(patch) && projection.extent(margin) >= 0) {
            for (int k = 0; k < patch.pointCount(); k++) {
                grid.offer(projection.xy[2 * k], projection.xy[2 * k + 1], projection.depth[k], p, k);
            }
        }
    }
}
