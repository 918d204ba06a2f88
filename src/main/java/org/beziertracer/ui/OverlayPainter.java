package org.beziertracer.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.image.BufferedImage;

import org.beziertracer.app.Handle;
import org.beziertracer.app.LightMarker;
import org.beziertracer.app.OverlayBuilder;
import org.beziertracer.app.OverlayGeometry;
import org.beziertracer.app.OverlaySnapshot;

/**
 * Draws an {@link OverlaySnapshot} over (or, in wireframe mode, instead of) the ray-traced
 * picture: the projected iso-curves, the control polygon, the control-point handles, the hovered
 * and the selected points, the rubber band and the light markers. It draws only what the snapshot
 * holds — a bounded number of shapes,
 * prepared off the event thread — and calls nothing back. Works in device pixels; {@code unit} is
 * the device scale, so lines keep their look under HiDPI. Event thread only (it keeps the
 * handle's image).
 */
final class OverlayPainter {
    private OverlayPainter() {}

    static final Color WIRE = new Color(0x7FD1FF);
    static final Color POLYGON = new Color(0xB0B8C0);
    static final Color POINT = new Color(0xFFFFFF);
    static final Color HOVER = new Color(0xFFD23F);
    static final Color SELECTED = new Color(0xFF4F4F);
    static final Color BAND = new Color(0xFFD23F);
    static final Color LIGHT = new Color(0xFFE066);

    // Event thread only: the handle images, drawn once per scale
    private static BufferedImage sprite, selectedSprite;
    private static double spriteUnit;

    static void paint(Graphics2D g, OverlaySnapshot s, double unit) {
        OverlayGeometry geo = s.geometry();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        if (!geo.isoCurves().isEmpty()) {
            g.setColor(WIRE);
            g.setStroke(new BasicStroke((float) unit));
            g.draw(polylines(geo.isoCurves()));
        }
        if (!geo.polygon().isEmpty()) {
            g.setColor(POLYGON);
            g.setStroke(new BasicStroke((float) unit, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 10,
                    new float[] {(float) (4 * unit), (float) (3 * unit)}, 0));
            g.draw(polylines(geo.polygon()));
        }
        double r = OverlayBuilder.HANDLE_RADIUS * unit;
        g.setStroke(new BasicStroke((float) unit));
        sprites(unit);
        double c = sprite.getWidth() / 2.0;
        for (int k = 0; k < geo.handleCount(); k++) {
            g.drawImage(sprite, (int) Math.floor(geo.handleX(k) - c + 0.5), (int) Math.floor(geo.handleY(k) - c + 0.5), null);
        }
        double cs = selectedSprite.getWidth() / 2.0;
        for (Handle sel : s.selected()) {
            g.drawImage(selectedSprite, (int) Math.floor(sel.x() - cs + 0.5), (int) Math.floor(sel.y() - cs + 0.5), null);
        }
        Handle h = s.hover();
        if (h != null) {
            dot(g, h.x(), h.y(), 2 * r, HOVER);
        }
        band(g, s.band(), unit);
        for (LightMarker m : s.lights()) {
            light(g, m, unit);
        }
    }

    /** The rubber band: a dashed rectangle. */
    private static void band(Graphics2D g, double[] b, double unit) {
        if (b == null) {
            return;
        }
        java.awt.geom.Rectangle2D.Double rect = new java.awt.geom.Rectangle2D.Double(Math.min(b[0], b[2]),
                Math.min(b[1], b[3]), Math.abs(b[2] - b[0]), Math.abs(b[3] - b[1]));
        g.setColor(new Color(BAND.getRed(), BAND.getGreen(), BAND.getBlue(), 40));
        g.fill(rect);
        g.setColor(BAND);
        g.setStroke(new BasicStroke((float) unit, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10,
                new float[] {(float) (4 * unit), (float) (3 * unit)}, 0));
        g.draw(rect);
    }

    /**
     * A light: a sun (a disc with rays); pale when pulled in from outside the picture; with a bar
     * across when it cannot be dragged (a scene's own light).
     */
    private static void light(Graphics2D g, LightMarker m, double unit) {
        double r = 6 * unit;
        g.setStroke(new BasicStroke((float) (1.5 * unit)));
        for (int k = 0; k < 8; k++) {
            double a = k * Math.PI / 4;
            double c = Math.cos(a), s = Math.sin(a);
            g.setColor(Color.BLACK);
            g.draw(new java.awt.geom.Line2D.Double(m.x() + c * 1.4 * r, m.y() + s * 1.4 * r, m.x() + c * 2.1 * r,
                    m.y() + s * 2.1 * r));
        }
        Ellipse2D.Double disc = new Ellipse2D.Double(m.x() - r, m.y() - r, 2 * r, 2 * r);
        g.setColor(m.inside() ? LIGHT : new Color(LIGHT.getRed(), LIGHT.getGreen(), LIGHT.getBlue(), 150));
        g.fill(disc);
        g.setColor(Color.BLACK);
        g.draw(disc);
        if (!m.draggable()) {
            g.draw(new java.awt.geom.Line2D.Double(m.x() - r / 2, m.y(), m.x() + r / 2, m.y()));
        }
    }

    private static Path2D.Float polylines(java.util.List<float[]> lines) {
        Path2D.Float path = new Path2D.Float();
        for (float[] line : lines) {
            path.moveTo(line[0], line[1]);
            for (int k = 2; k < line.length; k += 2) {
                path.lineTo(line[k], line[k + 1]);
            }
        }
        return path;
    }

    /** The handles drawn once, at this scale, to be stamped: far cheaper than filling and stroking each. */
    private static void sprites(double unit) {
        if (sprite == null || spriteUnit != unit) {
            double r = OverlayBuilder.HANDLE_RADIUS * unit;
            sprite = sprite(r, unit, POINT);
            selectedSprite = sprite(2 * r, unit, SELECTED);
            spriteUnit = unit;
        }
    }

    private static BufferedImage sprite(double r, double unit, Color fill) {
        int size = (int) Math.ceil(2 * r + 2 * unit) + 2;
        BufferedImage img = new BufferedImage(size, size, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.setStroke(new BasicStroke((float) unit));
        dot(g, size / 2.0, size / 2.0, r, fill);
        g.dispose();
        return img;
    }

    private static void dot(Graphics2D g, double x, double y, double r, Color fill) {
        Ellipse2D.Double e = new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r);
        g.setColor(fill);
        g.fill(e);
        g.setColor(Color.BLACK);
        g.draw(e);
    }
}
