package org.beziertracer.render;

/**
 * The image being rendered, in linear RGB floats: per pixel the sum of its samples and their
 * count, plus — only for a render that samples adaptively — the first sample alone (which the
 * adaptive sampler compares with the neighbours').
 * The displayed value of a pixel is {@code sum / count}; a pixel with no sample yet shows the
 * value of the anchor of its block in the current progressive pass.
 *
 * <p>A film may hold only a window of the image ({@code render --crop}): its pixels keep their image
 * coordinates {@code (x, y)}, {@code x0 ≤ x < x0 + width}, {@code y0 ≤ y < y0 + height}, in every
 * method that takes a pixel. Layout, with {@code p = (y − y0) * width + (x − x0)}: {@code sum[3 * p + c]},
 * {@code count[p]}, {@code first[3 * p + c]} ({@code null} when not kept).
 *
 * <p>Threads: workers write disjoint tiles; passes are separated by the engine's pass barrier
 * (which also publishes the writes). Read the film from other threads only after the render ended.
 */
public final class Film {
    private final int x0, y0, width, height;
    final float[] sum;
    final int[] count;
    /** First sample of every pixel; null unless the film was made to keep it. */
    final float[] first;

    /** A film that keeps the first samples (as an adaptive render needs). */
    public Film(int width, int height) {
        this(width, height, true);
    }

    /**
     * A film; {@code keepFirst} keeps each pixel's first sample apart (needed only by the
     * adaptive sampler's extra pass, which compares them), else those 12 bytes per pixel are
     * neither allocated nor written.
     */
    Film(int width, int height, boolean keepFirst) {
        this(PixelWindow.whole(Math.max(width, 1), Math.max(height, 1)), width, height, keepFirst);
    }

    /** A film of the pixels of {@code window} only (image coordinates kept); see {@link #Film(int, int, boolean)}. */
    Film(PixelWindow window, boolean keepFirst) {
        this(window, window.width(), window.height(), keepFirst);
    }

    private Film(PixelWindow window, int width, int height, boolean keepFirst) {
        this.x0 = window.x0();
        this.y0 = window.y0();
        if (width < 1 || height < 1 || (long) width * height > (1L << 26)) {
            throw new IllegalArgumentException("film of " + width + "x" + height + " pixels is not allowed");
        }
        this.width = width;
        this.height = height;
        sum = new float[3 * width * height];
        count = new int[width * height];
        first = keepFirst ? new float[3 * width * height] : null;
    }

    /** Bytes a film of this size holds (sums, first samples, counts). */
    public static long bytesFor(int width, int height) {
        return 28L * width * height;
    }

    public int width() { return width; }

    public int height() { return height; }

    /** The pixels of the image this film holds. */
    public PixelWindow window() { return new PixelWindow(x0, y0, x0 + width, y0 + height); }

    /** Image column of the film's first pixel (0 for a whole image). */
    int x0() { return x0; }

    /** Image row of the film's first pixel (0 for a whole image). */
    int y0() { return y0; }

    /** Index of pixel {@code (x, y)} (image coordinates) in {@link #count}. */
    int index(int x, int y) { return (y - y0) * width + (x - x0); }

    /** Adds a sample to pixel {@code (x, y)}. */
    void addSample(int x, int y, double r, double g, double b) {
        int p = (y - y0) * width + (x - x0), o = 3 * p;
        if (first != null && count[p] == 0) {
            first[o] = (float) r; first[o + 1] = (float) g; first[o + 2] = (float) b;
        }
        sum[o] += (float) r; sum[o + 1] += (float) g; sum[o + 2] += (float) b;
        count[p]++;
    }

    /** Samples in pixel {@code (x, y)} so far. */
    public int sampleCount(int x, int y) { return count[index(x, y)]; }

    /** Linear RGB of pixel {@code (x, y)} into {@code out[0..2]} (0 when it has no sample). */
    public void pixel(int x, int y, float[] out) {
        int p = index(x, y), o = 3 * p;
        float inv = count[p] > 0 ? 1f / count[p] : 0;
        out[0] = sum[o] * inv; out[1] = sum[o + 1] * inv; out[2] = sum[o + 2] * inv;
    }

    /** A copy of the averaged linear RGB image, {@code [3 * (y * width + x) + c]}. */
    public float[] linearRgb() {
        return linearRgb(window());
    }

    /**
     * A copy of the averaged linear RGB of the pixels of {@code w} (image coordinates, inside this film's
     * window), {@code [3 * ((y − w.y0) * w.width + (x − w.x0)) + c]}.
     */
    public float[] linearRgb(PixelWindow w) {
        int ww = w.width(), wh = w.height();
        float[] out = new float[3 * ww * wh];
        float[] px = new float[3];
        for (int y = 0; y < wh; y++) {
            for (int x = 0; x < ww; x++) {
                pixel(w.x0() + x, w.y0() + y, px);
                System.arraycopy(px, 0, out, 3 * (y * ww + x), 3);
            }
        }
        return out;
    }

    /** The whole image as sRGB-encoded opaque ARGB, row-major. */
    public int[] toArgb() {
        return toArgb(window());
    }

    /** The pixels of {@code w} (inside this film's window) as sRGB-encoded opaque ARGB, row-major. */
    public int[] toArgb(PixelWindow w) {
        if (w.x0() < x0 || w.y0() < y0 || w.x1() > x0 + width || w.y1() > y0 + height) {
            throw new IllegalArgumentException("window " + w + " is outside the film's " + window());
        }
        int[] out = new int[w.width() * w.height()];
        writeArgb(w.x0(), w.y0(), w.width(), w.height(), 1, out, w.width());
        return out;
    }

    /**
     * Encodes the rectangle {@code (x0, y0, w, h)} (image coordinates) into {@code argb[j * stride + i]}; a pixel without
     * samples takes the value of the anchor {@code (x − x mod block, y − y mod block)} of its block.
     * {@code block} is a power of two (the pass plan's), so the anchor is a mask away, not a division.
     */
    void writeArgb(int left, int top, int w, int h, int block, int[] argb, int stride) {
        writeArgb(left, top, w, h, block, argb, stride, 0);
    }

    /**
     * As {@link #writeArgb(int, int, int, int, int, int[], int)}, through the path tracer's tone map
     * ({@link ToneMap#argb(float, float, float, double)} with {@code toneScale = 2^exposure}) when
     * {@code toneScale > 0}, else the plain clamp and sRGB encoding.
     */
    void writeArgb(int left, int top, int w, int h, int block, int[] argb, int stride, double toneScale) {
        if (block < 1 || (block & (block - 1)) != 0) {
            throw new IllegalArgumentException("block must be a power of two, got " + block);
        }
        int mask = -block;
        for (int j = 0; j < h; j++) {
            int y = top + j;
            int last = -1, lastArgb = 0, anchorRow = ((y & mask) - y0) * width - x0;
            for (int i = 0; i < w; i++) {
                int x = left + i;
                int p = index(x, y);
                if (count[p] == 0) {
                    p = anchorRow + (x & mask);
                }
                if (p != last) {
                    // A coarse pass's pixels share their anchor's colour: encode it once per run
                    int o = 3 * p;
                    float inv = count[p] > 0 ? 1f / count[p] : 0;
                    lastArgb = toneScale > 0 ? ToneMap.argb(sum[o] * inv, sum[o + 1] * inv, sum[o + 2] * inv, toneScale)
                            : Srgb.argb(sum[o] * inv, sum[o + 1] * inv, sum[o + 2] * inv);
                    last = p;
                }
                argb[j * stride + i] = lastArgb;
            }
        }
    }
}
