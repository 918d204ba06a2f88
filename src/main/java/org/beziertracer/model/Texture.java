package org.beziertracer.model;

/**
 * A colour that varies over a surface with its (u,v): a procedural checker or an image, either
 * repeated {@code su} times along u and {@code sv} times along v ({@code (u·su, v·sv)} is the
 * texture's own coordinate; scene-file key {@code "scale": [su, sv]}, docs/scene-file.md).
 * Colours are linear RGB albedos in 0..1. Immutable; the render layer looks them up
 * ({@code render.SurfaceTexture}).
 */
public sealed interface Texture permits Texture.Checker, Texture.Image {

    /** Repeats along u. */
    double su();

    /** Repeats along v. */
    double sv();

    /** The texture's mean colour (r, g, b): the colour a renderer that ignores textures shows. */
    double[] mean();

    /**
     * Squares of {@code even} where {@code floor(u·su) + floor(v·sv)} is even, else {@code odd}:
     * {@code su × sv} squares over the unit (u,v) square.
     */
    record Checker(Surface.Vec even, Surface.Vec odd, double su, double sv) implements Texture {
        public Checker {
            checkColour(even);
            checkColour(odd);
            checkScale(su, sv);
        }

        @Override
        public double[] mean() {
            return new double[] {(even.r() + odd.r()) / 2, (even.g() + odd.g()) / 2, (even.b() + odd.b()) / 2};
        }
    }

    /**
     * An image ({@code pixels}, linear RGB decoded from an sRGB PNG or JPEG) stretched over the unit
     * (u,v) square: u from its left column to its right, v from its bottom row to its top (pbrt's
     * convention), repeated beyond. {@code name} is the file name as the scene file gives it
     * (relative to that file).
     */
    record Image(String name, HdrImage pixels, double su, double sv) implements Texture {
        public Image {
            if (name == null || name.isBlank() || pixels == null) {
                throw new IllegalArgumentException("an image texture needs its file name and its pixels");
            }
            checkScale(su, sv);
        }

        @Override
        public double[] mean() {
            double[] sum = new double[3];
            for (int y = 0; y < pixels.height(); y++) {
                for (int x = 0; x < pixels.width(); x++) {
                    for (int c = 0; c < 3; c++) {
                        sum[c] += pixels.get(x, y, c);
                    }
                }
            }
            double n = (double) pixels.width() * pixels.height();
            return new double[] {Math.min(1, sum[0] / n), Math.min(1, sum[1] / n), Math.min(1, sum[2] / n)};
        }
    }

    private static void checkColour(Surface.Vec c) {
        if (c == null || !(c.r() >= 0 && c.r() <= 1 && c.g() >= 0 && c.g() <= 1 && c.b() >= 0 && c.b() <= 1)) {
            throw new IllegalArgumentException("a texture colour is an albedo in 0..1, got " + c);
        }
    }

    private static void checkScale(double su, double sv) {
        if (!(su > 0) || !(sv > 0) || !Double.isFinite(su) || !Double.isFinite(sv)) {
            throw new IllegalArgumentException("a texture's scale must be two finite numbers > 0, got " + su + ", " + sv);
        }
    }
}
