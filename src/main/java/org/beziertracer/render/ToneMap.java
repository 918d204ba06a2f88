package org.beziertracer.render;

/**
 * Linear radiance → display: multiply by {@code 2^exposure}, map each channel by the ACES filmic
 * curve fitted by K. Narkowicz ("ACES Filmic Tone Mapping Curve", 2015:
 * {@code f(x) = x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14)}, clamped to [0, 1]), then encode as
 * sRGB ({@link Srgb}). The curve is nearly linear in the shadows (slope 0.21 at 0 rising to about 1
 * near 0.18), rolls highlights off smoothly and reaches white near x ≈ 10 instead of clipping at 1.
 * Stateless.
 */
public final class ToneMap {
    private ToneMap() {}

    /** The fitted ACES curve of one linear value (≥ 0; NaN and negatives give 0). */
    public static double aces(double x) {
        if (!(x > 0)) {
            return 0;
        }
        double y = x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
        return Math.min(1, y);
    }

    /**
     * One linear colour scaled by {@code scale} ({@code 2^exposure}), mapped by {@link #aces} and
     * encoded as opaque sRGB ARGB: the one formula of the PNG and of the tiles a progressive
     * render shows, so both give the same bytes.
     */
    public static int argb(float r, float g, float b, double scale) {
        return Srgb.argb((float) aces(r * scale), (float) aces(g * scale), (float) aces(b * scale));
    }

    /** The film tone mapped to opaque sRGB ARGB, row-major. */
    public static int[] argb(Film film, double exposure) {
        return argb(film, film.window(), exposure);
    }

    /** The pixels of {@code window} (image coordinates, inside the film's) tone mapped to opaque sRGB ARGB, row-major. */
    public static int[] argb(Film film, PixelWindow window, double exposure) {
        if (!Double.isFinite(exposure)) {
            throw new IllegalArgumentException("exposure must be finite, got " + exposure);
        }
        double scale = Math.pow(2, exposure);
        int w = window.width(), h = window.height();
        int[] out = new int[w * h];
        float[] px = new float[3];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                film.pixel(window.x0() + x, window.y0() + y, px);
                out[y * w + x] = argb(px[0], px[1], px[2], scale);
            }
        }
        return out;
    }
}
