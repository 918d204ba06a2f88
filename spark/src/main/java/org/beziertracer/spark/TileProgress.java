package org.beziertracer.spark;

import java.io.PrintStream;
import java.util.Locale;

import org.apache.spark.TaskFailedReason;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerTaskEnd;

/**
 * Prints {@code tiles D / T done, ETA S s} on the driver as tile tasks finish (Spark's listener bus calls
 * it on one thread), and one line for each failed attempt. Tiles found already written count as done from the start; the ETA is the mean time
 * per tile finished in this run times the tiles left.
 */
final class TileProgress extends SparkListener {
    private final PrintStream out;
    private final int total;
    private final int skipped;
    private final long startNanos = System.nanoTime();
    private int finished;

    TileProgress(PrintStream out, int total, int skipped) {
        this.out = out;
        this.total = total;
        this.skipped = skipped;
        out.println(line());
    }

    @Override
    public void onTaskEnd(SparkListenerTaskEnd end) {
        if (end.taskInfo() != null && end.taskInfo().successful()) {
            finished++;
            out.println(line());
        } else if (end.reason() instanceof TaskFailedReason failed) {
            out.println("a tile task failed (Spark retries it up to spark.task.maxFailures): "
                    + failed.toErrorString().lines().findFirst().orElse("?"));
        }
        out.flush();
    }

    String line() {
        int done = Math.min(total, skipped + finished);
        if (finished == 0) {
            return String.format(Locale.ROOT, "tiles %d / %d done", done, total);
        }
        double perTile = (System.nanoTime() - startNanos) / 1e9 / finished;
        return String.format(Locale.ROOT, "tiles %d / %d done, ETA %.0f s", done, total, perTile * (total - done));
    }
}
