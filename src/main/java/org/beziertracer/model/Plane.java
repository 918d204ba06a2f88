package org.beziertracer.model;

import org.beziertracer.math.Vec3;

/**
 * An infinite plane through {@code point} with unit {@code normal}; {@code material} indexes the
 * scene's materials. Its (u,v) for textures are coordinates along two fixed in-plane axes,
 * in scene units divided by {@code uvScale}.
 */
public record Plane(Vec3 point, Vec3 normal, int material, double uvScale) {
    public Plane {
        if (point == null || !point.isFinite()) {
            throw new IllegalArgumentException("plane point must be finite, got " + point);
        }
        if (normal == null || !normal.isFinite() || !(normal.length() > 0)) {
            throw new IllegalArgumentException("plane normal must be finite and non-zero, got " + normal);
        }
        if (!(uvScale > 0) || !Double.isFinite(uvScale)) {
            throw new IllegalArgumentException("plane uvScale must be positive, got " + uvScale);
        }
        normal = normal.normalize();
    }

    public Plane(Vec3 point, Vec3 normal) { this(point, normal, 0, 1); }
}
