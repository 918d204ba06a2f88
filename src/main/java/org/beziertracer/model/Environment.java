package org.beziertracer.model;

/**
 * The light from infinitely far around the scene: a constant colour (linear RGB radiance), or an
 * equirectangular HDR image ({@code image}: the file name as the scene file gives it, relative to
 * that file; {@code picture}: its pixels, z up, see {@code render.light.ImageEnvironment}), scaled
 * by {@code intensity} and turned about the up axis by {@code rotate} degrees.
 */
public record Environment(double r, double g, double b, String image, double intensity, double rotate,
                          HdrImage picture) {
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
        if ((image == null) != (picture == null)) {
            throw new IllegalArgumentException("an environment image needs both its name and its pixels");
        }
    }

    /** A constant environment of radiance {@code (r, g, b)}. */
    public static Environment color(double r, double g, double b) {
        return new Environment(r, g, b, null, 1, 0, null);
    }

    /** An image environment: {@code name} as written in the scene file, its pixels, scale and turn. */
    public static Environment image(String name, HdrImage picture, double intensity, double rotate) {
        return new Environment(0, 0, 0, name, intensity, rotate, picture);
    }
}
