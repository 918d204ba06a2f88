package org.beziertracer.app;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BooleanSupplier;
import java.util.stream.IntStream;

import org.beziertracer.geometry.BorderContinuity;
import org.beziertracer.model.Scene;

/**
 * Continuity across every border of a model: finds the borders as the editor welds them
 * ({@link SharedBorders}, {@link WeldIndex}), bounds the gap, normal angle and curvature mismatch
 * of each ({@link BorderContinuity}) and classes it by the given tolerances. Lives in {@code app}
 * because the border finding reuses the editor's weld index (its tolerance rule and union–find of
 * coincident points); the certified bounds themselves are {@code geometry}.
 *
 * <p>Stateless; the result is immutable.
 */
public final class ContinuityAnalysis {

    private ContinuityAnalysis() {}

    /**
     * What counts as continuous.
     *
     * @param g0        largest gap, model units
     * @param g1Degrees largest normal angle, degrees
     * @param g2        largest curvature mismatch, 1/model units
     */
    public record Tolerances(double g0, double g1Degrees, double g2) {

        /** Default G1 tolerance, degrees. */
        public static final double G1_DEGREES = 0.1;
        /** Default G2 tolerance times the model size. */
        public static final double G2_RELATIVE = 1e-3;

        /**
         * The defaults for {@code scene}: G0 the weld tolerance ({@link WeldIndex#tolerance}),
         * G1 {@value #G1_DEGREES}°, G2 {@value #G2_RELATIVE} over the model size.
         */
        public static Tolerances defaults(Scene scene) {
            double size = size(scene);
            return new Tolerances(WeldIndex.tolerance(scene), G1_DEGREES, size > 0 ? G2_RELATIVE / size : G2_RELATIVE);
        }
    }

    /** The class of a border, best first. */
    public enum Continuity {
        /** Curvature-continuous: gap, angle and curvature mismatch within tolerance. */
        G2,
        /** Tangent-continuous: gap and angle within tolerance. */
        G1,
        /** Position-continuous: only the gap within tolerance. */
        G0,
        /** The sides part by more than the G0 tolerance. */
        GAP;

        /** Lower-case name for the report ({@code g2, g1, g0, gap}). */
        public String label() { return this == GAP ? "gap" : name(); }
    }

    /**
     * One border.
     *
     * @param border     the two sides
     * @param report     the bounds
     * @param continuity its class
     */
    public record Row(SharedBorders.Border border, BorderContinuity.Report report, Continuity continuity) {

        /** G1 bound in degrees. */
        public double g1Degrees() { return Math.toDegrees(report.g1().bound()); }
    }

    /**
     * The analysis of a model.
     *
     * @param rows       one a border, worst first (by class, then by the measure that decides it)
     * @param tolerances the tolerances used
     * @param size       the model size (diagonal of its control box)
     * @param arcPairs   pairs of sides with welded corners that are arcs of one loop, not borders ({@link SharedBorders})
     */
    public record Result(List<Row> rows, Tolerances tolerances, double size, int arcPairs) {

        /** Number of borders of class {@code c}. */
        public long count(Continuity c) {
            return rows.stream().filter(r -> r.continuity() == c).count();
        }
    }

    /** Analyses every border of {@code scene}. */
    public static Result analyze(Scene scene, Tolerances tol) {
        return analyze(scene, tol, (done, total) -> { });
    }

    /** Borders done and in all, as an analysis goes (from any of its threads). */
    @FunctionalInterface
    public interface Progress {
        void progress(long done, long total);
    }

    /** Models with at least this many borders are analysed in parallel (the borders are independent). */
    static final int PARALLEL_BORDERS = 64;

    /**
     * As {@link #analyze(Scene, Tolerances)}, telling {@code progress} the total as soon as the
     * borders are found ({@code (0, total)}), then every {@value #PROGRESS_STEP} borders and at
     * the end; the borders of a big model are bounded in parallel, the rows the same on any number
     * of threads (sorted worst first).
     */
    public static Result analyze(Scene scene, Tolerances tol, Progress progress) {
        return analyze(scene, tol, progress, () -> false);
    }

    /**
     * As {@link #analyze(Scene, Tolerances, Progress)}, stopping with a
     * {@link CancellationException} once {@code cancelled} says so: it is asked every
     * {@value WeldIndex#CANCEL_STEP} patches while welding points and finding borders, between the
     * phases, and before each border, so a cancelled analysis bounds at most one more border per thread.
     */
    public static Result analyze(Scene scene, Tolerances tol, Progress progress, BooleanSupplier cancelled) {
        WeldIndex welds = WeldIndex.build(scene, cancelled);
        stopIf(cancelled);
        double size = size(scene);
        SharedBorders.Found found = SharedBorders.find(scene, welds, cancelled);
        stopIf(cancelled);
        List<SharedBorders.Border> borders = found.borders();
        int n = borders.size();
        progress.progress(0, n);
        AtomicLong done = new AtomicLong();
        IntStream all = IntStream.range(0, n);
        List<Row> rows = new ArrayList<>((n >= PARALLEL_BORDERS ? all.parallel() : all).mapToObj(k -> {
            stopIf(cancelled);
            SharedBorders.Border b = borders.get(k);
            BorderContinuity.Report r = BorderContinuity.analyze(scene.patches().get(b.a()), b.sideA(),
                    scene.patches().get(b.b()), b.sideB(), b.reversed(), size);
            long d = done.incrementAndGet();
            if (d % PROGRESS_STEP == 0) {
                progress.progress(d, n);
            }
            return new Row(b, r, classify(r, tol));
        }).toList());
        progress.progress(n, n);
        rows.sort(WORST_FIRST);
        return new Result(List.copyOf(rows), tol, size, found.arcPairs());
    }

    /** Throws a {@link CancellationException} when {@code cancelled} says so. */
    static void stopIf(BooleanSupplier cancelled) {
        if (cancelled.getAsBoolean()) {
            throw new CancellationException("the continuity analysis was cancelled");
        }
    }

    /** Borders between two progress reports. */
    static final int PROGRESS_STEP = 256;

    /** The class of a border by the tolerances; a measure that could not be bounded (NaN) fails. */
    static Continuity classify(BorderContinuity.Report r, Tolerances tol) {
        if (!(r.g0().bound() <= tol.g0())) {
            return Continuity.GAP;
        }
        if (!(Math.toDegrees(r.g1().bound()) <= tol.g1Degrees())) {
            return Continuity.G0;
        }
        return r.g2().bound() <= tol.g2() ? Continuity.G2 : Continuity.G1;
    }

    /** Class first (gap before G0 before G1 before G2), then the deciding measure, largest first, then patches. */
    private static final Comparator<Row> WORST_FIRST = Comparator
            .comparing((Row r) -> -r.continuity().ordinal())
            .thenComparingDouble(r -> -deciding(r))
            .thenComparingInt(r -> r.border().a())
            .thenComparingInt(r -> r.border().sideA())
            .thenComparingInt(r -> r.border().b())
            .thenComparingInt(r -> r.border().sideB());

    private static double deciding(Row r) {
        BorderContinuity.Report p = r.report();
        double v = switch (r.continuity()) {
            case GAP -> p.g0().bound();
            case G0 -> p.g1().bound();
            case G1, G2 -> p.g2().bound();
        };
        return Double.isNaN(v) ? Double.POSITIVE_INFINITY : v;
    }

    private static double size(Scene scene) {
        return scene.patchCount() == 0 ? 0 : scene.controlBounds().diagonal();
    }
}
