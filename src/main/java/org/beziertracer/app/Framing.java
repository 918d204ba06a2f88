package org.beziertracer.app;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;

/**
 * What the view is centred on: the model's bounding sphere ({@code target}, {@code radius}).
 * Rotation and zoom are not part of it, so an edit that re-frames the view (Replace with Flat Grid
 * to a grid of another size) and its undo move the view back and forth without losing the user's
 * rotation and zoom.
 */
public record Framing(Vec3 target, double radius) {

    /** The bounding sphere of a box (the origin and radius 0 for an empty one). */
    public static Framing of(Aabb bounds) {
        return bounds.isEmpty() ? new Framing(Vec3.ZERO, 0) : new Framing(bounds.center(), 0.5 * bounds.diagonal());
    }
}
