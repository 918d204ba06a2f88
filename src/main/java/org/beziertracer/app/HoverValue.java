package org.beziertracer.app;

import java.util.concurrent.Executor;
import java.util.function.Supplier;

import org.beziertracer.render.AnalysisProbe;
import org.beziertracer.render.RenderJob;

/**
 * The analysis view's value under the mouse, for the status bar: each {@link #request} (UI
 * thread, constant time) hands the pixel to a worker through {@link Coalescing}, which traces
 * it in the job of the picture shown ({@link AnalysisProbe}); while the mouse moves only the
 * newest position is traced, and its text arrives on the UI thread.
 */
public final class HoverValue {

    private record Request(RenderJob job, double x, double y) {}

    private final Executor ui;
    private final Runnable onChange;
    private final Supplier<RenderJob> jobs;
    private final Coalescing<Request> work;
    // UI thread only
    private String text = "";

    HoverValue(Executor worker, Executor ui, Supplier<RenderJob> jobs, Runnable onChange) {
        this.ui = ui;
        this.jobs = jobs;
        this.onChange = onChange;
        this.work = new Coalescing<>(worker, r -> show(AnalysisProbe.at(r.job(), r.x(), r.y())), e -> show(""));
    }

    /** The text for the last position traced ("" when none, or off the surface). */
    public String text() { return text; }

    /** True while a position waits or is traced (tests wait on this). */
    public boolean busy() { return work.busy(); }

    /** The mouse is at {@code (x, y)} picture pixels, or left the picture ({@code NaN}). */
    void request(double x, double y) {
        RenderJob job = jobs.get();
        if (job == null || !job.shading().isAnalysis() || Double.isNaN(x)) {
            if (!text.isEmpty()) {
                text = "";
                onChange.run();
            }
            return;
        }
        work.submit(new Request(job, x, y));
    }

    private void show(String s) {
        ui.execute(() -> {
            if (!s.equals(text)) {
                text = s;
                onChange.run();
            }
        });
    }
}
