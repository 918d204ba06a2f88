package org.beziertracer.app;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.function.Consumer;

import org.beziertracer.geometry.Patches;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * View → Continuity, kept up to date: each {@link #request} (UI thread, constant time) hands the
 * model and the tolerances to a worker through {@link Coalescing}, which certifies every shared
 * border ({@link ContinuityAnalysis}) and samples each border curve for the marks on the view; the
 * result arrives on the UI thread. A request for the model and tolerances already analysed (a
 * camera move, a new picture) costs nothing. While it runs the status bar shows the borders done
 * of all ({@link Task#progress(long, long, String)}) with Cancel; a newer request, View → Continuity
 * off or Cancel stops it before its next border ({@link ContinuityAnalysis#analyze(Scene,
 * ContinuityAnalysis.Tolerances, ContinuityAnalysis.Progress, java.util.function.BooleanSupplier)}),
 * and a cancelled model is not analysed again until it or the tolerances change or the view is
 * switched on again.
 */
public final class ContinuityModel {

    /** Points sampled along a border curve for its mark. */
    static final int MARK_POINTS = 24;

    /**
     * A finished analysis and, per row, its border curve in world space.
     *
     * @param result the analysis, worst border first
     * @param curves {@code curves.get(i)}: {@code 3·MARK_POINTS} coordinates along row i's border
     */
    public record Shown(ContinuityAnalysis.Result result, List<double[]> curves) {}

    private record Request(Scene scene, ContinuityAnalysis.Tolerances tolerances) {}

    private final Executor ui;
    private final StatusModel status;
    private final Runnable onChange;
    private final Coalescing<Request> work;
    // UI thread only
    private Request wanted;
    /** The analysis the user cancelled: not started again for the same model and tolerances. */
    private Request dismissed;
    private Shown current;
    /** The newest request, read by the worker to stop a superseded analysis. */
    private volatile Request latest;
    private ContinuityAnalysis.Tolerances tolerances;

    ContinuityModel(Executor worker, Executor ui, StatusModel status, Runnable onChange, Consumer<Throwable> failed) {
        this.ui = ui;
        this.status = status;
        this.onChange = onChange;
        this.work = new Coalescing<>(worker, this::compute, e -> ui.execute(() -> {
            wanted = null;
            failed.accept(e);
        }));
    }

    /** The analysis of the newest request, or null while it runs (or when none was asked for). */
    public Shown current() { return current; }

    /** True while an analysis waits, runs or has its result on the way (tests wait on this). */
    public boolean busy() { return work.busy() || wanted != null && current == null; }

    /** The tolerances in force: the user's, or null for each model's defaults. */
    public ContinuityAnalysis.Tolerances tolerances() { return tolerances; }

    /** New tolerances (null: the model's defaults); the next {@link #request} uses them. */
    void tolerances(ContinuityAnalysis.Tolerances t) { tolerances = t; }

    /** Analyse {@code scene} (unless it is the one analysed, with the same tolerances). */
    void request(Scene scene) {
        ContinuityAnalysis.Tolerances t = tolerances != null ? tolerances : ContinuityAnalysis.Tolerances.defaults(scene);
        Request r = new Request(scene, t);
        if (same(wanted, r) || same(dismissed, r)) {
            return;
        }
        dismissed = null;
        wanted = r;
        latest = r;
        work.submit(r);
    }

    /** View → Continuity off: forget the analysis. */
    void clear() {
        wanted = null;
        latest = null;
        dismissed = null;
        if (current != null) {
            current = null;
            onChange.run();
        }
    }

    private static boolean same(Request a, Request b) {
        return a != null && a.scene() == b.scene() && a.tolerances().equals(b.tolerances());
    }

    private void compute(Request r) {
        if (latest != r) {
            return; // superseded before it started
        }
        Task task = new Task("analysing continuity");
        ui.execute(() -> {
            if (status.task() == null) { // never hides an open's or a save's bar
                status.task(task);
            }
        });
        ContinuityAnalysis.Result result;
        try {
            result = ContinuityAnalysis.analyze(r.scene(), r.tolerances(),
                    (done, total) -> task.progress(done, total, "borders"), () -> task.isCancelled() || latest != r);
        } catch (java.util.concurrent.CancellationException e) {
            ui.execute(() -> {
                status.endTask(task);
                if (task.isCancelled() && wanted == r) {
                    wanted = null;
                    dismissed = r;
                    status.message("continuity analysis cancelled");
                }
            });
            return;
        }
        ui.execute(() -> status.endTask(task));
        List<double[]> curves = result.rows().stream()
                .map(row -> curve(r.scene().patches().get(row.border().a()), row.border().sideA())).toList();
        Shown shown = new Shown(result, curves);
        ui.execute(() -> {
            if (wanted == r) {
                current = shown;
                onChange.run();
            }
        });
    }

    /** {@link #MARK_POINTS} points along side {@code side} ({@code u=0, u=1, v=0, v=1}) of {@code patch}. */
    static double[] curve(BezierPatch patch, int side) {
        double[] out = new double[3 * MARK_POINTS];
        for (int k = 0; k < MARK_POINTS; k++) {
            double t = k / (MARK_POINTS - 1.0);
            double u = side == 0 ? 0 : side == 1 ? 1 : t, v = side == 2 ? 0 : side == 3 ? 1 : t;
            Vec3 p = Patches.evaluate(patch, u, v);
            out[3 * k] = p.x();
            out[3 * k + 1] = p.y();
            out[3 * k + 2] = p.z();
        }
        return out;
    }
}
