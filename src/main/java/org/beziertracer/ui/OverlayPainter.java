package org.beziertracer.ui;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;

import org.beziertracer.model.BezierPatch;

/**
 * Draws what lies over (or, in wireframe mode, instead of) the ray-traced picture: the projected
 * wireframe iso-curves, the control polygon, the control points, the hovered and dragged point.
 * Works in device pixels; {@code unit} is the device scale, so lines keep their look under HiDPI.
 */
final class OverlayPainter {
    private OverlayPainter() {}

    static final Color BACKGROUND = new Color(0x202428);
    static final Color WIRE = new Color(0x7FD1FF);
    static final Color POLYGON = new Color(0xB0B8C0);
    static final Color POINT = new Color(0xFFFFFF);
    static final Color HOVER = new Color(0xFFD23F);
    static final Color DRAG = new Color(0xFF4F4F);

    static void paint(Graphics2D g, AppController c, double unit) {
        ToolSettings t = c.tools();
        ProjectedScene ps = c.projected();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        boolean wire = !t.rayTrace;
        if (wire || t.wireframeOverlay) {
            g.setColor(WIRE);
            g.setStroke(new BasicStroke((float) unit));
            for (double[] line : ps.isoCurves(t.wireframeSubdivision)) {
                g.draw(polyline(line));
            }
        }
        if (wire || t.controlPolygon) {
            g.setColor(POLYGON);
            g.setStroke(new BasicStroke((float) unit, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 10,
                    new float[] {(float) (4 * unit), (float) (3 * unit)}, 0));
            drawPolygons(g, ps);
        }
        if (wire || t.controlPoints) {
            drawPoints(g, ps, c, unit);
        }
    }

    private static void drawPolygons(Graphics2D g, ProjectedScene ps) {
        var patches = ps.scene().patches();
        for (int p = 0; p < patches.size(); p++) {
            if (!ps.isVisible(p)) {
                continue;
            }
            BezierPatch bp = patches.get(p);
            int n = bp.degreeU(), m = bp.degreeV();
            Path2D.Double path = new Path2D.Double();
            for (int j = 0; j <= m; j++) {
                path.moveTo(ps.x(p, 0, j), ps.y(p, 0, j));
                for (int i = 1; i <= n; i++) {
                    path.lineTo(ps.x(p, i, j), ps.y(p, i, j));
                }
            }
            for (int i = 0; i <= n; i++) {
                path.moveTo(ps.x(p, i, 0), ps.y(p, i, 0));
                for (int j = 1; j <= m; j++) {
                    path.lineTo(ps.x(p, i, j), ps.y(p, i, j));
                }
            }
            g.draw(path);
        }
    }

    private static void drawPoints(Graphics2D g, ProjectedScene ps, AppController c, double unit) {
        var patches = ps.scene().patches();
        double r = 3.5 * unit;
        g.setStroke(new BasicStroke((float) unit));
        for (int p = 0; p < patches.size(); p++) {
            if (!ps.isVisible(p)) {
                continue;
            }
            BezierPatch bp = patches.get(p);
            for (int j = 0; j <= bp.degreeV(); j++) {
                for (int i = 0; i <= bp.degreeU(); i++) {
                    dot(g, ps.x(p, i, j), ps.y(p, i, j), r, POINT);
                }
            }
        }
        PointRef h = c.hover();
        if (h != null && h.patch() < patches.size() && ps.isVisible(h.patch())) {
            dot(g, ps.x(h.patch(), h.i(), h.j()), ps.y(h.patch(), h.i(), h.j()), 2 * r, HOVER);
        }
        PointRef d = c.dragged();
        if (d != null && d.patch() < patches.size() && ps.isVisible(d.patch())) {
            dot(g, ps.x(d.patch(), d.i(), d.j()), ps.y(d.patch(), d.i(), d.j()), 2 * r, DRAG);
        }
    }

    private static void dot(Graphics2D g, double x, double y, double r, Color fill) {
        Ellipse2D.Double e = new Ellipse2D.Double(x - r, y - r, 2 * r, 2 * r);
        g.setColor(fill);
        g.fill(e);
        g.setColor(Color.BLACK);
        g.draw(e);
    }

    private static Path2D.Double polyline(double[] xy) {
        Path2D.Double path = new Path2D.Double();
        path.moveTo(xy[0], xy[1]);
        for (int k = 2; k < xy.length; k += 2) {
            path.lineTo(xy[k], xy[k + 1]);
        }
        return path;
    }
}
