package org.beziertracer.app;

import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

/**
 * What the status bar shows: the latest render status (reported on render threads, shown on the
 * UI thread through one pending slot, so a burst of reports costs one refresh), the last message
 * (for instance the random seed) and the cancellable task in progress (opening a model). UI thread
 * only, except {@link #report}.
 */
public final class StatusModel {

    private final Executor ui;
    private final Runnable onChange;
    private final AtomicReference<RenderStatus> pending = new AtomicReference<>();
    private final AtomicBoolean posted = new AtomicBoolean();
    private final AtomicBoolean progressPosted = new AtomicBoolean();
    private RenderStatus render;
    private String message = "";
    private Task task;

    StatusModel(Executor ui, Runnable onChange) {
        this.ui = ui;
        this.onChange = onChange;
    }

    /** The latest render status, or null before the first pass. */
    public RenderStatus render() { return render; }

    /** The last action's message, e.g. {@code random seed 1234}. */
    public String message() { return message; }

    /** The task in progress that the user may cancel, or null. */
    public Task task() { return task; }

    /** Render threads: the latest status; shown on the UI thread, coalesced. */
    public void report(RenderStatus s) {
        pending.set(s);
        if (posted.compareAndSet(false, true)) {
            ui.execute(() -> {
                posted.set(false);
                render = pending.get();
                onChange.run();
            });
        }
    }

    void message(String m) {
        message = m;
        onChange.run();
    }

    void task(Task t) {
        task = t;
        if (t != null) {
            t.onProgress(this::progressed);
        }
        onChange.run();
    }

    /** {@code t} ended: the status bar stops showing it (unless another task took its place). */
    void endTask(Task t) {
        if (task == t) {
            task(null);
        }
    }

    /** A task's progress changed (its own thread): one refresh on the UI thread per burst. */
    private void progressed() {
        if (progressPosted.compareAndSet(false, true)) {
            ui.execute(() -> {
                progressPosted.set(false);
                onChange.run();
            });
        }
    }

    /** True while a report is on its way to the UI thread (any thread). */
    boolean busy() { return posted.get() || progressPosted.get(); }
}
