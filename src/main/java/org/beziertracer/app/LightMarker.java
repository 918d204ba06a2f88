package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.math.Vec3;

/**
 * A light as the view shows it ("Show light"): where it projects onto the picture, pulled in to the
 * picture's edge when it lies outside (then {@code inside} is false and the marker points the way),
 * and whether it can be dragged.
 *
 * @param x         picture x of the marker (device pixels)
 * @param y         picture y of the marker
 * @param inside    true when the light itself projects inside the picture
 * @param draggable true for the toolbox's light; false for a scene's own lights
 */
public record LightMarker(double x, double y, boolean inside, boolean draggable) {

    /** Distance kept from the picture's edge by a marker pulled in, in pixels at scale 1. */
    public static final double EDGE = 14;

    /** The markers of the lights at {@code positions} (lights behind the eye are not shown). */
    static List<LightMarker> of(List<Vec3> positions, ScreenProjector projector, boolean draggable, double scale) {
        List<LightMarker> out = new ArrayList<>();
        double[] at = new double[3];
        double edge = EDGE * scale;
        for (Vec3 p : positions) {
            if (projector.project(p.x(), p.y(), p.z(), at)) {
                double x = Math.max(edge, Math.min(projector.width() - edge, at[0]));
                double y = Math.max(edge, Math.min(projector.height() - edge, at[1]));
                out.add(new LightMarker(x, y, x == at[0] && y == at[1], draggable));
            }
        }
        return out;
    }
}
