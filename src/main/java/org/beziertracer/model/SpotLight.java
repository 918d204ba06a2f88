package org.beziertracer.model;

import org.beziertracer.math.Vec3;

/**
 * A spot light for the path tracer: a point source at {@code position} shining along
 * {@code direction}, full inside the cone of half-angle {@code falloff} degrees, fading to nothing
 * at {@code angle} degrees (0 < falloff ≤ angle ≤ 90), of colour {@code (r, g, b)} (an intensity,
 * scaled as the point lights' are, see docs/scene-file.md).
 */
public record SpotLight(Vec3 position, Vec3 direction, double angle, double falloff, double r, double g, double b) {
    public SpotLight {
        if (position == null || !position.isFinite()) {
            throw new IllegalArgumentException("spot light position must be finite, got " + position);
        }
        if (direction == null || !direction.isFinite() || !(direction.length() > 0)) {
            throw new IllegalArgumentException("spot light direction must be finite and non-zero");
        }
        if (!(falloff > 0 && falloff <= angle && angle <= 90)) {
            throw new IllegalArgumentException("spot angles must satisfy 0 < falloff <= angle <= 90 degrees, got falloff "
                    + falloff + " and angle " + angle);
        }
        if (!(r >= 0 && g >= 0 && b >= 0) || !Double.isFinite(r + g + b)) {
            throw new IllegalArgumentException("light colour must be finite and >= 0");
        }
    }
}
