package org.beziertracer.spark;

import java.io.PrintStream;
import java.util.HashSet;
import java.util.Locale;
import java.util.Properties;
import java.util.Set;

import org.apache.spark.TaskFailedReason;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerStageSubmitted;
import org.apache.spark.scheduler.SparkListenerTaskEnd;
import org.apache.spark.scheduler.SparkListenerTaskStart;

/**
 * Prints {@code tiles D / T done, ETA S s} on the driver as tile tasks finish (Spark's listener bus calls
 * it on one thread), and one line for each failed attempt (of a tile or of a frame's assembly). Tiles found
 * already written count as done from the start; the ETA is the mean time per tile finished in this run
 * times the tiles left. Tile tasks are told from the frames' assembly by their job's description
 * ({@link #TILES}, set with {@code setJobDescription}).
 */
final class TileProgress extends SparkListener {
    /** The description of the Spark job that renders tiles. */
    static final String TILES = "beziertracer tiles";
    private final Set<Integer> tileStages = new HashSet<>();
    private final PrintStream out;
    private final int total;
    private final int skipped;
    private final long startNanos = System.nanoTime();
    private int finished;
    private long firstStartNanos, lastEndNanos;
    private boolean closed;

    TileProgress(PrintStream out, int total, int skipped) {
        this.out = out;
        this.total = total;
        this.skipped = skipped;
        out.println(line());
    }

    @Override
    public synchronized void onStageSubmitted(SparkListenerStageSubmitted submitted) {
        Properties p = submitted.properties();
        if (p != null && TILES.equals(p.getProperty("spark.job.description"))) {
            tileStages.add(submitted.stageInfo().stageId());
        }
    }

    @Override
    public synchronized void onTaskStart(SparkListenerTaskStart start) {
        if (!tileStages.contains(start.stageId())) {
            return;
        }
        if (firstStartNanos == 0) {
            firstStartNanos = System.nanoTime();
        }
    }

    @Override
    public synchronized void onTaskEnd(SparkListenerTaskEnd end) {
        boolean tile = tileStages.contains(end.stageId());
        if (end.taskInfo() != null && end.taskInfo().successful()) {
            if (closed || !tile) {
                return;
            }
            finished++;
            lastEndNanos = System.nanoTime();
            out.println(line());
        } else if (end.reason() instanceof TaskFailedReason failed) {
            out.println("a " + (tile ? "tile" : "frame assembly") + " task failed (Spark retries it up to spark.task.maxFailures): "
                    + failed.toErrorString().lines().findFirst().orElse("?"));
        }
        out.flush();
    }

    /**
     * Tiles a second from the first task's start to the last one's end (executor start-up before the first
     * task not counted); 0 before a tile finished.
     */
    synchronized double tilesPerSecond() {
        long start = firstStartNanos == 0 ? startNanos : firstStartNanos;
        return finished == 0 || lastEndNanos <= start ? 0 : finished / ((lastEndNanos - start) / 1e9);
    }

    /**
     * The render stage ended with {@code rendered} tiles written: prints the last line if the listener bus
     * (which runs behind) has not yet, and ignores its later events.
     */
    synchronized void finish(int rendered) {
        if (finished < rendered) {
            finished = rendered;
            lastEndNanos = System.nanoTime();
            out.println(line());
            out.flush();
        }
        closed = true;
    }

    private String line() {
        int done = Math.min(total, skipped + finished);
        if (finished == 0) {
            return String.format(Locale.ROOT, "tiles %d / %d done", done, total);
        }
        double perTile = (System.nanoTime() - startNanos) / 1e9 / finished;
        return String.format(Locale.ROOT, "tiles %d / %d done, ETA %.0f s", done, total, perTile * (total - done));
    }
}
