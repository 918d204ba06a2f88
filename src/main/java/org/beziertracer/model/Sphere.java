package org.beziertracer.model;

import org.beziertracer.math.Vec3;

/** A sphere; {@code material} indexes the scene's materials. */
public record Sphere(Vec3 center, double radius, int material) {
    public Sphere {
        if (center == null || !center.isFinite()) {
            throw new IllegalArgumentException("sphere centre must be finite, got " + center);
        }
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("sphere radius must be positive and finite, got " + radius);
        }
    }

    public Sphere(Vec3 center, double radius) { this(center, radius, 0); }
}
