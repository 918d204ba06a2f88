package org.beziertracer.cli;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.beziertracer.app.ContinuityAnalysis;
import org.beziertracer.app.ContinuityAnalysis.Continuity;
import org.beziertracer.app.ContinuityAnalysis.Row;
import org.beziertracer.app.ContinuityAnalysis.Tolerances;
import org.beziertracer.geometry.BorderContinuity;
import org.beziertracer.geometry.BorderStrip;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;

import com.google.gson.GsonBuilder;
import com.google.gson.JsonArray;
import com.google.gson.JsonObject;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code analyze MODEL_OR_SCENE}: continuity across every border two patches share
 * ({@link ContinuityAnalysis}): the certified largest gap (G0), normal angle (G1, degrees) and
 * normal-curvature mismatch (G2) of each border, where along the border (t, 0..1 from the first
 * patch's side) the worst values lie, and its class by the tolerances. Worst borders first, then a
 * summary:
 * <pre>
 * model: teapot (32 patches, size 246.6)
 * tolerances: g0 2.466e-07, g1 0.1°, g2 4.055e-06
 * patch side  patch side  flip        g0   at t     g1 (°)   at t        g2   at t  class  notes
 *     1 u=1       2 u=0   no    0.000e+00   0.000  0.000e+00  0.000  0.000e+00  0.000  G2
 * …
 * summary: 40 borders: 8 G2, 28 G1, 4 G0, 0 open
 * </pre>
 * Patches are numbered from 1, as {@code info} numbers them. {@code --json} prints an array, one
 * object a border instead. A file that cannot be read ends the command with one error line and
 * exit code 1 ({@link CliErrors}).
 */
@Command(name = "analyze", mixinStandardHelpOptions = true,
        description = "Continuity across the borders patches share (welded as the editor welds them): the certified "
                + "largest gap (G0), normal angle (G1) and curvature mismatch (G2) of each border, and its class.")
final class AnalyzeCommand implements Callable<Integer> {

    @Parameters(index = "0", paramLabel = "MODEL_OR_SCENE", descriptionKey = CliText.INPUT)
    String model;

    @Option(names = "--json", description = "print a JSON array, one object a border")
    boolean json;

    @Option(names = "--g0", paramLabel = "TOL", description = "largest gap of a G0 border, model units "
            + "(default: the weld tolerance, 1e-9 of the model size)")
    Double g0;

    @Option(names = "--g1", paramLabel = "DEGREES", description = "largest normal angle of a G1 border, degrees "
            + "(default: " + Tolerances.G1_DEGREES + ")")
    Double g1;

    @Option(names = "--g2", paramLabel = "TOL", description = "largest curvature mismatch of a G2 border, 1/model units "
            + "(default: " + Tolerances.G2_RELATIVE + " / model size)")
    Double g2;

    @Option(names = {"-q", "--quiet"}, description = "no progress bar (shown on standard error only when it is a terminal)")
    boolean quiet;

    /** Columns of the terminal on standard error, 0 when it is not a terminal; tests replace it. */
    java.util.function.IntSupplier stderrColumns = StandardError::terminalColumns;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        Scene scene = ReadNotes.show(SceneFiles.load(model), spec.commandLine().getErr()).scene();
        Tolerances d = Tolerances.defaults(scene);
        Tolerances tol = new Tolerances(check("--g0", g0, d.g0()), check("--g1", g1, d.g1Degrees()),
                check("--g2", g2, d.g2()));
        long start = System.nanoTime();
        ContinuityAnalysis.Result result;
        int columns = quiet ? 0 : stderrColumns.getAsInt();
        if (columns == 0) {
            result = ContinuityAnalysis.analyze(scene, tol);
        } else {
            // The bar starts when the borders are found, so its first frame shows their total
            ProgressBarDisplay[] bar = {null};
            try {
                result = ContinuityAnalysis.analyze(scene, tol, (done, total) -> {
                    if (bar[0] == null) {
                        bar[0] = new ProgressBarDisplay(spec.commandLine().getErr(), columns, 1, total, "analyze",
                                " borders", 1);
                    }
                    bar[0].progress(0, done, total);
                });
            } finally {
                if (bar[0] != null) {
                    bar[0].close();
                }
            }
        }
        double millis = (System.nanoTime() - start) / 1e6;
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            out.println(new GsonBuilder().setPrettyPrinting().disableHtmlEscaping().create().toJson(json(result)));
        } else {
            table(out, model, scene, result, millis);
        }
        out.flush();
        return 0;
    }

    private static double check(String option, Double value, double fallback) {
        if (value == null) {
            return fallback;
        }
        if (!(value >= 0) || value.isInfinite()) {
            throw new IllegalArgumentException(option + " must be a finite number ≥ 0, got " + value);
        }
        return value;
    }

    static void table(PrintWriter out, String name, Scene scene, ContinuityAnalysis.Result result, double millis) {
        Tolerances tol = result.tolerances();
        out.println(String.format(Locale.ROOT, "model: %s (%d patches, size %.4g)", name, scene.patchCount(), result.size()));
        out.println(String.format(Locale.ROOT, "tolerances: g0 %.3e, g1 %s°, g2 %.3e", tol.g0(),
                stripZeros(tol.g1Degrees()), tol.g2()));
        out.println("patch side  patch side  flip        g0   at t     g1 (°)   at t        g2   at t  class  notes");
        for (Row r : result.rows()) {
            BorderContinuity.Report p = r.report();
            out.println(String.format(Locale.ROOT, "%5d %-4s  %5d %-4s  %-4s %10s  %5.3f %10s  %5.3f %10s  %5.3f  %-5s  %s",
                    r.border().a() + 1, BorderStrip.SIDE_NAMES[r.border().sideA()],
                    r.border().b() + 1, BorderStrip.SIDE_NAMES[r.border().sideB()], p.flipped() ? "yes" : "no",
                    number(p.g0().bound()), p.g0().t(), number(r.g1Degrees()), p.g1().t(),
                    number(p.g2().bound()), p.g2().t(), r.continuity().label(), notes(p)));
        }
        out.println(String.format(Locale.ROOT, "summary: %d borders: %d G2, %d G1, %d G0, %d open (analysed in %.0f ms)",
                result.rows().size(), result.count(Continuity.G2), result.count(Continuity.G1),
                result.count(Continuity.G0), result.count(Continuity.GAP), millis));
        if (result.arcPairs() > 0) {
            out.println(result.arcPairs() + " pairs of sides share their corners but part by more than half their chord: "
                    + "arcs of one loop, not borders (left out)");
        }
    }

    /** What the numbers do not say: degenerate normals, a sampled G2, a bound not within 1 %. */
    private static String notes(BorderContinuity.Report p) {
        StringBuilder sb = new StringBuilder();
        double[] deg = union(p.g1().degenerate(), p.g2().degenerate());
        if (deg.length > 0) {
            sb.append("degenerate normal at t=");
            for (int k = 0; k < deg.length; k++) {
                sb.append(k == 0 ? "" : ",").append(stripZeros(deg[k]));
            }
        }
        if (!p.g2().certified()) {
            sb.append(sb.length() > 0 ? "; " : "").append("g2 sampled (rational)");
        }
        if (!p.g0().tight() || !p.g1().tight() || (p.g2().certified() && !p.g2().tight())) {
            sb.append(sb.length() > 0 ? "; " : "").append("bound not within 1% of samples");
        }
        return sb.toString();
    }

    static JsonArray json(ContinuityAnalysis.Result result) {
        JsonArray rows = new JsonArray();
        for (Row r : result.rows()) {
            BorderContinuity.Report p = r.report();
            JsonObject o = new JsonObject();
            o.addProperty("patchA", r.border().a() + 1);
            o.addProperty("sideA", BorderStrip.SIDE_NAMES[r.border().sideA()]);
            o.addProperty("patchB", r.border().b() + 1);
            o.addProperty("sideB", BorderStrip.SIDE_NAMES[r.border().sideB()]);
            o.addProperty("reversed", r.border().reversed());
            o.addProperty("flipped", p.flipped());
            o.addProperty("class", r.continuity().label());
            put(o, "g0", p.g0().bound(), p.g0());
            put(o, "g1", r.g1Degrees(), p.g1());
            put(o, "g2", p.g2().bound(), p.g2());
            JsonArray deg = new JsonArray();
            for (double t : union(p.g1().degenerate(), p.g2().degenerate())) {
                deg.add(t);
            }
            o.add("degenerateAt", deg);
            rows.add(o);
        }
        return rows;
    }

    /** {@code name}: the bound (null when none), {@code nameAt}: where the worst sample lies, {@code nameCertified}. */
    private static void put(JsonObject o, String name, double value, BorderContinuity.Bound b) {
        o.addProperty(name, Double.isFinite(value) ? value : null);
        o.addProperty(name + "At", b.t());
        o.addProperty(name + "Certified", b.certified());
    }

    private static String number(double v) {
        return Double.isFinite(v) ? String.format(Locale.ROOT, "%.3e", v) : Double.isNaN(v) ? "n/a" : "inf";
    }

    private static String stripZeros(double v) {
        return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }

    private static double[] union(double[] x, double[] y) {
        return java.util.stream.DoubleStream.concat(java.util.Arrays.stream(x), java.util.Arrays.stream(y))
                .map(t -> Math.round(t * 1e6) / 1e6).distinct().sorted().toArray();
    }
}
