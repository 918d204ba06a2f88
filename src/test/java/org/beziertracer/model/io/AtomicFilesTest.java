package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AtomicFilesTest {

    @TempDir
    Path dir;

    private List<String> names() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aFailedWriteNamesTheTargetAndTheReasonNeverTheTemporaryFile() throws IOException {
        Path target = dir.resolve("teapot.bpt");
        Files.writeString(target, "old");
        String denied = UserMessages.of(IOException.class, () -> AtomicFiles.write(target, out -> {
            throw new AccessDeniedException(dir.resolve(".teapot.bpt.123.tmp").toString());
        }));
        assertEquals(target + ": cannot write: permission denied", denied);
        String full = UserMessages.of(IOException.class, () -> AtomicFiles.write(target, out -> {
            throw new IOException("No space left on device");
        }));
        assertEquals(target + ": cannot write: disk full", full);
        assertEquals("old", Files.readString(target), "the old file stays whole");
        assertEquals(List.of("teapot.bpt"), names(), "no temporary file left");
    }

    @Test
    void aMissingFolderIsNamed() {
        Path target = dir.resolve("gone").resolve("teapot.bpt");
        String message = UserMessages.of(IOException.class, () -> AtomicFiles.write(target, out -> out.write("x")));
        assertEquals(target + ": cannot write: the folder " + dir.resolve("gone") + " does not exist", message);
    }

    @Test
    void aSaveRemovesStaleTemporaryFilesOfTheSameTargetOnly() throws IOException {
        for (String stale : List.of(".teapot.bpt.123.tmp", ".teapot.bpt.98765432101234.tmp")) {
            Files.writeString(dir.resolve(stale), "left by a killed save");
        }
        List<String> others = List.of(".other.bpt.5.tmp", ".teapot.bpt.notes.tmp", "teapot.bpt.1.tmp");
        for (String other : others) {
            Files.writeString(dir.resolve(other), "not ours");
        }
        AtomicFiles.write(dir.resolve("teapot.bpt"), out -> out.write("new"));
        assertEquals(Stream.concat(others.stream(), Stream.of("teapot.bpt")).sorted().toList(), names());
        assertEquals("new", Files.readString(dir.resolve("teapot.bpt")));
    }

    @Test
    void writingOverAFolderSaysSo() throws IOException {
        Path folder = Files.createDirectory(dir.resolve("model.bpt"));
        Files.writeString(folder.resolve("inside"), "x");
        String message = UserMessages.of(IOException.class, () -> AtomicFiles.write(folder, out -> out.write("x")));
        assertEquals(folder + ": cannot write: is a folder", message);
        assertFalse(names().stream().anyMatch(n -> n.endsWith(".tmp")), names().toString());
        assertTrue(Files.isDirectory(folder));
    }

    @Test
    void aDeviceIsWrittenInPlaceNeverReplacedByAFile() throws IOException {
        Path devNull = Path.of("/dev/null"), devFull = Path.of("/dev/full");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.exists(devNull) && Files.exists(devFull), "a Linux /dev");
        Path copy = dir.resolve("null-link");
        Files.createSymbolicLink(copy, devNull);
        AtomicFiles.write(copy, out -> out.write("gone"));
        assertTrue(Files.isSymbolicLink(copy) && !Files.isRegularFile(devNull), "/dev/null stays a device");
        String full = UserMessages.of(IOException.class, () -> AtomicFiles.write(devFull, out -> out.write("x".repeat(1 << 16))));
        assertEquals("/dev/full: cannot write: disk full", full);
        assertFalse(Files.isRegularFile(devFull), "/dev/full stays a device");
    }

    @Test
    void aLinkStaysALinkAndItsFileIsReplaced() throws IOException {
        Path file = Files.writeString(dir.resolve("real.bpt"), "old");
        Path link = Files.createSymbolicLink(dir.resolve("link.bpt"), file.getFileName());
        AtomicFiles.write(link, out -> out.write("new"));
        assertTrue(Files.isSymbolicLink(link), "still a link");
        assertEquals("new", Files.readString(file));
        assertEquals(List.of("link.bpt", "real.bpt"), names());
    }
}
