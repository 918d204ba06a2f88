package org.beziertracer.render;

import java.util.Locale;

/**
 * Reconstruction filter, applied by <i>filter importance sampling</i>: sample offsets are warped
 * so their density follows the filter, and every sample then has weight 1 (pbrt-v4's
 * {@code FilterSampler}; Shirley &amp; Chiu's tent warp in smallpt). A pixel therefore only
 * ever receives its own samples, so tiles never write outside themselves.
 */
public enum PixelFilter {
    /** Samples uniform over the pixel square. */
    BOX,
    /** Tent of radius one pixel: samples reach into the neighbouring pixels, denser at the centre. */
    TENT;

    /**
     * Maps a uniform {@code s ∈ [0,1)} to the offset from the pixel's left (or top) edge:
     * {@code s} itself for the box; {@code 0.5 + tent⁻¹(s)} with the tent on {@code [-1, 1]} for the
     * tent. The centre {@code s = 0.5} maps to 0.5 for both.
     */
    public double warp(double s) {
        if (this == BOX) {
            return s;
        }
        double r = 2 * s;
        double d = r < 1 ? Math.sqrt(r) - 1 : 1 - Math.sqrt(2 - r);
        return 0.5 + d;
    }

    public static PixelFilter parse(String s) {
        return switch (s == null ? "" : s.trim().toLowerCase(Locale.ROOT)) {
            case "box" -> BOX;
            case "tent" -> TENT;
            default -> throw new IllegalArgumentException("unknown filter '" + s + "': expected box or tent");
        };
    }
}
