package org.beziertracer.app;

/**
 * A background job the user may cancel (opening a model, exporting an image). {@link #cancel} marks
 * it cancelled and interrupts its thread, so a read or a render in progress stops at once (file
 * channels close on interrupt); its result, if any, is dropped. A job that knows how far it got
 * reports it with {@link #progress(double)} (the status bar's bar then fills). Thread-safe.
 */
public final class Task {

    private final String label;
    private volatile boolean cancelled;
    private volatile double progress = -1;
    private volatile String count = "";
    private volatile Runnable onProgress = () -> {};
    private Thread runner;

    public Task(String label) {
        this.label = label;
    }

    /** What the job does, for the status bar, e.g. {@code opening teapot.bpt}. */
    public String label() { return label; }

    public boolean isCancelled() { return cancelled; }

    /** How far the job got, 0..1, or -1 when it cannot tell. */
    public double progress() { return progress; }

    /** Any thread: the job got this far (0..1). */
    public void progress(double fraction) {
        progress = Math.max(0, Math.min(1, fraction));
        onProgress.run();
    }

    /**
     * Any thread: {@code done} of {@code total} {@code unit}s are done ({@code 40,000 / 100,489
     * patches}); the bar fills by their ratio and shows the count ({@link #count()}).
     */
    public void progress(long done, long total, String unit) {
        count = String.format(java.util.Locale.ROOT, "%,d / %,d %s", done, total, unit);
        progress(total > 0 ? (double) done / total : 0);
    }

    /** The last count reported ({@code 40,000 / 100,489 patches}), or empty when the job reports none. */
    public String count() { return count; }

    /** The label and, when known, the count: {@code saving big.bpt: 40,000 / 100,489 patches}. */
    public String text() {
        String c = count;
        return c.isEmpty() ? label : label + ": " + c;
    }

    /** Where progress reports go (the status bar's refresh; called on the job's thread). */
    void onProgress(Runnable r) { onProgress = r; }

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
