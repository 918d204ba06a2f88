package org.beziertracer.bench.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.TreeMap;

import javax.imageio.ImageIO;

import org.beziertracer.bench.FrameScenes;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Cost versus degree from a {@code DegreeSweep} JMH JSON: a Markdown table on standard output
 * (degree, exact and tessellated median ms per frame with min..p90, the tessellation's K, and
 * exact / tessellated) and a line chart of the two medians against the degree (whiskers min..p90).
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.DegreeCurve \
 *     bench/results/report/degree.json docs/perf/report-degree.png
 * </pre>
 */
public final class DegreeCurve {
    private DegreeCurve() {}

    /** Median, fastest and 90th-percentile sample of one run, in the run's unit (ms). */
    record Sample(double median, double min, double p90) {}

    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: DegreeCurve DEGREE_SWEEP.json OUTPUT.png");
            System.exit(2);
        }
        TreeMap<Integer, Sample> exact = new TreeMap<>(), tess = new TreeMap<>();
        read(Path.of(args[0]), exact, tess);
        System.out.println("| degree | exact, ms (min–p90) | tessellated, ms (min–p90) | K | exact / tessellated |");
        System.out.println("|---|---|---|---|---|");
        for (int d : exact.keySet()) {
            Sample e = exact.get(d), t = tess.get(d);
            System.out.printf(Locale.ROOT, "| %d | %s | %s | %d | %s |%n", d, cell(e), cell(t),
                    FrameScenes.equalK("wavy" + (d + 1)),
                    t == null ? "—" : String.format(Locale.ROOT, "%.2f×", e.median() / t.median()));
        }
        plot(exact, tess, Path.of(args[1]));
    }

    private static String cell(Sample s) {
        return s == null ? "—" : String.format(Locale.ROOT, "%.1f (%.1f–%.1f)", s.median(), s.min(), s.p90());
    }

    /** Splits the runs by {@code tessellate} (0 = exact) and keys them by degree. */
    static void read(Path file, TreeMap<Integer, Sample> exact, TreeMap<Integer, Sample> tess) throws IOException {
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            for (JsonElement e : JsonParser.parseReader(r).getAsJsonArray()) {
                JsonObject run = e.getAsJsonObject();
                JsonObject params = run.getAsJsonObject("params");
                JsonObject pc = run.getAsJsonObject("primaryMetric").getAsJsonObject("scorePercentiles");
                Sample s = new Sample(pc.get("50.0").getAsDouble(), pc.get("0.0").getAsDouble(),
                        pc.get("90.0").getAsDouble());
                int degree = params.get("degree").getAsInt();
                ("0".equals(params.get("tessellate").getAsString()) ? exact : tess).put(degree, s);
            }
        }
    }

    /** Line chart: degree on x, ms per frame on y, exact in blue and tessellated in orange. */
    static void plot(TreeMap<Integer, Sample> exact, TreeMap<Integer, Sample> tess, Path out) throws IOException {
        int width = 760, height = 460, left = 70, right = 30, top = 60, bottom = 50;
        int plotW = width - left - right, plotH = height - top - bottom;
        int dMin = exact.firstKey(), dMax = exact.lastKey();
        double yMax = 0;
        for (Sample s : exact.values()) {
            yMax = Math.max(yMax, s.median());
        }
        for (Sample s : tess.values()) {
            yMax = Math.max(yMax, s.median());
        }
        yMax *= 1.15;
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = Plots.canvas(img);
        Font font = new Font(Font.SANS_SERIF, Font.PLAIN, 13);
        g.setFont(font.deriveFont(Font.BOLD, 16f));
        g.setColor(Color.BLACK);
        g.drawString("Cost versus degree: wavy grid frame, 800x600, 1 spp, Phong + shadows", left - 50, 26);
        g.setFont(font);
        FontMetrics fm = g.getFontMetrics();
        g.setColor(Color.DARK_GRAY);
        g.drawString("ms per frame (median; whiskers min..p90), lower is better", left - 50, 46);
        double step = Plots.niceStep(yMax / 6);
        for (double v = 0; v <= yMax; v += step) {
            int y = top + plotH - (int) Math.round(v / yMax * plotH);
            g.setColor(new Color(225, 225, 225));
            g.drawLine(left, y, left + plotW, y);
            g.setColor(Color.GRAY);
            String s = String.format(Locale.ROOT, step >= 1 ? "%.0f" : "%.1f", v);
            g.drawString(s, left - 8 - fm.stringWidth(s), y + fm.getAscent() / 2 - 2);
        }
        for (int d = dMin; d <= dMax; d++) {
            int x = xOf(d, dMin, dMax, left, plotW);
            g.setColor(Color.GRAY);
            String s = Integer.toString(d);
            g.drawString(s, x - fm.stringWidth(s) / 2, top + plotH + 18);
        }
        g.drawString("degree (n = m)", left + plotW / 2 - 40, top + plotH + 38);
        Color blue = new Color(58, 110, 165), orange = new Color(214, 122, 48);
        series(g, exact, blue, dMin, dMax, left, top, plotW, plotH, yMax);
        series(g, tess, orange, dMin, dMax, left, top, plotW, plotH, yMax);
        g.setColor(blue);
        g.fillRect(left + 10, top + 6, 14, 4);
        g.setColor(Color.BLACK);
        g.drawString("exact", left + 30, top + 12);
        g.setColor(orange);
        g.fillRect(left + 10, top + 24, 14, 4);
        g.setColor(Color.BLACK);
        g.drawString("tessellated at equal accuracy (K per degree)", left + 30, top + 30);
        g.dispose();
        Files.createDirectories(out.toAbsolutePath().getParent());
        ImageIO.write(img, "png", out.toFile());
        System.err.println("wrote " + out);
    }

    private static void series(Graphics2D g, TreeMap<Integer, Sample> data, Color color, int dMin, int dMax,
                               int left, int top, int plotW, int plotH, double yMax) {
        g.setColor(color);
        int px = -1, py = -1;
        for (var e : data.entrySet()) {
            int x = xOf(e.getKey(), dMin, dMax, left, plotW);
            Sample s = e.getValue();
            int y = yOf(s.median(), top, plotH, yMax);
            g.setStroke(new BasicStroke(1f));
            g.drawLine(x, yOf(s.min(), top, plotH, yMax), x, yOf(s.p90(), top, plotH, yMax));
            g.setStroke(new BasicStroke(2.5f));
            if (px >= 0) {
                g.drawLine(px, py, x, y);
            }
            g.fillOval(x - 4, y - 4, 8, 8);
            px = x;
            py = y;
        }
    }

    private static int xOf(int d, int dMin, int dMax, int left, int plotW) {
        return left + (int) Math.round((d - dMin + 0.5) / (dMax - dMin + 1) * plotW);
    }

    private static int yOf(double v, int top, int plotH, double yMax) {
        return top + plotH - (int) Math.round(Math.min(v, yMax) / yMax * plotH);
    }
}
