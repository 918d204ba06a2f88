package org.beziertracer.ui;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;

import org.beziertracer.app.OverlaySnapshot;
import org.beziertracer.app.Picture;

/**
 * The picture exactly as the render panel shows it: the ray-traced image (or, in the wireframe
 * view, the plain background) with the overlay on top, in device pixels. Used by the panel and by
 * Export Picture. Stateless.
 */
final class PicturePainter {
    private PicturePainter() {}

    static final Color BACKGROUND = new Color(Picture.BACKGROUND);

    /**
     * Paints into {@code g}, whose user space is device pixels.
     *
     * @param image      the ray-traced picture, or null to show the background only (wireframe view)
     * @param difference View → Difference to clipping's marks over the picture, or null
     */
    static void paint(Graphics2D g, BufferedImage image, BufferedImage difference, OverlaySnapshot overlay, int w, int h,
                      double unit) {
        if (image != null) {
            g.drawImage(image, 0, 0, null);
        } else {
            g.setColor(BACKGROUND);
            g.fillRect(0, 0, w, h);
        }
        if (difference != null) {
            g.drawImage(difference, 0, 0, null);
        }
        OverlayPainter.paint(g, overlay, unit);
    }

    /** A copy of what the panel shows, {@code w × h} device pixels (Export Picture, tests). */
    static BufferedImage snapshot(BufferedImage image, BufferedImage difference, OverlaySnapshot overlay, int w, int h,
                                  double unit) {
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        try {
            paint(g, image, difference, overlay, w, h, unit);
        } finally {
            g.dispose();
        }
        return out;
    }
}
