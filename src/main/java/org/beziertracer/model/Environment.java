package org.beziertracer.model;

/**
 * The light from infinitely far around the scene: a constant colour (linear RGB radiance), or an
 * equirectangular image file ({@code image}, relative to the scene file; read by a later version)
 * scaled by {@code intensity} and turned about the up axis by {@code rotate} degrees.
 */
public record Environment(double r, double g, double b, String image, double intensity, double rotate) {
    public Environment {
        if (!(r >= 0 && g >= 0 && b >= 0) || !Double.isFinite(r + g + b)) {
            throw new IllegalArgumentException("environment colour must be finite and >= 0");
        }
        if (!(intensity >= 0) || !Double.isFinite(intensity)) {
            throw new IllegalArgumentException("environment intensity must be finite and >= 0, got " + intensity);
        }
        if (!Double.isFinite(rotate)) {
            throw new IllegalArgumentException("environment rotation must be finite, got " + rotate);
        }
    }

    /** A constant environment of radiance {@code (r, g, b)}. */
    public static Environment color(double r, double g, double b) {
        return new Environment(r, g, b, null, 1, 0);
    }
}
