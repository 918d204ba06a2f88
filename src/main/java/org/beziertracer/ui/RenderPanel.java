package org.beziertracer.ui;

import java.awt.Cursor;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.AffineTransform;

import javax.swing.JComponent;

/**
 * The framebuffer: shows the ray-traced picture at <b>device</b> resolution (the Graphics2D
 * transform's scale, 2 under {@code GDK_SCALE=2}) with the overlays on top, and forwards mouse
 * events, converted to device pixels, to the controller. Paints only; never renders.
 */
public final class RenderPanel extends JComponent {

    private final AppController c;
    private double scale = 1;

    public RenderPanel(AppController controller) {
        this.c = controller;
        setName("renderPanel");
        setPreferredSize(new Dimension(840, 660));
        setOpaque(true);
        setFocusable(true);
        setToolTipText(null);
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                requestFocusInWindow();
                c.mousePressed(e.getX() * scale, e.getY() * scale);
            }

            @Override
            public void mouseDragged(MouseEvent e) { c.mouseDragged(e.getX() * scale, e.getY() * scale); }

            @Override
            public void mouseReleased(MouseEvent e) { c.mouseReleased(e.getX() * scale, e.getY() * scale); }

            @Override
            public void mouseMoved(MouseEvent e) {
                c.mouseMoved(e.getX() * scale, e.getY() * scale);
                setCursor(Cursor.getPredefinedCursor(c.hover() != null ? Cursor.HAND_CURSOR : Cursor.DEFAULT_CURSOR));
            }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) { c.mouseWheel(e.getPreciseWheelRotation()); }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        c.setRepaint(this::repaint);
    }

    /** Device pixels per user-space pixel, from the screen's default transform. */
    public double deviceScale() { return scale; }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            AffineTransform t = g2.getTransform();
            scale = Math.max(1e-3, t.getScaleX());
            int w = (int) Math.ceil(getWidth() * scale), h = (int) Math.ceil(getHeight() * scale);
            if (w <= 0 || h <= 0) {
                return;
            }
            c.viewport(w, h, scale);
            // Draw in device pixels: undo the scale, keep the translation
            g2.scale(1 / t.getScaleX(), 1 / t.getScaleY());
            FrameBuffer fb = c.buffer();
            if (fb != null) {
                fb.painted();
            }
            PictureSnapshot.paint(g2, c, w, h, scale);
        } finally {
            g2.dispose();
        }
    }
}
