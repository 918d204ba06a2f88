package org.beziertracer.app;

import java.util.List;

import org.beziertracer.model.Scene;

/**
 * The overlay of one scene in one view, ready to draw: a <b>bounded</b> number of control-point
 * handles, control-polygon and iso-curve polylines in picture pixels (device pixels), the
 * selected points' positions, and the model's point count. Made by {@link OverlayBuilder} off the UI
 * thread; immutable, so the painter draws it while the next one is built.
 *
 * <h2>Layout</h2>
 * Handle {@code k}: {@code handleXY[2k], handleXY[2k+1]}, depth {@code handleDepth[k]}, point
 * {@code P_ij} of patch {@code handlePatch[k]} with {@code handlePoint[k] = j·(n+1) + i}.
 * Each control-polygon row or column and each iso-curve is a polyline {@code x0, y0, x1, y1, …}.
 */
public final class OverlayGeometry {

    /** Nothing to draw (before the first build, and while a newly opened model is prepared). */
    public static final OverlayGeometry EMPTY = new OverlayGeometry(null, null, new float[0], new float[0], new int[0],
            new int[0], 0, false, List.of(), List.of(), 0, false, -1);

    private final Scene scene;
    private final ScreenProjector projector;
    private final float[] handleXY;
    private final float[] handleDepth;
    private final int[] handlePatch;
    private final int[] handlePoint;
    private final int handleCount;
    private final boolean thinned;
    private final List<float[]> polygon;
    private final List<float[]> isoCurves;
    private final long pointCount;
    private final boolean focused;
    private final int underMouse;
    private FocusIndex focusIndex;

    /**
     * What a focused overlay keeps to be focused again cheaply: the request it was built for and,
     * per patch, its control net's pixel box and nearest depth ({@code minX, minY, maxX, maxY,
     * depth}; NaN for a patch off screen).
     */
    record FocusIndex(OverlayRequest built, float[] boxes) {
        /** True when {@code r} differs from the request built only in the mouse and the selection. */
        boolean sameView(OverlayRequest r) {
            return r.scene() == built.scene() && r.projector().camera().equals(built.projector().camera())
                    && r.projector().width() == built.projector().width()
                    && r.projector().height() == built.projector().height() && r.points() == built.points()
                    && r.polygon() == built.polygon() && r.isoCurves() == built.isoCurves() && r.unit() == built.unit();
        }
    }

    /** This geometry with {@code index} (set once, by the builder, before it is published). */
    OverlayGeometry withFocusIndex(FocusIndex index) {
        focusIndex = index;
        return this;
    }

    /** The index to refocus from, or null. */
    FocusIndex focusIndex() { return focusIndex; }

    OverlayGeometry(Scene scene, ScreenProjector projector, float[] handleXY, float[] handleDepth, int[] handlePatch,
                    int[] handlePoint, int handleCount, boolean thinned, List<float[]> polygon,
                    List<float[]> isoCurves, long pointCount, boolean focused, int underMouse) {
        this.scene = scene;
        this.projector = projector;
        this.handleXY = handleXY;
        this.handleDepth = handleDepth;
        this.handlePatch = handlePatch;
        this.handlePoint = handlePoint;
        this.handleCount = handleCount;
        this.thinned = thinned;
        this.polygon = List.copyOf(polygon);
        this.isoCurves = List.copyOf(isoCurves);
        this.pointCount = pointCount;
        this.focused = focused;
        this.underMouse = underMouse;
    }

    /**
     * True when the handles were too dense to show them all and only those of the patch under the
     * mouse and of the selected patches are drawn ({@link OverlayBuilder}).
     */
    public boolean focused() { return focused; }

    /** The patch whose handles the mouse brought up (nearest the eye under it), or −1. */
    public int underMouse() { return underMouse; }

    /** The scene this was built for (null for {@link #EMPTY}). */
    public Scene scene() { return scene; }

    /** The view this was built for (null for {@link #EMPTY}). */
    public ScreenProjector projector() { return projector; }

    public int handleCount() { return handleCount; }

    /** Handle {@code k}, {@code 0 ≤ k < handleCount()}. */
    public Handle handle(int k) {
        int patch = handlePatch[k];
        int n = scene.patches().get(patch).degreeU();
        return new Handle(new PointRef(patch, handlePoint[k] % (n + 1), handlePoint[k] / (n + 1)),
                handleXY[2 * k], handleXY[2 * k + 1], handleDepth[k]);
    }

    public float handleX(int k) { return handleXY[2 * k]; }

    public float handleY(int k) { return handleXY[2 * k + 1]; }

    /** True when some control points on screen are not drawn (too dense to tell apart at this zoom). */
    public boolean thinned() { return thinned; }

    /** The control polygons' rows and columns as polylines (unmodifiable; do not change the arrays). */
    public List<float[]> polygon() { return polygon; }

    /** Segments of the control polygons drawn. */
    public int segmentCount() {
        int n = 0;
        for (float[] line : polygon) {
            n += line.length / 2 - 1;
        }
        return n;
    }

    /** The iso-curves as polylines (unmodifiable; do not change the arrays). */
    public List<float[]> isoCurves() { return isoCurves; }

    /** Control points of the whole model (drawn or not). */
    public long pointCount() { return pointCount; }

    /**
     * The drawn handle nearest to pixel {@code (x, y)} within {@code radius} pixels, the nearer to
     * the eye on a tie; null when none. Costs one pass over the drawn handles (a bounded number).
     */
    public Handle pick(double x, double y, double radius) {
        int best = -1;
        double bestD2 = radius * radius;
        double bestDepth = Double.POSITIVE_INFINITY;
        for (int k = 0; k < handleCount; k++) {
            double dx = handleXY[2 * k] - x, dy = handleXY[2 * k + 1] - y;
            double d2 = dx * dx + dy * dy;
            boolean nearer = d2 < bestD2 - 1e-9 || (d2 <= bestD2 + 1e-9 && handleDepth[k] < bestDepth);
            if (d2 <= radius * radius && nearer) {
                best = k;
                bestD2 = d2;
                bestDepth = handleDepth[k];
            }
        }
        return best < 0 ? null : handle(best);
    }
}
