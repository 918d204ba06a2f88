package org.beziertracer.ui;

import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.util.Locale;

import org.beziertracer.app.RenderStatus;
import org.beziertracer.render.AnalysisLegend;
import org.beziertracer.render.ShadingMode;
import org.beziertracer.render.Srgb;

/**
 * The colour legend of a curvature view, drawn in the picture's bottom-right corner: the scale
 * from its low to its high end ({@link AnalysisLegend}, the view's own axis) with the values at
 * the ends and the middle. Event thread only; device pixels.
 */
final class LegendPainter {
    private LegendPainter() {}

    static void paint(Graphics2D g, RenderStatus s, int width, int height, double unit) {
        if (s == null || s.shading() == null || !s.shading().needsCurvature()) {
            return;
        }
        ShadingMode mode = s.shading();
        int barW = (int) (200 * unit), barH = (int) (10 * unit), margin = (int) (12 * unit);
        Font font = g.getFont().deriveFont((float) (11 * unit));
        g.setFont(font);
        FontMetrics fm = g.getFontMetrics();
        int x0 = width - margin - barW, y0 = height - margin - fm.getHeight() - barH;
        if (x0 < margin || y0 < margin) {
            return;
        }
        g.setColor(new Color(0, 0, 0, 140));
        g.fillRect(x0 - (int) (6 * unit), y0 - (int) (20 * unit), barW + (int) (12 * unit),
                barH + fm.getHeight() + (int) (26 * unit));
        double[] c = new double[3];
        for (int x = 0; x < barW; x++) {
            AnalysisLegend.colourAt(mode, s.analysisLow(), s.analysisHigh(), (x + 0.5) / barW, c);
            g.setColor(new Color(Srgb.to8((float) c[0]), Srgb.to8((float) c[1]), Srgb.to8((float) c[2])));
            g.fillRect(x0 + x, y0, 1, barH);
        }
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        String title = switch (mode) {
            case GAUSSIAN -> "Gaussian curvature K (√ scale)";
            case MEAN -> "mean curvature H";
            case MIN_RADIUS -> "minimum radius (log scale)";
            default -> "maximum radius (log scale)";
        };
        g.drawString(title, x0, y0 - (int) (5 * unit));
        int base = y0 + barH + fm.getAscent() + (int) (2 * unit);
        for (double f : new double[] {0, 0.5, 1}) {
            String text = number(AnalysisLegend.valueAt(mode, s.analysisLow(), s.analysisHigh(), f));
            int tx = (int) (x0 + f * barW - f * fm.stringWidth(text));
            g.drawString(text, tx, base);
        }
    }

    private static String number(double v) {
        return String.format(Locale.ROOT, "%.3g", v).replace('-', '−');
    }
}
