package org.beziertracer.ui;

import java.awt.Cursor;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.event.ComponentAdapter;
import java.awt.event.ComponentEvent;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;

import javax.swing.JComponent;
import javax.swing.SwingUtilities;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.Axis;
import org.beziertracer.app.Modifiers;
import org.beziertracer.app.Picture;
import org.beziertracer.app.PointerTool;
import org.beziertracer.app.RenderStatus;
import org.beziertracer.app.Toggle;

/**
 * Shows the ray-traced picture at <b>device</b> resolution (2 under {@code GDK_SCALE=2}) with the
 * overlay on top, and forwards mouse events, converted to device pixels and with the modifier keys
 * held, to the app's {@link PointerTool}, and the X, Y and Z keys (held while dragging to move
 * along that axis); its size goes to the app's view when it changes. Painting reads the picture's
 * pixels and the overlay snapshot and nothing else; it never renders and never calls into the
 * app.
 */
public final class RenderPanel extends JComponent {

    private final AppModel app;
    private final PictureImage images = new PictureImage();
    private final DifferenceImage differences = new DifferenceImage();
    private long paintCount;

    public RenderPanel(AppModel app) {
        this.app = app;
        setName("renderPanel");
        setPreferredSize(new Dimension(840, 660));
        setOpaque(true);
        setFocusable(true);
        PointerTool p = app.pointer();
        MouseAdapter mouse = new MouseAdapter() {
            @Override
            public void mousePressed(MouseEvent e) {
                requestFocusInWindow();
                if (SwingUtilities.isLeftMouseButton(e)) {
                    p.pressed(x(e), y(e), new Modifiers(e.isShiftDown(), e.isControlDown(), e.isAltDown()));
                }
            }

            @Override
            public void mouseDragged(MouseEvent e) { p.dragged(x(e), y(e)); }

            @Override
            public void mouseReleased(MouseEvent e) {
                if (SwingUtilities.isLeftMouseButton(e)) {
                    p.released(x(e), y(e));
                }
            }

            @Override
            public void mouseMoved(MouseEvent e) {
                p.moved(x(e), y(e));
                setCursor(Cursor.getPredefinedCursor(app.overlay().hover() != null ? Cursor.HAND_CURSOR : Cursor.DEFAULT_CURSOR));
            }

            @Override
            public void mouseExited(MouseEvent e) { p.left(); }

            @Override
            public void mouseWheelMoved(MouseWheelEvent e) { p.wheel(e.getPreciseWheelRotation()); }
        };
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        addKeyListener(new KeyAdapter() {
            @Override
            public void keyPressed(KeyEvent e) { axisKey(e, true); }

            @Override
            public void keyReleased(KeyEvent e) { axisKey(e, false); }
        });
        addComponentListener(new ComponentAdapter() {
            @Override
            public void componentResized(ComponentEvent e) { syncSize(); }
        });
        addPropertyChangeListener("graphicsConfiguration", e -> syncSize());
        app.view().setRepaint(this::repaint);
    }

    private void axisKey(KeyEvent e, boolean down) {
        Axis a = switch (e.getKeyCode()) {
            case KeyEvent.VK_X -> Axis.X;
            case KeyEvent.VK_Y -> Axis.Y;
            case KeyEvent.VK_Z -> Axis.Z;
            default -> null;
        };
        if (a != null && (!down || e.getModifiersEx() == 0)) {
            app.pointer().axis(a, down);
        }
    }

    private double x(MouseEvent e) { return e.getX() * deviceScale(); }

    private double y(MouseEvent e) { return e.getY() * deviceScale(); }

    /** Device pixels per user-space pixel, from the screen's default transform. */
    public double deviceScale() {
        var gc = getGraphicsConfiguration();
        return gc == null ? 1 : Math.max(1e-3, gc.getDefaultTransform().getScaleX());
    }

    private void syncSize() {
        double scale = deviceScale();
        int w = (int) Math.ceil(getWidth() * scale), h = (int) Math.ceil(getHeight() * scale);
        if (w > 0 && h > 0) {
            app.view().resize(w, h, scale);
        }
    }

    /** Paints so far (tests check that the window repaints). */
    public long paintCount() { return paintCount; }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            AffineTransform t = g2.getTransform();
            int w = (int) Math.ceil(getWidth() * t.getScaleX()), h = (int) Math.ceil(getHeight() * t.getScaleY());
            // Draw in device pixels: undo the scale, keep the translation
            g2.scale(1 / t.getScaleX(), 1 / t.getScaleY());
            Picture picture = app.view().picture();
            BufferedImage image = null;
            if (picture != null) {
                picture.painted();
                image = app.settings().current().on(Toggle.RAY_TRACE) ? images.of(picture) : null;
            }
            PicturePainter.paint(g2, image, differences.of(app, picture), app.overlay().snapshot(), w, h,
                    t.getScaleX());
            RenderStatus status = app.status().render();
            if (image != null && status != null && status.shading() == app.settings().current().analysis()) {
                LegendPainter.paint(g2, status, w, h, t.getScaleX());
            }
            if (app.settings().current().on(Toggle.CONTINUITY)) {
                ContinuityMarks.paint(g2, app.continuity().current(), app.view().projector(), t.getScaleX());
            }
            paintCount++;
        } finally {
            g2.dispose();
        }
    }

    /** The picture as shown now, at device resolution (Export Picture, tests). */
    public BufferedImage snapshot() {
        Picture picture = app.view().picture();
        boolean traced = picture != null && app.settings().current().on(Toggle.RAY_TRACE);
        return PicturePainter.snapshot(traced ? images.of(picture) : null, differences.of(app, picture),
                app.overlay().snapshot(),
                app.view().width(), app.view().height(), app.view().scale());
    }
}
