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
 */
public record OverlayRequest(Scene scene, ScreenProjector projector, boolean points, boolean polygon, int isoCurves,
                             double unit) {

    /** The request for the current state of the app. */
    static OverlayRequest of(Scene scene, ScreenProjector projector, Settings s, double unit) {
        return new OverlayRequest(scene, projector, s.pointsShown(), s.polygonShown(),
                s.isoCurvesShown() ? s.level(Level.WIREFRAME_SUBDIVISION) : 0, unit);
    }
}
