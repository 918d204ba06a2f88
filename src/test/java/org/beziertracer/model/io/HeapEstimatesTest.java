package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A model that cannot fit is refused from its first lines or its size, before the body is parsed (issue 36). */
class HeapEstimatesTest {

    private static final String HEADER = "1000000\n15 15\n";

    /** A billion degree-15 patches: more than any heap (6 TB), allowed by these limits. */
    private static final String HUGE_HEADER = "1000000000\n15 15\n";

    @TempDir
    Path dir;

    /** The header's bytes, then a failure: any read past the header fails the test. */
    private static InputStream headerOnly(String text) {
        return new InputStream() {
            private final InputStream header = new ByteArrayInputStream(text.getBytes(StandardCharsets.US_ASCII));

            @Override
            public int read() throws IOException {
                int b = header.read();
                if (b < 0) {
                    throw new AssertionError("read past the header");
                }
                return b;
            }

            @Override
            public int read(byte[] b, int off, int len) throws IOException {
                int n = header.read(b, off, len);
                if (n < 0) {
                    throw new AssertionError("read past the header");
                }
                return n;
            }
        };
    }

    @Test
    void patchesThatCannotFitAreRefusedFromTheHeaderWithoutReadingTheBody() {
        ReadLimits billion = new ReadLimits(ReadLimits.DEFAULT.lineChars(), ReadLimits.DEFAULT.bytesInMemory(),
                1_000_000_000, ReadLimits.DEFAULT.vertices(), ReadLimits.DEFAULT.sceneModels(),
                ReadLimits.DEFAULT.sceneObjects());
        String message = UserMessages.of(ModelFormatException.class,
                () -> BptReader.read(new TextSource(headerOnly(HUGE_HEADER), "big.bpt", billion)));
        assertTrue(message.matches("big\\.bpt:2: 1000000000 patches of degree 15x15 need about 6\\d{3} GB of heap; "
                + "this JVM allows \\d+(\\.\\d)? [MG]B(, .* of it in use)? \\(run java -Xmx\\d+g …\\)"), message);
    }

    @Test
    void aMillionDegreeFifteenPatchesAreRefusedFromTheHeaderWhenTheHeapIsSmaller() {
        long estimate = 1_000_000L * HeapEstimates.patchBytes(15, 15);
        if (Runtime.getRuntime().maxMemory() >= estimate * 1.1) {
            // A big heap takes them: the header is read and the missing body is what fails
            AssertionError e = org.junit.jupiter.api.Assertions.assertThrows(AssertionError.class,
                    () -> BptReader.read(new TextSource(headerOnly(HEADER), "big.bpt")));
            assertEquals("read past the header", e.getMessage());
            return;
        }
        String message = UserMessages.of(ModelFormatException.class,
                () -> BptReader.read(new TextSource(headerOnly(HEADER), "big.bpt")));
        assertTrue(message.matches("big\\.bpt:2: 1000000 patches of degree 15x15 need about 6\\.\\d GB of heap; "
                + "this JVM allows \\d+(\\.\\d)? [MG]B(, .* of it in use)? \\(run java -Xmx(8|16)g …\\)"), message);
    }

    @Test
    void aPatchHoldsItsControlPointsAndAnObject() {
        assertEquals(16 + 24 * 256 + 96, HeapEstimates.patchBytes(15, 15));
        assertEquals(16 + 24 * 16 + 96, HeapEstimates.patchBytes(3, 3));
    }

    @Test
    void anObjFileLargerThanTheHeapIsRefusedBeforeParsing() {
        long size = 1L << 40; // a terabyte announced, a few bytes present
        TextSource text = new TextSource(new ByteArrayInputStream("v 0 0 0\n".getBytes(StandardCharsets.US_ASCII)),
                "huge.obj", ReadLimits.DEFAULT, size);
        String message = UserMessages.of(ModelFormatException.class, () -> ObjReader.readModel(text));
        assertTrue(message.startsWith("huge.obj: its 1024 GB of OBJ text need about 1126 GB of heap; this JVM allows "),
                message);
    }

    @Test
    void theEstimateOfAFileReadsABptHeaderAndOtherwiseTheSize() throws IOException {
        Path bpt = Files.writeString(dir.resolve("big.bpt"), HEADER + "0 0 0\n");
        assertEquals(1_000_000L * HeapEstimates.patchBytes(15, 15), HeapEstimates.forFile(bpt));
        Path obj = Files.writeString(dir.resolve("m.obj"), "v 0 0 0\n".repeat(100));
        assertEquals(800, HeapEstimates.forFile(obj));
        assertEquals(0, HeapEstimates.forFile(dir.resolve("missing.bpt")));
    }

    @Test
    void anObjFileWithTooManyVertexLinesIsRefusedByCountingThemBeforeParsing() throws IOException {
        ReadLimits ten = new ReadLimits(ReadLimits.DEFAULT.lineChars(), ReadLimits.DEFAULT.bytesInMemory(),
                ReadLimits.DEFAULT.patches(), 10, ReadLimits.DEFAULT.sceneModels(), ReadLimits.DEFAULT.sceneObjects());
        Path many = Files.writeString(dir.resolve("many.obj"), "# eleven\n" + "v 0 0 0\n".repeat(11) + "f 1 2 3\n");
        String message = UserMessages.of(ModelFormatException.class,
                () -> HeapEstimates.requireObjVertexCount(many, "many.obj", ten));
        assertEquals("many.obj: a file may have at most 10 vertices; this one has more (v lines counted before parsing)",
                message);
        // vt, vn and vp lines are not vertices; CRLF lines count like LF ones
        Path fine = Files.writeString(dir.resolve("fine.obj"), "v 0 0 0\r\n".repeat(10) + "vt 0 0\n".repeat(20)
                + "vn 0 0 1\n".repeat(20) + "  v 1 1 1\n");
        HeapEstimates.requireObjVertexCount(fine, "fine.obj", ten);
    }
}
