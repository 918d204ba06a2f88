package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.model.HeapRoom;

/**
 * What reading a model holds on the heap, estimated before the body is parsed, so that a file
 * that cannot fit is refused in a moment instead of after minutes of parsing and an out-of-memory
 * error ({@link HeapRoom}). The figures are lower bounds of the model alone: the acceleration
 * structures built afterwards are checked by {@code intersect.HeapBudget}. Stateless.
 */
public final class HeapEstimates {
    private HeapEstimates() {}

    /**
     * Heap a plain Bézier patch of degree {@code n × m} holds: its control-point array
     * ({@code 16 + 24(n+1)(m+1)} bytes) and about 96 bytes of object, list slot and headers.
     */
    static long patchBytes(int n, int m) {
        return 16 + 24L * (n + 1) * (m + 1) + 96;
    }

    /**
     * Heap an OBJ file of {@code fileBytes} holds once read: at least its own size (a vertex line
     * of about 30 characters becomes four doubles, 32 bytes; a face its indices and triangles).
     */
    static long objBytes(long fileBytes) {
        return fileBytes;
    }

    /**
     * Throws when {@code count} patches like the first one ({@code n × m}) would not fit: a BPT
     * file is refused from its first lines.
     */
    static void requirePatches(TextSource text, int line, long count, int n, int m) {
        String shortfall = HeapRoom.shortfall(count + (count == 1 ? " patch" : " patches") + " of degree " + n + "x" + m,
                count * patchBytes(n, m));
        if (shortfall != null) {
            throw new ModelFormatException(text.fileName(), line, shortfall);
        }
    }

    /** Throws when an OBJ file of the text's size would not fit (nothing is checked for a stream of unknown size). */
    static void requireObj(TextSource text) {
        long size = text.knownSize();
        if (size <= 0) {
            return;
        }
        String shortfall = HeapRoom.shortfall("its " + HeapRoom.size(size) + " of OBJ text", objBytes(size));
        if (shortfall != null) {
            throw new ModelFormatException(text.fileName(), shortfall);
        }
    }

    /** Bytes of the shortest vertex statement, {@code "v 0 0 0\n"}. */
    static final int SHORTEST_VERTEX_LINE = 8;

    /**
     * Refuses an OBJ file with more vertices than {@link ReadLimits#vertices()} before parsing it:
     * when the file is large enough to hold that many ({@value #SHORTEST_VERTEX_LINE} bytes each),
     * its lines starting {@code v } are counted in one pass over the bytes (about a second a
     * gigabyte, against a minute to parse), so that such a file is refused in seconds.
     */
    static void requireObjVertexCount(Path file, String fileName, ReadLimits limits) throws IOException {
        long size = Files.size(file);
        if (size < (long) limits.vertices() * SHORTEST_VERTEX_LINE) {
            return;
        }
        long count = 0;
        boolean lineStart = true;
        int previous = -1;
        byte[] buffer = new byte[1 << 20];
        try (InputStream in = Files.newInputStream(file)) {
            for (int n; (n = in.read(buffer)) > 0; ) {
                for (int k = 0; k < n; k++) {
                    byte b = buffer[k];
                    if (lineStart && previous == 'v' && (b == ' ' || b == '\t')) {
                        if (++count > limits.vertices()) {
                            throw new ModelFormatException(fileName, "a file may have at most " + limits.vertices()
                                    + " vertices; this one has more (v lines counted before parsing)");
                        }
                    }
                    if (b == '\n' || b == '\r') {
                        lineStart = true;
                        previous = -1;
                    } else if (previous == -1 && lineStart) {
                        previous = b;
                    } else {
                        lineStart = false;
                    }
                }
            }
        }
    }

    /**
     * A heap, in bytes, that reading {@code file} would at least take — for the hint after running
     * out of memory: a BPT file by its first lines, any other file by its size; 0 when unknown.
     */
    public static long forFile(Path file) {
        try {
            long size = Files.size(file);
            if (FileFormats.BPT.matches(file.toString())) {
                try (InputStream in = Files.newInputStream(file)) {
                    BptTokenizer tokens = new BptTokenizer(new TextSource(in, file.toString()));
                    long count = Long.parseLong(tokens.next());
                    int n = Integer.parseInt(tokens.next()), m = Integer.parseInt(tokens.next());
                    if (count > 0 && n > 0 && m > 0 && n <= 64 && m <= 64) {
                        return Math.max(size, count * patchBytes(n, m));
                    }
                }
            }
            return size;
        } catch (IOException | RuntimeException e) {
            return 0;
        }
    }
}
