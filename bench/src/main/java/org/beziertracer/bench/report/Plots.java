package org.beziertracer.bench.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import javax.imageio.ImageIO;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Bar charts from JMH JSON results (plain Java 2D, written as PNG). One chart per input file:
 * a bar per (benchmark method, parameter set), the primary score with its 99.9 % error as a
 * whisker (clipped at the chart's edge, 1.3× the largest bar). With {@code --rays}, time per ray ({@code ns/op}) is converted to millions of rays per
 * second (the error interval converted end to end). Sample-time results ({@code -bm sample}, e.g.
 * {@code FrameBench}) are drawn as the <b>median</b> with a whisker from the fastest sample to the
 * 90th percentile (JMH's percentiles), since the mean of a noisy shared machine is skewed.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.Plots \
 *     [--rays] [--title "..."] bench/results/scene.json docs/perf/scene.png
 * </pre>
 * Several {@code INPUT OUTPUT} pairs may follow the options, which apply to all of them.
 */
public final class Plots {
    private Plots() {}

    /** One bar. */
    record Bar(String label, double value, double lo, double hi) {}

    public static void main(String[] args) throws IOException {
        boolean rays = false;
        String title = null;
        List<String> files = new ArrayList<>();
        for (int k = 0; k < args.length; k++) {
            switch (args[k]) {
                case "--rays" -> rays = true;
                case "--title" -> title = args[++k];
                default -> files.add(args[k]);
            }
        }
        if (files.isEmpty() || files.size() % 2 != 0) {
            System.err.println("usage: Plots [--rays] [--title T] INPUT.json OUTPUT.png [INPUT OUTPUT ...]");
            System.exit(2);
        }
        for (int k = 0; k < files.size(); k += 2) {
            Path in = Path.of(files.get(k)), out = Path.of(files.get(k + 1));
            List<Bar> bars = new ArrayList<>();
            String unit = read(in, rays, bars);
            String t = title != null ? title : in.getFileName().toString().replace(".json", "");
            write(bars, t, rays ? "million rays/s (higher is better)" : unit + " (lower is better)", out);
            System.out.println("wrote " + out + " (" + bars.size() + " bars)");
        }
    }

    /** Reads the bars of one JMH JSON file; returns the score unit. */
    static String read(Path file, boolean rays, List<Bar> bars) throws IOException {
        JsonArray runs;
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            runs = JsonParser.parseReader(r).getAsJsonArray();
        }
        String unit = "";
        for (JsonElement e : runs) {
            JsonObject run = e.getAsJsonObject();
            String name = run.get("benchmark").getAsString();
            name = name.substring(name.lastIndexOf('.', name.lastIndexOf('.') - 1) + 1);
            StringBuilder label = new StringBuilder(name);
            if (run.has("params")) {
                Map<String, String> params = new TreeMap<>();
                for (Map.Entry<String, JsonElement> p : run.getAsJsonObject("params").entrySet()) {
                    params.put(p.getKey(), p.getValue().getAsString());
                }
                for (Map.Entry<String, String> p : params.entrySet()) {
                    label.append(' ').append(p.getKey()).append('=').append(p.getValue());
                }
            }
            JsonObject primary = run.getAsJsonObject("primaryMetric");
            if ("sample".equals(run.has("mode") ? run.get("mode").getAsString() : "")
                    && primary.has("scorePercentiles") && !rays) {
                JsonObject pc = primary.getAsJsonObject("scorePercentiles");
                unit = primary.get("scoreUnit").getAsString();
                bars.add(new Bar(label.toString(), pc.get("50.0").getAsDouble(), pc.get("0.0").getAsDouble(),
                        pc.get("90.0").getAsDouble()));
                continue;
            }
            double score = primary.get("score").getAsDouble();
            double err = primary.get("scoreError").isJsonPrimitive()
                    && !Double.isNaN(primary.get("scoreError").getAsDouble()) ? primary.get("scoreError").getAsDouble() : 0;
            unit = primary.get("scoreUnit").getAsString();
            if (rays) {
                double perNs = nanosPerOp(unit);
                // time per ray -> million rays per second
                double v = 1e3 / (score * perNs);
                double lo = 1e3 / ((score + err) * perNs), hi = err < score ? 1e3 / ((score - err) * perNs) : v;
                bars.add(new Bar(label.toString(), v, lo, hi));
            } else {
                bars.add(new Bar(label.toString(), score, score - err, score + err));
            }
        }
        return unit;
    }

    private static double nanosPerOp(String unit) {
        return switch (unit) {
            case "ns/op" -> 1;
            case "us/op" -> 1e3;
            case "ms/op" -> 1e6;
            case "s/op" -> 1e9;
            default -> throw new IllegalArgumentException("--rays needs a time per op, got " + unit);
        };
    }

    /** Horizontal bar chart, one row per bar, value printed at the bar's end. */
    static void write(List<Bar> bars, String title, String axis, Path out) throws IOException {
        int rowH = 26, top = 56, bottom = 40, left = 20, right = 110, barArea = 460;
        Font font = new Font(Font.SANS_SERIF, Font.PLAIN, 13), bold = font.deriveFont(Font.BOLD, 16f);
        BufferedImage probe = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        FontMetrics fm = probe.createGraphics().getFontMetrics(font);
        int labelW = 0;
        for (Bar b : bars) {
            labelW = Math.max(labelW, fm.stringWidth(b.label()));
        }
        int width = left + labelW + 12 + barArea + right, height = top + rowH * bars.size() + bottom;
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = canvas(img);
        g.setColor(Color.BLACK);
        g.setFont(bold);
        g.drawString(title, left, 26);
        g.setFont(font);
        g.setColor(Color.DARK_GRAY);
        g.drawString(axis, left, 46);
        // Axis from the values; whiskers wider than the chart (noisy runs) are clipped at its edge
        double max = 0;
        for (Bar b : bars) {
            max = Math.max(max, b.value());
        }
        max *= 1.3;
        if (!(max > 0)) {
            max = 1;
        }
        int x0 = left + labelW + 12;
        // Grid lines at nice steps
        double step = niceStep(max / 5);
        g.setStroke(new BasicStroke(1f));
        for (double v = 0; v <= max * 1.0001; v += step) {
            int x = x0 + (int) Math.round(v / max * barArea);
            g.setColor(new Color(225, 225, 225));
            g.drawLine(x, top - 4, x, top + rowH * bars.size());
            g.setColor(Color.GRAY);
            String s = format(v);
            g.drawString(s, x - fm.stringWidth(s) / 2, top + rowH * bars.size() + 16);
        }
        Color[] palette = {new Color(58, 110, 165), new Color(214, 122, 48), new Color(80, 150, 90),
                new Color(170, 70, 70), new Color(120, 90, 160), new Color(110, 110, 110)};
        Map<String, Integer> methodColor = new TreeMap<>();
        for (int i = 0; i < bars.size(); i++) {
            Bar b = bars.get(i);
            int y = top + i * rowH;
            String method = b.label().split(" ")[0];
            Integer c = methodColor.get(method);
            if (c == null) {
                c = methodColor.size() % palette.length;
                methodColor.put(method, c);
            }
            g.setColor(Color.BLACK);
            g.drawString(b.label(), left, y + rowH / 2 + fm.getAscent() / 2 - 2);
            int w = (int) Math.round(b.value() / max * barArea);
            g.setColor(palette[c]);
            g.fillRect(x0, y + 4, Math.max(w, 1), rowH - 8);
            // Error whisker
            g.setColor(Color.BLACK);
            int xl = x0 + (int) Math.round(Math.max(0, b.lo()) / max * barArea);
            int xh = x0 + (int) Math.round(Math.min(max, b.hi()) / max * barArea);
            int ym = y + rowH / 2;
            g.drawLine(xl, ym, xh, ym);
            g.drawLine(xl, ym - 4, xl, ym + 4);
            g.drawLine(xh, ym - 4, xh, ym + 4);
            g.drawString(format(b.value()), Math.max(x0 + w, xh) + 6, ym + fm.getAscent() / 2 - 2);
        }
        g.setTransform(new AffineTransform());
        g.dispose();
        Files.createDirectories(out.toAbsolutePath().getParent());
        ImageIO.write(img, "png", out.toFile());
    }

    /** Graphics on {@code img}, antialiased (shapes and text), the image filled white. */
    static Graphics2D canvas(BufferedImage img) {
        Graphics2D g = img.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, img.getWidth(), img.getHeight());
        return g;
    }

    static double niceStep(double raw) {
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        double f = raw / p;
        return (f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10) * p;
    }

    private static String format(double v) {
        double a = Math.abs(v);
        String f = a >= 100 ? "%.0f" : a >= 10 ? "%.1f" : a >= 1 ? "%.2f" : "%.3f";
        return String.format(Locale.ROOT, f, v);
    }
}
