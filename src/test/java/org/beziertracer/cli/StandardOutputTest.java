package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.beziertracer.Main;
import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Output that cannot be written (a full disk) fails the command in one line (issue 36); a reader that left ends it quietly. */
class StandardOutputTest {

    @TempDir
    Path dir;

    /** A stream that refuses every write with one error (a full disk's, a closed pipe's), counting the attempts. */
    private static class Refusing extends OutputStream {
        final AtomicInteger attempts = new AtomicInteger();
        private final String error;

        Refusing(String error) {
            this.error = error;
        }

        @Override
        public void write(int b) throws IOException {
            write(new byte[] {(byte) b}, 0, 1);
        }

        @Override
        public void write(byte[] b, int off, int len) throws IOException {
            attempts.incrementAndGet();
            throw new IOException(error);
        }
    }

    /** A full disk. */
    private static final class FullDisk extends Refusing {
        FullDisk() {
            super("No space left on device");
        }
    }

    /** A pipe whose reader has gone, as one into {@code head -1} after its line. */
    private static final class ClosedPipe extends Refusing {
        ClosedPipe() {
            super("Broken pipe");
        }
    }

    private static Run toFullDisk(FullDisk disk, String... args) {
        return Run.writingTo(StandardOutput.over(disk, StandardCharsets.UTF_8), args);
    }

    @Test
    void everyCommandThatWritesToAFullDiskFailsInOneLine() {
        String png = dir.resolve("p.png").toString();
        List<List<String>> commands = List.of(List.of("info", "teapot"), List.of("trace", "patch", "--random", "5"),
                List.of("render", "patch", "--size", "8x8", "-o", png, "--stats"), List.of("analyze", "patch"),
                List.of("render", "--help"));
        for (List<String> command : commands) {
            Run r = toFullDisk(new FullDisk(), command.toArray(String[]::new));
            assertEquals(1, r.code(), command + ": " + r.err());
            assertEquals("beziertracer " + command.get(0) + ": standard output: write failed (disk full)",
                    UserMessages.checkOneLineOutput(r.err()), command.toString());
        }
    }

    @Test
    void aCommandWhoseReaderLeftEndsQuietlyAsUnixToolsDo() {
        for (String[] command : List.of(new String[] {"info", "teapot"}, new String[] {"analyze", "patch"})) {
            ClosedPipe pipe = new ClosedPipe();
            Run r = Run.writingTo(StandardOutput.over(pipe, StandardCharsets.UTF_8), command);
            assertEquals(StandardOutput.EXIT_CLOSED_PIPE, r.code(), r.err());
            assertEquals("", r.err(), "no error line: the reader chose to stop reading");
            assertTrue(pipe.attempts.get() > 0);
        }
        ClosedPipe pipe = new ClosedPipe();
        Run r = Run.writingTo(StandardOutput.over(pipe, StandardCharsets.UTF_8), "trace", "patch", "--random", "2000000");
        assertEquals(StandardOutput.EXIT_CLOSED_PIPE, r.code(), r.err());
        assertTrue(pipe.attempts.get() < 10, "writes attempted after the reader left: " + pipe.attempts.get());
    }

    @Test
    void aChildProcessPipedIntoAReaderThatLeavesExitsQuietly() throws Exception {
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "trace", "patch", "--random", "2000000").directory(dir.toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
        try (var in = p.getInputStream()) {
            assertTrue(in.read() >= 0, "the child starts writing"); // then the reader leaves, as head -c 1 does
        }
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child ends soon after its reader left");
        String err = Files.readString(dir.resolve("err.txt"));
        assertEquals(StandardOutput.EXIT_CLOSED_PIPE, p.exitValue(), err);
        assertEquals("", err.lines().filter(l -> !l.startsWith("WARNING: Using incubator modules")).reduce("", String::concat));
    }

    @Test
    void aWriterThatKeepsNoReasonStillFails() {
        Run r = Run.writingTo(new PrintWriter(new FullDisk()), "info", "patch");
        assertEquals(1, r.code(), r.err());
        assertEquals("beziertracer info: standard output: write failed (input/output error)",
                UserMessages.checkOneLineOutput(r.err()));
    }

    @Test
    void aLongTraceStopsSoonAfterTheFirstFailedWrite() {
        FullDisk disk = new FullDisk();
        Run r = toFullDisk(disk, "trace", "patch", "--random", "2000000");
        assertEquals(1, r.code(), r.err());
        assertTrue(disk.attempts.get() < 10, "writes attempted after the first failure: " + disk.attempts.get());
    }

    @Test
    void aChildProcessWritingToDevFullExitsWithOneLine() throws Exception {
        File devFull = new File("/dev/full");
        org.junit.jupiter.api.Assumptions.assumeTrue(devFull.exists(), "a Linux /dev/full");
        Process p = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), Main.class.getName(),
                "info", "teapot").directory(dir.toFile()).redirectOutput(devFull)
                .redirectError(dir.resolve("err.txt").toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child finishes");
        String err = Files.readString(dir.resolve("err.txt"));
        assertEquals(1, p.exitValue(), err);
        assertEquals("beziertracer info: standard output: write failed (disk full)", UserMessages.checkOneLineOutput(err));
    }

    @Test
    void traceToDevFullNamesTheFile() {
        org.junit.jupiter.api.Assumptions.assumeTrue(new File("/dev/full").exists(), "a Linux /dev/full");
        Run r = Run.of("trace", "patch", "--random", "5000", "-o", "/dev/full");
        assertEquals(1, r.code(), r.err());
        assertEquals("beziertracer trace: /dev/full: cannot write: disk full", UserMessages.checkOneLineOutput(r.err()));
        assertTrue(new File("/dev/full").exists() && !Files.isRegularFile(Path.of("/dev/full")), "still a device");
    }
}
