package org.beziertracer.bench.report;

import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.beziertracer.bench.FrameScenes;
import org.beziertracer.math.Kernels;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The "issue 32 targets" table of {@code docs/performance.md}, from the JMH JSON and the heap report
 * that {@code bench/report.sh} writes: per case the median exact and tessellated-K frame (SIMD and
 * scalar kernel), their ratio, the figure before the issue, the target and whether it is met (judged
 * on the SIMD column, the kernel the README's launch command gives).
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.TargetsTable \
 *     bench/results/report/frame.json bench/results/report/frame-scalar.json \
 *     bench/results/report/drag.json bench/results/report/build.json bench/results/report/heap-body100000.txt
 * java --add-modules jdk.incubator.vector -cp bench/target/benchmarks.jar \
 *     org.beziertracer.bench.report.TargetsTable --kernel       # the kernel this JVM chooses
 * java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.TargetsTable --jvm-args FILE.json
 * </pre>
 * A missing file leaves its rows "not measured".
 */
public final class TargetsTable {
    private TargetsTable() {}

    /** Median of one JMH run (sample time: JMH's 50th percentile; otherwise the mean), in ms. */
    private static Map<String, Double> medians(Path file) throws IOException {
        Map<String, Double> out = new HashMap<>();
        if (!Files.isRegularFile(file)) {
            return out;
        }
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            for (JsonElement e : JsonParser.parseReader(r).getAsJsonArray()) {
                JsonObject run = e.getAsJsonObject();
                String name = run.get("benchmark").getAsString();
                name = name.substring(name.lastIndexOf('.') + 1);
                Map<String, String> params = new TreeMap<>();
                if (run.has("params")) {
                    for (Map.Entry<String, JsonElement> p : run.getAsJsonObject("params").entrySet()) {
                        params.put(p.getKey(), p.getValue().getAsString());
                    }
                }
                JsonObject pm = run.getAsJsonObject("primaryMetric");
                double median = pm.has("scorePercentiles")
                        ? pm.getAsJsonObject("scorePercentiles").get("50.0").getAsDouble()
                        : pm.get("score").getAsDouble();
                double toMs = switch (pm.get("scoreUnit").getAsString()) {
                    case "ns/op" -> 1e-6;
                    case "us/op" -> 1e-3;
                    case "s/op" -> 1e3;
                    default -> 1;
                };
                out.put(name + params, median * toMs);
            }
        }
        return out;
    }

    /** The forks' JVM arguments recorded in a JMH JSON (the first run's), or "" when absent. */
    private static String jvmArgs(Path file) throws IOException {
        if (!Files.isRegularFile(file)) {
            return "(no file)";
        }
        try (Reader r = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            var runs = JsonParser.parseReader(r).getAsJsonArray();
            if (runs.isEmpty()) {
                return "";
            }
            List<String> args = new ArrayList<>();
            for (JsonElement a : runs.get(0).getAsJsonObject().getAsJsonArray("jvmArgs")) {
                args.add(a.getAsString());
            }
            return String.join(" ", args);
        }
    }

    private static String key(String bench, String... kv) {
        Map<String, String> p = new TreeMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            p.put(kv[i], kv[i + 1]);
        }
        return bench + p;
    }

    private static String ms(Double v) {
        if (v == null) {
            return "not measured";
        }
        return v >= 100 ? String.format(Locale.ROOT, "%,.0f ms", v) : String.format(Locale.ROOT, "%.1f ms", v);
    }

    private static String status(Boolean met) {
        return met == null ? "—" : met ? "**met**" : "missed";
    }

    /** One frame case: medians of exact and tessellated-K in both kernels. */
    private static void frameRow(StringBuilder sb, String label, String scene, Map<String, Double> simd,
            Map<String, Double> scalar, String before, String target, Double maxRatio, Double maxExactMs) {
        String k = String.valueOf(FrameScenes.equalK(scene));
        Double es = simd.get(key("frame", "scene", scene, "tessellate", "0", "threads", "2"));
        Double ts = simd.get(key("frame", "scene", scene, "tessellate", "K", "threads", "2"));
        Double ec = scalar.get(key("frame", "scene", scene, "tessellate", "0", "threads", "2"));
        Double tc = scalar.get(key("frame", "scene", scene, "tessellate", "K", "threads", "2"));
        Double rs = es != null && ts != null ? es / ts : null;
        Double rc = ec != null && tc != null ? ec / tc : null;
        Boolean met = null;
        if (maxRatio != null && rs != null) {
            met = rs <= maxRatio;
        } else if (maxExactMs != null && es != null) {
            met = es <= maxExactMs;
        }
        sb.append(String.format(Locale.ROOT, "| %s | %s | %s (K = %s) | %s | %s | %s | %s | %s | %s | %s |%n", label,
                ms(es), ms(ts), k, ratio(rs), ms(ec), ms(tc), ratio(rc), before, target, status(met)));
    }

    private static String ratio(Double r) {
        return r == null ? "—" : String.format(Locale.ROOT, "%.2f×", r);
    }

    /** A row with one measured figure (not an exact/tessellated pair). */
    private static void singleRow(StringBuilder sb, String label, String measured, String before, String target,
            Boolean met) {
        sb.append(String.format(Locale.ROOT, "| %s | %s | — | — | — | — | — | %s | %s | %s |%n", label, measured, before,
                target, status(met)));
    }

    private static final Pattern HEAP_FRAME = Pattern.compile("build ([0-9,]+) ms \\+ frame ([0-9,]+) ms");
    private static final Pattern HEAP_CPU = Pattern.compile("CPU time build [0-9,]+ ms, frame ([0-9,]+) ms");
    private static final Pattern HEAP_BYTES = Pattern.compile("together ([0-9,]+) a patch");
    private static final Pattern HEAP_BUILD = Pattern.compile("build \\(split \\+ BVH\\): ([0-9,]+) ms");

    private static Double find(Pattern p, String text, int group) {
        Matcher m = p.matcher(text);
        return m.find() ? Double.valueOf(m.group(group).replace(",", "")) : null;
    }

    public static void main(String[] args) throws IOException {
        if (args.length == 1 && args[0].equals("--kernel")) {
            System.out.println(Kernels.best().description());
            return;
        }
        if (args.length == 2 && args[0].equals("--jvm-args")) {
            System.out.println(jvmArgs(Path.of(args[1])));
            return;
        }
        if (args.length != 5) {
            System.err.println("usage: TargetsTable FRAME_SIMD.json FRAME_SCALAR.json DRAG.json BUILD.json HEAP.txt"
                    + " | --kernel | --jvm-args FILE.json");
            System.exit(2);
        }
        Map<String, Double> simd = medians(Path.of(args[0])), scalar = medians(Path.of(args[1]));
        Map<String, Double> drag = medians(Path.of(args[2])), build = medians(Path.of(args[3]));
        Path heapFile = Path.of(args[4]);
        String heap = Files.isRegularFile(heapFile) ? Files.readString(heapFile) : "";

        StringBuilder sb = new StringBuilder();
        sb.append("| case | exact, SIMD | tessellated K, SIMD | ratio, SIMD | exact, scalar | tessellated K, scalar"
                + " | ratio, scalar | before (main 6ff76a6, 2026-12-04) | target | status (SIMD) |\n");
        sb.append("|---|---|---|---|---|---|---|---|---|---|\n");
        frameRow(sb, "10×10-point wavy patch (degree 9)", "wavy10", simd, scalar, "3.5×", "≤ 1.0×", 1.0, null);
        frameRow(sb, "6×6-point wavy patch (degree 5)", "wavy6", simd, scalar, "2.0×", "≤ 1.0×", 1.0, null);
        frameRow(sb, "strongly curved bicubic patch with shadows", "curved", simd, scalar, "1.6–1.9×", "≤ 0.7×", 0.7,
                null);
        frameRow(sb, "default patch, whole frame (exact)", "patch", simd, scalar, "27 ms", "≤ 16 ms", null, 16.0);
        frameRow(sb, "teapot, issue-4 view (for reference; its target is against Sunflow, next row)", "teapot", simd,
                scalar, "—", "—", null, null);
        String sunflow = "not run here: Sunflow is not a dependency; see [performance-journal.md](performance-journal.md)";
        singleRow(sb, "teapot vs Sunflow subdivs 16 (same run)", sunflow, "0.48×", "≤ 0.3×", null);
        singleRow(sb, "Sunflow's curved bicubic patch with shadows vs Sunflow", sunflow, "0.60×", "≤ 0.4×", null);

        Double heapFrame = find(HEAP_FRAME, heap, 2), heapCpu = find(HEAP_CPU, heap, 1);
        singleRow(sb, "100k-patch bumpy surface (`BigModels` body): the frame itself",
                heapFrame == null ? "not measured" : ms(heapFrame) + " wall clock"
                        + (heapCpu == null ? "" : ", " + ms(heapCpu) + " CPU time of the process")
                        + " (the first frame, JIT still warming; one run)",
                "1.35–2.1 s", "≤ 0.5 s", heapFrame == null ? null : heapFrame <= 500);

        Double d0 = drag.get(key("dragFrame", "scene", "wavy10", "tessellate", "0"));
        Double dk = drag.get(key("dragFrame", "scene", "wavy10", "tessellate", "K"));
        String dragText = d0 == null ? "not measured"
                : String.format(Locale.ROOT, "%.1f pictures/s (%s a step)", 1000 / d0, ms(d0))
                        + (dk == null ? "" : String.format(Locale.ROOT, "; tessellated K = %d: %.1f pictures/s",
                                FrameScenes.equalK("wavy10"), 1000 / dk));
        singleRow(sb, "drag on the 10×10 grid, full pictures a second (DragBench p50, exact)", dragText, "13.6", "≥ 24",
                d0 == null ? null : 1000 / d0 >= 24);

        Double t100 = build.get(key("build", "model", "teapots3200"));
        Double t1000 = build.get(key("build", "model", "teapots32000"));
        singleRow(sb, "100 / 1,000 teapots, split + build", ms(t100) + " / " + ms(t1000), "380 / 2,970 ms",
                "≤ 50 / ≤ 400 ms", t100 == null || t1000 == null ? null : t100 <= 50 && t1000 <= 400);

        Double b100k = build.get(key("build", "model", "body100000"));
        Double bytes = find(HEAP_BYTES, heap, 1);
        Double heapBuild = find(HEAP_BUILD, heap, 1);
        String bigText = ms(b100k) + " (SceneBuildBench median"
                + (heapBuild == null ? "" : String.format(Locale.ROOT, "; %,.0f ms in the heap report's one run", heapBuild))
                + "); " + (bytes == null ? "bytes not measured" : String.format(Locale.ROOT, "%,.0f B a patch", bytes));
        singleRow(sb, "100k-patch model: split + BVH build; retained bytes a patch", bigText, "0.8–1.25 s; ~1,980 B",
                "≤ 0.5 s; ≤ 1.5 KB (1,536 B)", b100k == null || bytes == null ? null : b100k <= 500 && bytes <= 1536);
        System.out.print(sb);
    }
}
