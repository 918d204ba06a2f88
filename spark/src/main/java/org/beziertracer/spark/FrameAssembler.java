package org.beziertracer.spark;

import java.io.IOException;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;

import org.apache.hadoop.fs.Path;
import org.apache.spark.api.java.function.Function;
import org.beziertracer.model.io.FramePattern;
import org.beziertracer.render.FrameAssembly;
import org.beziertracer.render.TilePixels;

/**
 * The last stage of a job, one Spark task per frame, run on the executors once every tile is written (so
 * frames are assembled in parallel, as many at once as there are task slots, and the driver reads no tile):
 * reads the frame's tiles from the output folder, puts them together ({@link FrameAssembly}) and writes the
 * frame's PNG and linear {@code .pfm} atomically beside the {@code tiles/} folder, named as
 * {@code render JOB.json} names them ({@link FramePattern}). A frame whose PNG and {@code .pfm} are both
 * there already is left alone (a resumed run, a retried or speculative attempt). Returns 1 when it wrote
 * the frame, 0 when it was there.
 *
 * <p>Memory: a task holds one frame's tiles and picture, about {@code 32 · width · height} bytes (a 4K frame:
 * 270 MB), so an executor needs that times its cores.
 */
final class FrameAssembler implements Function<Integer, Integer> {
    private static final long serialVersionUID = 1L;
    private static final AtomicInteger ASSEMBLED = new AtomicInteger();

    private final String output;
    private final String jobName;
    private final String pattern;
    private final int width, height, tiles;

    /**
     * @param output  the output folder's URI
     * @param pattern the frames' PNG name, a run of {@code #} standing for the frame number (the file
     *                name of the job's {@code output}, or {@code JOB-####.png})
     * @param tiles   tiles per frame
     */
    FrameAssembler(String output, String jobName, String pattern, int width, int height, int tiles) {
        this.output = output;
        this.jobName = jobName;
        this.pattern = pattern;
        this.width = width;
        this.height = height;
        this.tiles = tiles;
    }

    /** The PNG file name of {@code frame}. */
    String pngName(int frame) {
        return FramePattern.fileOf(java.nio.file.Path.of(pattern), frame).getFileName().toString();
    }

    /** The {@code .pfm} file name of {@code frame}: the PNG's with {@code .pfm}, as {@code render JOB.json} names it. */
    String pfmName(int frame) {
        return FramePattern.pfmName(pngName(frame));
    }

    /** True when {@code frame}'s PNG and {@code .pfm} are both in {@code folder}. */
    boolean written(OutputFolder folder, int frame) throws IOException {
        return folder.exists(folder.frame(pngName(frame))) && folder.exists(folder.frame(pfmName(frame)));
    }

    @Override
    public Integer call(Integer frame) throws IOException {
        return assemble(new OutputFolder(output), frame) ? 1 : 0;
    }

    /** Assembles {@code frame} from its tiles in {@code folder}; false when it was there already. */
    boolean assemble(OutputFolder folder, int frame) throws IOException {
        if (written(folder, frame)) {
            return false;
        }
        FrameAssembly assembly = new FrameAssembly(width, height);
        for (int i = 1; i <= tiles; i++) {
            Path tile = folder.tile(new TileTask(frame, i, tiles).fileName(jobName));
            assembly.add(TilePixels.fromBytes(folder.read(tile), tile.toString()));
        }
        String tag = OutputFolder.attemptTag();
        folder.writeAtomically(folder.frame(pfmName(frame)), assembly.pfm(), tag);
        folder.writeAtomically(folder.frame(pngName(frame)), assembly.png(), tag);
        ASSEMBLED.incrementAndGet();
        return true;
    }

    /** How many frames this JVM assembled (the tests check: none on a driver whose executors are other JVMs). */
    static int assembledCount() { return ASSEMBLED.get(); }

    /** {@code JOB-####.png}: the frames' name when the job names no output. */
    static String defaultPattern(String jobName) {
        return jobName.toLowerCase(Locale.ROOT).endsWith(".png") ? jobName : jobName + "-####.png";
    }
}
