package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.BezierPatch;

/**
 * Writes patches as Wavefront OBJ free-form Bézier surfaces, the subset read by
 * {@link ObjReader}:
 * <pre>
 * cstype bezier
 * v x y z                     # (n+1)(m+1) vertices per patch, u fastest
 * deg n m
 * surf 0 1 0 1 1 2 3 4 \      # one row of control points per line (u fastest),
 *      5 6 7 8 …              # continued with a trailing backslash
 * parm u 0 1
 * parm v 0 1
 * end
 * </pre>
 * Each patch gets its own vertices (no sharing), written with the shortest round-trip number
 * text, so reading the file back gives equal patches bit for bit. Stateless and thread-safe.
 */
public final class ObjWriter {
    private ObjWriter() {}

    /** Writes the patches to {@code file} atomically (see {@link AtomicFiles}). */
    public static void write(Path file, List<BezierPatch> patches) throws IOException {
        AtomicFiles.write(file, out -> write(out, patches));
    }

    /** The OBJ text of the patches. */
    public static String toString(List<BezierPatch> patches) {
        return AtomicFiles.toText(out -> write(out, patches));
    }

    /** Writes OBJ text to {@code out} (not closed). */
    public static void write(Writer out, List<BezierPatch> patches) throws IOException {
        StringBuilder sb = new StringBuilder(256);
        sb.append("# Bézier Tracer: ").append(patches.size()).append(" Bézier patches\n");
        sb.append("cstype bezier\n");
        out.write(sb.toString());
        int firstVertex = 1;
        int patchNumber = 1;
        for (BezierPatch patch : patches) {
            sb.setLength(0);
            int n = patch.degreeU(), m = patch.degreeV();
            sb.append("# patch ").append(patchNumber++).append('\n');
            double[] net = patch.copyNet();
            for (int k = 0; k < net.length; k += 3) {
                sb.append("v ").append(NumberText.format(net[k])).append(' ')
                        .append(NumberText.format(net[k + 1])).append(' ')
                        .append(NumberText.format(net[k + 2])).append('\n');
            }
            sb.append("deg ").append(n).append(' ').append(m).append('\n');
            sb.append("surf 0 1 0 1");
            for (int j = 0; j <= m; j++) {
                if (j > 0) {
                    sb.append(" \\\n    ");
                }
                for (int i = 0; i <= n; i++) {
                    sb.append(' ').append(firstVertex + j * (n + 1) + i);
                }
            }
            sb.append("\nparm u 0 1\nparm v 0 1\nend\n");
            out.write(sb.toString());
            firstVertex += patch.pointCount();
        }
        out.flush();
    }
}
