package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.stream.Stream;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class BptWriterTest {

    private static final long SEED = 20240602L;

    @TempDir
    Path dir;

    @Test
    void randomPatchesOfEveryDegreeRoundTripExactly() {
        Random random = new Random(SEED);
        for (int trial = 0; trial < 50; trial++) {
            List<BezierPatch> patches = RandomPatches.scene(random, 1 + random.nextInt(4));
            String text = BptWriter.toString(patches);
            List<BezierPatch> back = BptReader.read(text, "random.bpt");
            int t = trial;
            assertEquals(patches, back, () -> "trial " + t + " (seed " + SEED + ") did not round-trip:\n" + text);
        }
    }

    @Test
    void wholeNumbersAreWrittenWithoutAFraction() {
        String text = BptWriter.toString(List.of(Models.flatGrid(2, 2)));
        assertEquals("1\n1 1\n-1.5 -1.5 0\n1.5 -1.5 0\n-1.5 1.5 0\n1.5 1.5 0\n", text);
    }

    @Test
    void theTeapotWrittenAndReadBackIsUnchanged() {
        List<BezierPatch> teapot = Models.teapot().patches();
        assertEquals(teapot, BptReader.read(BptWriter.toString(teapot), "teapot.bpt"));
    }

    @Test
    void savingReplacesTheFileAndLeavesNoTemporaryFile() throws IOException {
        Path file = dir.resolve("model.bpt");
        Files.writeString(file, "old content");
        List<BezierPatch> patches = Models.teapot().patches();
        BptWriter.write(file, patches);
        assertEquals(patches, FileFormats.BPT.read(file).scene().patches());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList(), "only the saved file should remain");
        }
    }

    @Test
    void aFailedSaveKeepsTheOldFileAndRemovesTheTemporaryOne() throws IOException {
        Path file = dir.resolve("keep.bpt");
        Files.writeString(file, "old content");
        UserMessages.of(IOException.class, () -> AtomicFiles.write(file, (Writer out) -> {
            out.write("half");
            throw new IOException("disk full");
        }));
        assertEquals("old content", Files.readString(file, StandardCharsets.UTF_8));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(file), files.toList());
        }
    }

    @Test
    void savingIntoANewFileCreatesIt() throws IOException {
        Path file = dir.resolve("new.bpt");
        assertFalse(Files.exists(file));
        BptWriter.write(file, List.of(Models.flatGrid(4, 4)));
        assertTrue(Files.readString(file).startsWith("1\n3 3\n"));
    }

    @Test
    void savingKeepsTheFilesPermissionsAndGivesNewFilesOrdinaryOnes() throws IOException {
        org.junit.jupiter.api.Assumptions.assumeTrue(
                Files.getFileStore(dir).supportsFileAttributeView(java.nio.file.attribute.PosixFileAttributeView.class),
                "POSIX permissions not supported here");
        Path fresh = dir.resolve("fresh.bpt");
        BptWriter.write(fresh, List.of(Models.flatGrid(2, 2)));
        assertEquals("rw-r--r--", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(fresh)));
        Path shared = dir.resolve("shared.bpt");
        Files.writeString(shared, "old");
        Files.setPosixFilePermissions(shared, java.nio.file.attribute.PosixFilePermissions.fromString("rw-rw-r--"));
        BptWriter.write(shared, List.of(Models.flatGrid(2, 2)));
        assertEquals("rw-rw-r--", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(shared)));
        assertTrue(Files.readString(shared).startsWith("1\n"));
    }
}
