package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A file the reader skipped parts of (a CAD export with 3-D curves and connectivity) opens, and
 * its note is shown once: {@code info} among its lines, {@code render}, {@code trace} and
 * {@code analyze} on standard error (their standard output unchanged).
 */
class ReadNotesTest {

    @TempDir
    Path dir;

    private Path cad;
    private String note;

    @BeforeEach
    void writeTheCadExport() throws IOException {
        cad = dir.resolve("cad-export.obj");
        try (InputStream in = getClass().getResourceAsStream("/org/beziertracer/model/io/cad-export.obj")) {
            Files.write(cad, in.readAllBytes());
        }
        note = "note: " + cad + ": skipped 2 curv, 1 scrv, 1 sp, 1 con (3-D curves, special curves, special points and "
                + "connectivity hints are not drawn)\n";
    }

    private static int count(String text, String part) {
        int n = 0;
        for (int at = text.indexOf(part); at >= 0; at = text.indexOf(part, at + 1)) {
            n++;
        }
        return n;
    }

    @Test
    void infoPrintsTheNoteAfterTheModelLine() {
        Run r = Run.of("info", cad.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("model: " + cad + "\n" + note + "patches: 2\n"), r.out());
        assertEquals("", r.err());
    }

    @Test
    void renderTraceAndAnalyzePrintTheNoteOnceOnStandardError() throws IOException {
        Path png = dir.resolve("cad.png");
        Run render = Run.of("render", cad.toString(), "-o", png.toString(), "--size", "16x12", "--stats", "--quiet");
        assertEquals(0, render.code(), render.err());
        assertEquals(1, count(render.err(), note), render.err());
        assertFalse(render.out().contains("note:"), "the --stats JSON line stays alone: " + render.out());
        assertTrue(Files.size(png) > 0);

        Run trace = Run.of("trace", cad.toString(), "--random", "10");
        assertEquals(0, trace.code(), trace.err());
        assertEquals(note, trace.err());
        assertFalse(trace.out().contains("note:"), trace.out());

        Run analyze = Run.of("analyze", cad.toString(), "--quiet");
        assertEquals(0, analyze.code(), analyze.err());
        assertEquals(note, analyze.err());
    }

    @Test
    void aFileWithoutNotesPrintsNone() {
        Run r = Run.of("info", "teapot");
        assertFalse(r.out().contains("note:"), r.out());
    }
}
