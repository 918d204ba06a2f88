package org.beziertracer.spark;

import java.io.IOException;
import java.util.Locale;

import org.apache.hadoop.fs.Path;
import org.beziertracer.model.io.FramePattern;
import org.beziertracer.render.FrameAssembly;
import org.beziertracer.render.TilePixels;

/**
 * The driver's last step: reads the tiles of each frame from the output folder, puts them together
 * ({@link FrameAssembly}) and writes the frame's PNG and linear {@code .pfm} atomically beside the
 * {@code tiles/} folder. A frame whose PNG and {@code .pfm} are both there already is left alone.
 */
final class FrameAssembler {
    private final OutputFolder folder;
    private final String jobName;
    private final String pattern;
    private final int width, height;

    /**
     * @param pattern the frames' PNG name, a run of {@code #} standing for the frame number (the file
     *                name of the job's {@code output}, or {@code JOB-####.png})
     */
    FrameAssembler(OutputFolder folder, String jobName, String pattern, int width, int height) {
        this.folder = folder;
        this.jobName = jobName;
        this.pattern = pattern;
        this.width = width;
        this.height = height;
    }

    /** The PNG file name of {@code frame}. */
    String pngName(int frame) {
        return FramePattern.fileOf(java.nio.file.Path.of(pattern), frame).getFileName().toString();
    }

    /** The {@code .pfm} file name of {@code frame}: the PNG's with {@code .pfm}, as {@code render JOB.json} names it. */
    String pfmName(int frame) {
        return FramePattern.pfmName(pngName(frame));
    }

    /** Assembles {@code frame} from its {@code n} tiles; false when it was there already. */
    boolean assemble(int frame, int n) throws IOException {
        Path png = folder.frame(pngName(frame)), pfm = folder.frame(pfmName(frame));
        if (folder.exists(png) && folder.exists(pfm)) {
            return false;
        }
        FrameAssembly assembly = new FrameAssembly(width, height);
        for (int i = 1; i <= n; i++) {
            Path tile = folder.tile(new TileTask(frame, i, n).fileName(jobName));
            assembly.add(TilePixels.fromBytes(folder.read(tile), tile.toString()));
        }
        String tag = "driver" + ProcessHandle.current().pid();
        folder.writeAtomically(pfm, assembly.pfm(), tag);
        folder.writeAtomically(png, assembly.png(), tag);
        return true;
    }

    /** {@code JOB-####.png}: the frames' name when the job names no output. */
    static String defaultPattern(String jobName) {
        return jobName.toLowerCase(Locale.ROOT).endsWith(".png") ? jobName : jobName + "-####.png";
    }
}
