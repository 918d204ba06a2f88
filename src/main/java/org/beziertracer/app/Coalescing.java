package org.beziertracer.app;

import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

/**
 * Runs only the newest of a burst of jobs: {@link #submit} parks the item in one slot (replacing
 * one not yet started) and makes sure a drain runs on the executor, which handles items until the
 * slot stays empty. During a drag, items that arrive while one is being handled replace each
 * other, and only the latest is handled next.
 *
 * <p>Thread-safe; {@code handler} runs on the executor's thread, one item at a time. A handler that
 * throws reports to {@code failed} and the worker stays usable.
 *
 * @param <T> the job
 */
public final class Coalescing<T> {

    private final Executor executor;
    private final Consumer<T> handler;
    private final Consumer<Throwable> failed;
    private final AtomicReference<T> pending = new AtomicReference<>();
    private final AtomicBoolean draining = new AtomicBoolean();

    public Coalescing(Executor executor, Consumer<T> handler, Consumer<Throwable> failed) {
        this.executor = executor;
        this.handler = handler;
        this.failed = failed;
    }

    /** Parks {@code item} as the newest job; returns at once (unless the executor runs inline). */
    public void submit(T item) {
        pending.set(item);
        schedule();
    }

    /** True while an item waits or is being handled. */
    public boolean busy() {
        return pending.get() != null || draining.get();
    }

    /** True while an item waits that the worker has not taken yet. */
    public boolean hasPending() {
        return pending.get() != null;
    }

    private void schedule() {
        if (draining.compareAndSet(false, true)) {
            executor.execute(this::drain);
        }
    }

    private void drain() {
        try {
            for (T item = pending.getAndSet(null); item != null; item = pending.getAndSet(null)) {
                try {
                    handler.accept(item);
                } catch (RuntimeException | OutOfMemoryError | StackOverflowError e) {
                    failed.accept(e);
                }
            }
        } finally {
            draining.set(false);
        }
        // An item that slipped in between the last poll and clearing the flag
        if (pending.get() != null) {
            schedule();
        }
    }
}
