package org.beziertracer.model;

import org.beziertracer.math.Vec3;

/** A point light with linear RGB intensity (white 1,1,1 by default). */
public record PointLight(Vec3 position, double r, double g, double b) {
    public PointLight {
        if (position == null || !position.isFinite()) {
            throw new IllegalArgumentException("light position must be finite, got " + position);
        }
        if (!(r >= 0 && g >= 0 && b >= 0) || !Double.isFinite(r + g + b)) {
            throw new IllegalArgumentException("light colour must be finite and >= 0");
        }
    }

    public PointLight(Vec3 position) { this(position, 1, 1, 1); }
}
