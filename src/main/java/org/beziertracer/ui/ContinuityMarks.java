package org.beziertracer.ui;

import java.awt.BasicStroke;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Path2D;

import org.beziertracer.app.ContinuityModel;
import org.beziertracer.app.ScreenProjector;

/**
 * Draws View → Continuity's marks over the picture: every shared border as a thick line in its
 * class's colour ({@link ContinuityPanel#COLOURS}: green G2, yellow G1, red G0 only or a gap),
 * the worst last so that it stays on top. The border curves are sampled in world space by the
 * analysis; here they are only projected. Event thread only; works in device pixels.
 */
final class ContinuityMarks {
    private ContinuityMarks() {}

    static void paint(Graphics2D g, ContinuityModel.Shown shown, ScreenProjector projector, double unit) {
        if (shown == null) {
            return;
        }
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setStroke(new BasicStroke((float) (3 * unit), BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        double[] p = new double[3];
        var rows = shown.result().rows();
        for (int i = rows.size() - 1; i >= 0; i--) {
            double[] c = shown.curves().get(i);
            Path2D.Double path = new Path2D.Double();
            boolean pen = false;
            for (int k = 0; k < c.length; k += 3) {
                if (!projector.project(c[k], c[k + 1], c[k + 2], p)) {
                    pen = false;
                    continue;
                }
                if (pen) {
                    path.lineTo(p[0], p[1]);
                } else {
                    path.moveTo(p[0], p[1]);
                    pen = true;
                }
            }
            g.setColor(ContinuityPanel.COLOURS[rows.get(i).continuity().ordinal()]);
            g.draw(path);
        }
    }
}
