package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.BezierPatch;

/**
 * Writes the BPT format read by {@link BptReader}: the patch count on the first line, then per
 * patch a line {@code n m} and one line {@code x y z} per control point, u index fastest.
 *
 * <p>Only polynomial, untrimmed patches fit the format (a patch's parameter range is not kept).
 * Numbers are written as the shortest text that parses back to the same {@code double}
 * (whole numbers without {@code .0}), so reading the output gives back equal patches bit for bit.
 * Stateless and thread-safe.
 */
public final class BptWriter {
    private BptWriter() {}

    /** Writes the patches to {@code file} atomically (see {@link AtomicFiles}). */
    public static void write(Path file, List<BezierPatch> patches) throws IOException {
        AtomicFiles.write(file, out -> write(out, patches));
    }

    /** The BPT text of the patches. */
    public static String toString(List<BezierPatch> patches) {
        return AtomicFiles.toText(out -> write(out, patches));
    }

    /**
     * Writes BPT text to {@code out} (not closed).
     *
     * @throws IllegalArgumentException before writing anything, when a patch is rational or
     *                                  trimmed (BPT cannot hold weights or trim loops; OBJ can)
     */
    public static void write(Writer out, List<BezierPatch> patches) throws IOException {
        write(out, patches, WriteProgress.NONE);
    }

    /** As {@link #write(Writer, List)}, telling {@code progress} the patches written. */
    public static void write(Writer out, List<BezierPatch> patches, WriteProgress progress) throws IOException {
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch p = patches.get(k);
            if (p.isRational() || p.trim() != null) {
                throw new IllegalArgumentException("a BPT file holds polynomial, untrimmed Bézier patches but patch "
                        + (k + 1) + " is " + (p.isRational() ? "rational" : "trimmed") + "; save the model as .obj");
            }
        }
        out.write(Integer.toString(patches.size()));
        out.write('\n');
        StringBuilder line = new StringBuilder(64);
        int done = 0;
        for (BezierPatch patch : patches) {
            out.write(patch.degreeU() + " " + patch.degreeV() + "\n");
            double[] net = patch.copyNet();
            for (int k = 0; k < net.length; k += 3) {
                line.setLength(0);
                line.append(NumberText.format(net[k])).append(' ')
                        .append(NumberText.format(net[k + 1])).append(' ')
                        .append(NumberText.format(net[k + 2])).append('\n');
                out.write(line.toString());
            }
            progress.patch(++done, patches.size());
        }
        out.flush();
    }
}
