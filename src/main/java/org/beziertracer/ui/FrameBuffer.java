package org.beziertracer.ui;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * The picture the ray tracer paints into: a {@link BufferedImage} of {@code TYPE_INT_RGB} whose
 * {@code int[]} raster render threads write directly, a tile row at a time with
 * {@link System#arraycopy} (no {@code setRGB}, no {@code Color}).
 *
 * <p><b>Threads:</b> {@link #tile} runs on render threads and never touches Swing; it asks for a
 * repaint through one pending flag, so a burst of tiles costs one {@code repaint()} on the event
 * thread ({@code repaint()} itself is thread-safe and coalescing). A torn read while painting shows at worst a
 * half-updated tile for one frame, which the next repaint corrects.
 */
public final class FrameBuffer {

    private final BufferedImage image;
    private final int[] pixels;
    private final int width;
    private final int height;
    private final Runnable repaint;
    private final AtomicBoolean repaintPending = new AtomicBoolean();

    /**
     * @param repaint asks the panel to repaint; called from any thread (it must be thread-safe,
     *                e.g. {@code Component::repaint})
     */
    public FrameBuffer(int width, int height, Runnable repaint) {
        this.width = Math.max(1, width);
        this.height = Math.max(1, height);
        this.image = new BufferedImage(this.width, this.height, BufferedImage.TYPE_INT_RGB);
        this.pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        this.repaint = repaint;
    }

    public int width() { return width; }

    public int height() { return height; }

    public BufferedImage image() { return image; }

    /**
     * Copies a finished tile ({@code argb[j*stride + i]}) into the image; the caller has dropped
     * tiles of stale generations. Tiles outside the image are ignored.
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

    /** Fills the whole image with one colour (a fresh buffer before the first tile). */
    public void clear(int rgb) {
        java.util.Arrays.fill(pixels, rgb);
    }

    /** One repaint for any number of calls until the event thread has painted. */
    public void requestRepaint() {
        if (repaintPending.compareAndSet(false, true)) {
            repaint.run();
        }
    }

    /** Called by the panel when it paints, re-arming {@link #requestRepaint}. */
    public void painted() { repaintPending.set(false); }

    /** RGB of pixel {@code (x, y)} (tests). */
    public int rgb(int x, int y) { return pixels[y * width + x] & 0xFFFFFF; }
}
