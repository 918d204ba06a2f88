package org.beziertracer.app;

/**
 * A background job the user may cancel (opening a model). {@link #cancel} marks it cancelled and
 * interrupts its thread, so a read in progress stops at once (file channels close on interrupt);
 * its result, if any, is dropped. Thread-safe.
 */
public final class Task {

    private final String label;
    private volatile boolean cancelled;
    private Thread runner;

    public Task(String label) {
        this.label = label;
    }

    /** What the job does, for the status bar, e.g. {@code opening teapot.bpt}. */
    public String label() { return label; }

    public boolean isCancelled() { return cancelled; }

    /** Cancels the job; a finished job is not affected. */
    public synchronized void cancel() {
        cancelled = true;
        if (runner != null) {
            runner.interrupt();
        }
    }

    synchronized void started() {
        runner = Thread.currentThread();
        if (cancelled) {
            runner.interrupt();
        }
    }

    synchronized void ended() {
        runner = null;
        Thread.interrupted(); // never leak an interrupt into the worker's next job
    }
}
