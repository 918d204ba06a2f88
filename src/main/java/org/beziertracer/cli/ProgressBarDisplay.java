package org.beziertracer.cli;

import java.io.PrintWriter;

import org.beziertracer.render.RenderProgress;

import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarConsumer;
import me.tongfei.progressbar.ProgressBarStyle;

/**
 * {@code render}'s progress bar (me.tongfei:progressbar): task name, percent, bar, samples traced,
 * elapsed time and ETA ({@code render  37% [=====>    ] 2841/7680 k samples (0:00:02 / 0:00:03)})
 * on one line of standard error, redrawn in place five times a second, ended by a newline on
 * {@link #close()}. Over {@code --repeat K} frames it shows the K frames as one task. Thread-safe:
 * the render workers call {@link #progress} (one at a time), the library's timer thread draws.
 */
final class ProgressBarDisplay implements RenderProgress, AutoCloseable {
    static final int REFRESH_MILLIS = 200;

    private final ProgressBar bar;
    private final LineConsumer line;
    private final int frameCount;
    private int frame = -1;
    private int generation;

    /**
     * A bar drawn on {@code err}, at most {@code columns} wide, for {@code frameCount} frames of
     * about {@code samplesPerFrame} samples each (the first drawing shows {@code 0%} of that total;
     * the frames' own totals replace it as they start).
     */
    ProgressBarDisplay(PrintWriter err, int columns, int frameCount, long samplesPerFrame) {
        this(err, columns, frameCount, samplesPerFrame, "render", " k samples", 1000);
    }

    /**
     * A bar for another task ({@code analyze}: borders), counted in {@code unit}s of {@code unitSize};
     * {@code perFrame} 0 when the total is not known before the first progress.
     */
    ProgressBarDisplay(PrintWriter err, int columns, int frameCount, long perFrame, String task, String unit,
                       long unitSize) {
        this.frameCount = frameCount;
        this.bar = new ProgressBarBuilder().setTaskName(task).setInitialMax(perFrame * frameCount)
                .setStyle(ProgressBarStyle.ASCII).setUpdateIntervalMillis(REFRESH_MILLIS)
                .setUnit(unit, unitSize)
                .setConsumer(line = new LineConsumer(err, columns)).build();
    }

    @Override
    public synchronized void progress(int generation, long done, long total) {
        if (frame < 0 || generation != this.generation) {
            frame++;
            this.generation = generation;
            bar.maxHint(total * frameCount);
        }
        bar.stepTo(frame * total + done);
    }

    /**
     * Ends the bar with its last state and a newline before returning. The library ends it on its
     * own timer thread and waits for that, but swallows a failure or an interrupt of the wait (a CI
     * run once saw the line end without its newline), so the newline is made sure of here: what the
     * command prints next starts on a fresh line.
     */
    @Override
    public void close() {
        bar.close();
        line.close();
    }

    /** Draws each line over the last one with a carriage return; a newline at the end. */
    private static final class LineConsumer implements ProgressBarConsumer {
        private final PrintWriter err;
        private final int columns;
        private final java.util.concurrent.atomic.AtomicBoolean closed = new java.util.concurrent.atomic.AtomicBoolean();

        LineConsumer(PrintWriter err, int columns) {
            this.err = err;
            this.columns = columns;
        }

        @Override
        public int getMaxRenderedLength() { return columns - 1; }

        @Override
        public synchronized void accept(String line) {
            if (closed.get()) {
                return; // a periodic redraw that lost the race with the final one
            }
            err.print('\r' + line);
            err.flush();
        }

        @Override
        public synchronized void close() {
            if (closed.compareAndSet(false, true)) {
                err.println();
                err.flush();
            }
        }
    }
}
