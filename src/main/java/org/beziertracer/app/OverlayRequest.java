package org.beziertracer.app;

import org.beziertracer.model.Scene;

/**
 * What the overlay shows, for {@link OverlayBuilder}: immutable, made on the UI thread in constant
 * time, built into an {@link OverlayGeometry} off it.
 *
 * @param scene          the scene whose control nets are drawn
 * @param projector      the view onto the picture
 * @param points         control-point handles (drawn and pickable)
 * @param polygon        the control polygon
 * @param isoCurves      subdivisions per direction of the projected iso-curves, 0 for none
 * @param unit           device pixels per user-space pixel: handles keep their size under HiDPI
 * @param mouseX         where the mouse is (picture pixels), NaN when it is not over the picture
 * @param mouseY         likewise
 * @param focusPatches   the patches whose handles stay drawn when the handles are dense (those
 *                       with selected points), ascending; not copied (do not change it)
 */
public record OverlayRequest(Scene scene, ScreenProjector projector, boolean points, boolean polygon, int isoCurves,
                             double unit, double mouseX, double mouseY, int[] focusPatches) {

    private static final int[] NONE = new int[0];

    /** A request with no mouse over the picture and nothing selected. */
    public OverlayRequest(Scene scene, ScreenProjector projector, boolean points, boolean polygon, int isoCurves,
                          double unit) {
        this(scene, projector, points, polygon, isoCurves, unit, Double.NaN, Double.NaN, NONE);
    }

    /** The request for the current state of the app, without the mouse or the selection. */
    static OverlayRequest of(Scene scene, ScreenProjector projector, Settings s, double unit) {
        return of(scene, projector, s, unit, Double.NaN, Double.NaN, NONE);
    }

    /** The request for the current state of the app: the mouse at {@code (x, y)}, {@code focus} the selected patches. */
    static OverlayRequest of(Scene scene, ScreenProjector projector, Settings s, double unit, double x, double y,
                             int[] focus) {
        return new OverlayRequest(scene, projector, s.pointsShown(), s.polygonShown(),
                s.isoCurvesShown() ? s.level(Level.WIREFRAME_SUBDIVISION) : 0, unit, x, y, focus);
    }

    /** The patches of {@code s}'s points, ascending, each once. */
    static int[] patchesOf(Selection s) {
        return s.handles().stream().flatMap(java.util.List::stream).mapToInt(PointRef::patch).distinct().sorted().toArray();
    }
}
