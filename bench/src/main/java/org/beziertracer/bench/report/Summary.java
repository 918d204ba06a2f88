package org.beziertracer.bench.report;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Markdown table of JMH JSON results: per (benchmark, params) the mean ± 99.9 % error, the
 * median and minimum of the measurement iterations, and, for time per ray, the median in rays/s.
 * The median resists the noise of a shared machine better than the mean. Sample-time results
 * ({@code FrameBench}) take median and minimum from JMH's percentiles, and the last column is
 * frames (ops) per second at the median.
 * <pre>java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.Summary bench/results/scene.json</pre>
 */
public final class Summary {
    private Summary() {}

    public static void main(String[] args) throws IOException {
        for (String file : args) {
            JsonArray runs;
            try (Reader r = Files.newBufferedReader(Path.of(file), StandardCharsets.UTF_8)) {
                runs = JsonParser.parseReader(r).getAsJsonArray();
            }
            System.out.println("### " + file);
            System.out.println("| benchmark | params | mean ± error | median | min | median ops/s (rays/s for ray loops) | B/op |");
            System.out.println("|---|---|---|---|---|---|---|");
            for (JsonElement e : runs) {
                JsonObject run = e.getAsJsonObject();
                String name = run.get("benchmark").getAsString();
                name = name.substring(name.lastIndexOf('.', name.lastIndexOf('.') - 1) + 1);
                Map<String, String> params = new TreeMap<>();
                if (run.has("params")) {
                    for (Map.Entry<String, JsonElement> p : run.getAsJsonObject("params").entrySet()) {
                        params.put(p.getKey(), p.getValue().getAsString());
                    }
                }
                JsonObject pm = run.getAsJsonObject("primaryMetric");
                String unit = pm.get("scoreUnit").getAsString();
                List<Double> raw = new ArrayList<>();
                if (!pm.has("rawData") && pm.has("scorePercentiles")) {
                    // Sample-time mode: JMH keeps a histogram; its percentiles give median and min
                    JsonObject pc = pm.getAsJsonObject("scorePercentiles");
                    double err = pm.get("scoreError").getAsDouble();
                    double median = pc.get("50.0").getAsDouble();
                    System.out.printf(Locale.ROOT, "| %s | %s | %.4g ± %.2g %s | %.4g | %.4g | %s | %s |%n", name,
                            params.toString().replaceAll("[{}]", ""), pm.get("score").getAsDouble(),
                            Double.isNaN(err) ? 0 : err, unit, median, pc.get("0.0").getAsDouble(),
                            String.format(Locale.ROOT, "%,.1f", unitsPerSecond(unit) / median), "");
                    continue;
                }
                for (JsonElement fork : pm.getAsJsonArray("rawData")) {
                    for (JsonElement x : fork.getAsJsonArray()) {
                        raw.add(x.getAsDouble());
                    }
                }
                Collections.sort(raw);
                int n = raw.size();
                double median = n % 2 == 1 ? raw.get(n / 2) : 0.5 * (raw.get(n / 2 - 1) + raw.get(n / 2));
                String rays = unit.equals("ns/op") ? String.format(Locale.ROOT, "%,.0f", 1e9 / median) : "";
                String alloc = "";
                if (run.has("secondaryMetrics") && run.getAsJsonObject("secondaryMetrics").has("gc.alloc.rate.norm")) {
                    alloc = String.format(Locale.ROOT, "%.3f", run.getAsJsonObject("secondaryMetrics")
                            .getAsJsonObject("gc.alloc.rate.norm").get("score").getAsDouble());
                }
                double err = pm.get("scoreError").getAsDouble();
                System.out.printf(Locale.ROOT, "| %s | %s | %.4g ± %.2g %s | %.4g | %.4g | %s | %s |%n", name,
                        params.toString().replaceAll("[{}]", ""), pm.get("score").getAsDouble(),
                        Double.isNaN(err) ? 0 : err, unit, median, raw.get(0), rays, alloc);
            }
            System.out.println();
        }
    }

    /** Operations per second for a score of 1 in {@code unit} (time per op units only). */
    private static double unitsPerSecond(String unit) {
        return switch (unit) {
            case "ns/op" -> 1e9;
            case "us/op" -> 1e6;
            case "ms/op" -> 1e3;
            case "s/op" -> 1;
            default -> Double.NaN;
        };
    }
}
