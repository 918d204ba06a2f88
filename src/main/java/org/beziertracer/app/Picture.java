package org.beziertracer.app;

import java.util.Arrays;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The picture the ray tracer paints into: {@code width × height} device pixels as one
 * {@code int[]} of {@code 0xRRGGBB} values, row after row, written a tile row at a time with
 * {@link System#arraycopy}. The desktop wraps the same array in an image, so nothing is copied to
 * show it.
 *
 * <p><b>Threads:</b> {@link #tile} runs on render threads; it asks for a repaint through one
 * pending flag, so a burst of tiles costs one repaint request until the view calls
 * {@link #painted()}. A torn read while painting shows at worst a half-updated tile for one frame,
 * which the next repaint corrects.
 */
public final class Picture {

    /** Colour of a fresh picture and of the wireframe view's background. */
    public static final int BACKGROUND = 0x202428;

    private final int[] pixels;
    private final int width;
    private final int height;
    private final Runnable repaint;
    private final AtomicBoolean repaintPending = new AtomicBoolean();

    /**
     * @param repaint asks the view to repaint; called from any thread (it must be thread-safe)
     */
    public Picture(int width, int height, Runnable repaint) {
        this.width = Math.max(1, width);
        this.height = Math.max(1, height);
        this.pixels = new int[this.width * this.height];
        this.repaint = repaint;
        Arrays.fill(pixels, BACKGROUND);
    }

    public int width() { return width; }

    public int height() { return height; }

    /** The live pixel array ({@code 0xRRGGBB}, row-major); the view reads it, render threads write it. */
    public int[] pixels() { return pixels; }

    /**
     * Copies a finished tile ({@code argb[j*stride + i]}) into the picture; the caller has dropped
     * tiles of stale generations. Tiles outside the picture are ignored.
     */
    public void tile(int x0, int y0, int w, int h, int[] argb, int stride) {
        if (x0 < 0 || y0 < 0 || x0 + w > width || y0 + h > height) {
            return;
        }
        for (int j = 0; j < h; j++) {
            System.arraycopy(argb, j * stride, pixels, (y0 + j) * width + x0, w);
        }
        requestRepaint();
    }

    /** One repaint for any number of calls until the view has painted. */
    public void requestRepaint() {
        if (repaintPending.compareAndSet(false, true)) {
            repaint.run();
        }
    }

    /** Called by the view when it paints, re-arming {@link #requestRepaint}. */
    public void painted() { repaintPending.set(false); }

    /** RGB of pixel {@code (x, y)}. */
    public int rgb(int x, int y) { return pixels[y * width + x] & 0xFFFFFF; }
}
