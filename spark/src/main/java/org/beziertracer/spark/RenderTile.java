package org.beziertracer.spark;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.apache.spark.SparkEnv;
import org.apache.spark.api.java.function.Function;
import org.apache.spark.broadcast.Broadcast;
import org.beziertracer.render.TilePixels;

/**
 * The executor's side of a job: renders one {@link TileTask} with the broadcast job (loaded once per
 * executor JVM, {@link JobSource#frames}) and writes the tile atomically into the output folder; a tile
 * already there (a resumed run, or a retried task whose first attempt finished) is not rendered again.
 * Returns {@link TileDone}: whether it rendered the tile, and the executor's kernel and job loading time.
 *
 * <p>Test hook: when {@code failOnceFile} names a file that exists, the first task to delete it throws,
 * once, after rendering and before writing (Spark retries the task).
 */
final class RenderTile implements Function<TileTask, TileDone> {
    private static final long serialVersionUID = 1L;

    private final Broadcast<JobSource> job;
    private final String jobName;
    private final String output;
    private final int threads;
    private final String failOnceFile;

    RenderTile(Broadcast<JobSource> job, String jobName, String output, int threads, String failOnceFile) {
        this.job = job;
        this.jobName = jobName;
        this.output = output;
        this.threads = threads;
        this.failOnceFile = failOnceFile;
    }

    @Override
    public TileDone call(TileTask t) throws IOException, InterruptedException {
        OutputFolder out = new OutputFolder(output);
        org.apache.hadoop.fs.Path target = out.tile(t.fileName(jobName));
        SparkEnv env = SparkEnv.get();
        String executor = env == null ? "?" : env.executorId();
        if (out.exists(target)) {
            return TileDone.skipped(executor);
        }
        JobSource.Loaded loaded = job.value().load(threads);
        TilePixels pixels = loaded.frames().renderTile(t.frame(), t.i(), t.n());
        if (failOnceFile != null && Files.deleteIfExists(Path.of(failOnceFile))) {
            throw new IllegalStateException("injected failure (test hook) in tile " + t);
        }
        out.writeAtomically(target, pixels.toBytes(), OutputFolder.attemptTag());
        return new TileDone(true, executor, loaded.frames().kernel(), loaded.seconds());
    }
}
