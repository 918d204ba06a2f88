package org.beziertracer.app;

import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * Work that must not run on the UI thread because it grows with the model — opening, saving,
 * exporting, whole-model edits — run on one worker, in order; the result comes back on the UI
 * thread. Thread-safe.
 */
public final class BackgroundTasks {

    private final Executor worker;
    private final Executor ui;
    private final AtomicInteger inFlight = new AtomicInteger();

    BackgroundTasks(Executor worker, Executor ui) {
        this.worker = worker;
        this.ui = ui;
    }

    /**
     * Runs {@code work} on the worker. On the UI thread afterwards: {@code done} with its result,
     * or {@code failed} with what it threw — a {@link CancellationException} when the task was
     * cancelled (whatever the work returned or threw).
     */
    public <T> Task submit(String label, Callable<T> work, Consumer<T> done, Consumer<Throwable> failed) {
        Task task = new Task(label);
        submit(task, work, done, failed);
        return task;
    }

    /** Like {@link #submit(String, Callable, Consumer, Consumer)} for a task made beforehand. */
    public <T> void submit(Task task, Callable<T> work, Consumer<T> done, Consumer<Throwable> failed) {
        String label = task.label();
        inFlight.incrementAndGet();
        worker.execute(() -> {
            Runnable outcome = () -> failed.accept(new CancellationException(label));
            try {
                task.started();
                T result = work.call();
                outcome = () -> done.accept(result);
            } catch (Exception | Error e) {
                outcome = () -> failed.accept(e);
            } finally {
                task.ended();
                Runnable deliver = outcome;
                ui.execute(() -> {
                    inFlight.decrementAndGet();
                    if (task.isCancelled()) {
                        failed.accept(new CancellationException(label));
                    } else {
                        deliver.run();
                    }
                });
            }
        });
    }

    /** True while a task waits, runs or has its result on the way to the UI thread. */
    public boolean busy() { return inFlight.get() > 0; }
}
