package org.beziertracer.render;

/**
 * The image being rendered, in linear RGB floats: per pixel the sum of its samples and their
 * count, plus — only for a render that samples adaptively — the first sample alone (which the
 * adaptive sampler compares with the neighbours').
 * The displayed value of a pixel is {@code sum / count}; a pixel with no sample yet shows the
 * value of the anchor of its block in the current progressive pass.
 *
 * <p>Layout: {@code sum[3 * (y * width + x) + c]}, {@code count[y * width + x]},
 * {@code first[3 * (y * width + x) + c]} ({@code null} when not kept).
 *
 * <p>Threads: workers write disjoint tiles; passes are separated by the engine's pass barrier
 * (which also publishes the writes). Read the film from other threads only after the render ended.
 */
public final class Film {
    private final int width, height;
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

    /** Adds a sample to pixel {@code (x, y)}. */
    void addSample(int x, int y, double r, double g, double b) {
        int p = y * width + x, o = 3 * p;
        if (first != null && count[p] == 0) {
            first[o] = (float) r; first[o + 1] = (float) g; first[o + 2] = (float) b;
        }
        sum[o] += (float) r; sum[o + 1] += (float) g; sum[o + 2] += (float) b;
        count[p]++;
    }

    /** Samples in pixel {@code (x, y)} so far. */
    public int sampleCount(int x, int y) { return count[y * width + x]; }

    /** Linear RGB of pixel {@code (x, y)} into {@code out[0..2]} (0 when it has no sample). */
    public void pixel(int x, int y, float[] out) {
        int p = y * width + x, o = 3 * p;
        float inv = count[p] > 0 ? 1f / count[p] : 0;
        out[0] = sum[o] * inv; out[1] = sum[o + 1] * inv; out[2] = sum[o + 2] * inv;
    }

    /** A copy of the averaged linear RGB image, {@code [3 * (y * width + x) + c]}. */
    public float[] linearRgb() {
        float[] out = new float[sum.length];
        float[] px = new float[3];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                pixel(x, y, px);
                System.arraycopy(px, 0, out, 3 * (y * width + x), 3);
            }
        }
        return out;
    }

    /** The whole image as sRGB-encoded opaque ARGB, row-major. */
    public int[] toArgb() {
        int[] out = new int[width * height];
        writeArgb(0, 0, width, height, 1, out, width);
        return out;
    }

    /**
     * Encodes the rectangle {@code (x0, y0, w, h)} into {@code argb[j * stride + i]}; a pixel without
     * samples takes the value of the anchor {@code (x − x mod block, y − y mod block)} of its block.
     * {@code block} is a power of two (the pass plan's), so the anchor is a mask away, not a division.
     */
    void writeArgb(int x0, int y0, int w, int h, int block, int[] argb, int stride) {
        if (block < 1 || (block & (block - 1)) != 0) {
            throw new IllegalArgumentException("block must be a power of two, got " + block);
        }
        int mask = -block;
        for (int j = 0; j < h; j++) {
            int y = y0 + j;
            int last = -1, lastArgb = 0, anchorRow = (y & mask) * width;
            for (int i = 0; i < w; i++) {
                int x = x0 + i;
                int p = y * width + x;
                if (count[p] == 0) {
                    p = anchorRow + (x & mask);
                }
                if (p != last) {
                    // A coarse pass's pixels share their anchor's colour: encode it once per run
                    int o = 3 * p;
                    float inv = count[p] > 0 ? 1f / count[p] : 0;
                    lastArgb = Srgb.argb(sum[o] * inv, sum[o + 1] * inv, sum[o + 2] * inv);
                    last = p;
                }
                argb[j * stride + i] = lastArgb;
            }
        }
    }
}
