package org.beziertracer.ui;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;

/** The picture exactly as the render panel shows it, at device resolution (for Export PNG and tests). */
final class PictureSnapshot {
    private PictureSnapshot() {}

    static BufferedImage of(AppController c) {
        FrameBuffer fb = c.buffer();
        int w = fb == null ? 800 : fb.width(), h = fb == null ? 600 : fb.height();
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        try {
            paint(g, c, w, h, c.scale());
        } finally {
            g.dispose();
        }
        return out;
    }

    /** Paints picture and overlays into {@code g}, whose user space is device pixels. */
    static void paint(Graphics2D g, AppController c, int w, int h, double unit) {
        FrameBuffer fb = c.buffer();
        if (c.tools().rayTrace && fb != null) {
            g.drawImage(fb.image(), 0, 0, null);
        } else {
            g.setColor(OverlayPainter.BACKGROUND);
            g.fillRect(0, 0, w, h);
        }
        OverlayPainter.paint(g, c, unit);
    }
}
