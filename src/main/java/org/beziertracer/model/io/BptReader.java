package org.beziertracer.model.io;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Reads the BPT format ("Bézier patch text").
 *
 * <h2>Format</h2>
 * <pre>
 * count                      # number of patches, 1..{@link ReadLimits#patches()} (a million)
 * n m                        # per patch: degree in u, degree in v, each 1..15
 * x y z                      # then (n+1)(m+1) points, u index fastest:
 * ...                        #   point k = j(n+1) + i holds P_ij
 * </pre>
 * Tokens are separated by any whitespace (line breaks carry no meaning; a whole file may be one
 * line). {@code #} starts a comment that runs to the end of the line. Coordinates are plain
 * decimal or scientific numbers; NaN and infinities are rejected. Nothing may follow the last
 * patch except whitespace and comments.
 *
 * <h2>Errors</h2>
 * Every problem is a one-line {@link ModelFormatException}: {@code file:line: expected …, found …}.
 * In messages, patches and points are numbered from 1 in file order.
 *
 * <p>The patch count is never used to pre-allocate, so an absurd count in a short file fails on
 * the missing data rather than on memory; but a count whose patches, of the first patch's
 * degrees, could not fit in the heap is refused before the first point is read
 * ({@link HeapEstimates}). Lines may be of any length: the reader streams tokens.
 * Files are opened through {@link FileFormats#BPT}. Stateless and thread-safe.
 */
public final class BptReader {
    private BptReader() {}

    /** Reads BPT text; for tests and in-memory use. */
    public static List<BezierPatch> read(String text, String fileName) {
        try {
            return read(TextSource.of(text, fileName));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The patches of {@code text} as a scene (the reader {@link FileFormats#BPT} declares). */
    static Scene readScene(TextSource text) throws IOException {
        return new Scene(read(text));
    }

    /**
     * Reads BPT text.
     *
     * @throws ModelFormatException for any syntax or range problem, naming {@link TextSource#fileName()}
     */
    public static List<BezierPatch> read(TextSource text) throws IOException {
        String fileName = text.fileName();
        int maxCount = text.limits().patches();
        BptTokenizer tokens = new BptTokenizer(text);

        // Patch count
        String token = tokens.next();
        if (token == null) {
            throw new ModelFormatException(fileName, 1,
                    "expected the patch count, found end of file (the file is empty)");
        }
        if (!NumberText.isWhole(token)) {
            throw new ModelFormatException(fileName, tokens.line(), "expected the patch count (a whole number 1.."
                    + maxCount + "), found " + NumberText.describe(token));
        }
        long count = NumberText.parseWhole(token);
        if (count < 1 || count > maxCount) {
            throw new ModelFormatException(fileName, tokens.line(), "expected the patch count, found "
                    + NumberText.describe(token) + ": patch count " + Echo.cut(token) + " out of range 1.." + maxCount);
        }

        // Patches; the list grows as data arrives, never sized from the announced count
        List<BezierPatch> patches = new ArrayList<>((int) Math.min(count, 1024));
        for (int p = 1; p <= count; p++) {
            String of = " of patch " + p + " (of " + count + " announced)";
            int n = readDegree(tokens, "u degree" + of, fileName);
            int m = readDegree(tokens, "v degree" + of, fileName);
            if (p == 1) { // refuse what cannot fit now, not after minutes of parsing
                HeapEstimates.requirePatches(text, tokens.line(), count, n, m);
            }
            int points = (n + 1) * (m + 1);
            double[] net = new double[points * 3];
            for (int k = 0; k < points; k++) {
                for (int c = 0; c < 3; c++) {
                    token = tokens.next();
                    double v = NumberText.finiteOrNaN(token);
                    if (Double.isNaN(v)) { // throws, saying why
                        String what = "the " + "xyz".charAt(c) + " coordinate of point " + (k + 1) + of;
                        NumberText.parseFinite(token, what, fileName, tokens.line());
                    }
                    net[3 * k + c] = v;
                }
            }
            patches.add(new BezierPatch(n, m, net));
        }

        // Nothing but comments may follow
        token = tokens.next();
        if (token != null) {
            throw new ModelFormatException(fileName, tokens.line(), "expected end of file after the " + count
                    + " announced patches, found " + NumberText.describe(token));
        }
        return patches;
    }

    private static int readDegree(BptTokenizer tokens, String what, String fileName) throws IOException {
        String token = tokens.next();
        if (token == null || !NumberText.isWhole(token)) {
            throw new ModelFormatException(fileName, tokens.line(), "expected the " + what
                    + " (a whole number 1.." + BezierPatch.MAX_DEGREE + "), found " + NumberText.describe(token));
        }
        long degree = NumberText.parseWhole(token);
        if (degree < 1 || degree > BezierPatch.MAX_DEGREE) {
            throw new ModelFormatException(fileName, tokens.line(), "expected the " + what + ", found "
                    + NumberText.describe(token) + ": degree " + Echo.cut(token) + " out of range 1.."
                    + BezierPatch.MAX_DEGREE);
        }
        return (int) degree;
    }
}
