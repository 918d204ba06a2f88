package org.beziertracer.model;

/**
 * A high-dynamic-range image in linear RGB floats, row-major from the top row,
 * {@code rgb[3 * (y * width + x) + c]}: an environment map read from a Radiance {@code .hdr}
 * file. Immutable (the array is copied in and never handed out).
 */
public final class HdrImage {
    private final int width, height;
    private final float[] rgb;

    public HdrImage(int width, int height, float[] rgb) {
        if (width < 1 || height < 1 || rgb == null || rgb.length != 3L * width * height) {
            throw new IllegalArgumentException("an HDR image needs 3 floats per pixel of " + width + "x" + height);
        }
        for (float v : rgb) {
            if (!(v >= 0) || !Float.isFinite(v)) {
                throw new IllegalArgumentException("an HDR image holds finite values >= 0, found " + v);
            }
        }
        this.width = width;
        this.height = height;
        this.rgb = rgb.clone();
    }

    public int width() { return width; }

    public int height() { return height; }

    /** Channel {@code c} of pixel {@code (x, y)}. */
    public float get(int x, int y, int c) { return rgb[3 * (y * width + x) + c]; }
}
