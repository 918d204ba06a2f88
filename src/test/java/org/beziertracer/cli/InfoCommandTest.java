package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class InfoCommandTest {

    @TempDir
    Path dir;

    private static Run run(String... args) {
        return Run.of(args);
    }

    @Test
    void infoTeapotPrints32PatchesAndTheControlBox() {
        Run r = run("info", "teapot");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("patches: 32\n"), r.out());
        assertTrue(r.out().contains("degrees: 3x3 (32)\n"), r.out());
        assertTrue(r.out().contains("x[-120,141] y[-80,80] z[0,120]"), r.out());
        assertEquals("", r.err());
    }

    @Test
    void infoPatchPrintsTheDefaultPatch() {
        Run r = run("info", "patch");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("patches: 1\n"), r.out());
        assertTrue(r.out().contains("degrees: 3x3 (1)\n"), r.out());
        assertTrue(r.out().contains("x[-1.5,1.5] y[-1.5,1.5] z[0,0]"), r.out());
    }

    @Test
    void mixedDegreesAreListedAsAHistogram() throws IOException {
        Path file = dir.resolve("mixed.bpt");
        Files.writeString(file, "3\n1 1 0 0 0 1 0 0 0 1 0 1 1 0\n"
                + "2 1 0 0 0 1 0 0 2 0 0 0 1 0 1 1 0 2 1 0\n1 1 0 0 0 1 0 0 0 1 0 1 1 5\n");
        Run r = run("info", file.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("degrees: 1x1 (2), 2x1 (1)\n"), r.out());
        assertTrue(r.out().contains("x[0,2] y[0,1] z[0,5]"), r.out());
    }

    @Test
    void aParseErrorIsOneLineWithExitCodeOne() throws IOException {
        Path file = dir.resolve("broken.bpt");
        Files.writeString(file, "1\n3 3\n0 0 abc\n");
        Run r = run("info", file.toString());
        assertEquals(1, r.code());
        assertEquals("", r.out());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.startsWith("beziertracer info: " + file + ":3: expected a number"), line);
    }

    @Test
    void aMissingFileIsOneLineWithExitCodeOne() {
        Run r = run("info", "no-such-model.obj");
        assertEquals(1, r.code());
        assertEquals("beziertracer info: no-such-model.obj: no such file", UserMessages.checkOneLineOutput(r.err()));
    }

    @Test
    void helpDescribesTheCommand() {
        Run r = run("info", "--help");
        assertEquals(0, r.code());
        assertTrue(r.out().contains("MODEL"), r.out());
    }
}
