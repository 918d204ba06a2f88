package org.beziertracer.app;

import java.util.List;
import java.util.concurrent.Executor;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

/**
 * Where the app's work runs. {@code ui} is the thread that owns all mutable app state (the Swing
 * event thread in the desktop app); the five workers take what grows with the model:
 * {@code edits} (drag previews, whole-model edits, selecting), {@code io} (open, save, export),
 * {@code overlay} (projecting control points), {@code topology} (finding welded points and
 * cross-border rows) and {@code difference} (View → Difference to clipping: every pixel's ray
 * traced twice). Results come back through {@code ui}. Tests use {@link #direct()}, which runs
 * everything at once on the caller's thread.
 */
public record AppThreads(Executor ui, Executor edits, Executor io, Executor overlay, Executor topology,
                         Executor difference) {

    /** Everything runs inline, on the caller's thread (unit tests: deterministic, no waiting). */
    public static AppThreads direct() {
        Executor now = Runnable::run;
        return new AppThreads(now, now, now, now, now, now);
    }

    /** One daemon thread per worker, results delivered through {@code ui}. */
    public static AppThreads start(Executor ui) {
        return new AppThreads(ui, worker("model-edits"), worker("model-io"), worker("overlay-prep"),
                worker("model-topology"), worker("difference"));
    }

    private static ExecutorService worker(String name) {
        return Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, name);
            t.setDaemon(true);
            return t;
        });
    }

    /** Stops the workers this record started (jobs in flight are interrupted). */
    public void close() {
        for (Executor e : List.of(edits, io, overlay, topology, difference)) {
            if (e instanceof ExecutorService s) {
                s.shutdownNow();
            }
        }
    }
}
