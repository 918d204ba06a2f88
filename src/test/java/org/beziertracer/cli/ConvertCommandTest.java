package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.SceneFiles;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code convert IN OUT}: any readable model to any writable format, atomically, never over its input. */
class ConvertCommandTest {

    @TempDir
    Path dir;

    private static List<double[]> nets(String file) {
        return SceneFiles.load(file).scene().patches().stream().map(BezierPatch::copyNet).toList();
    }

    @Test
    void theTeapotGoesToIgesAndObjAndComesBackTheSame() {
        for (String name : new String[] {"teapot.igs", "teapot.obj", "teapot.bpt"}) {
            Path out = dir.resolve(name);
            Run r = Run.of("convert", "teapot", out.toString());
            assertEquals(0, r.code(), r.err());
            assertTrue(r.out().startsWith("wrote " + out + " ("), r.out());
            assertTrue(r.out().endsWith(": 32 patches\n"), r.out());
            List<double[]> expected = nets("teapot"), actual = nets(out.toString());
            assertEquals(expected.size(), actual.size());
            for (int k = 0; k < expected.size(); k++) {
                org.junit.jupiter.api.Assertions.assertArrayEquals(expected.get(k), actual.get(k), name + " patch " + k);
            }
        }
    }

    @Test
    void anOutputWithoutAWritableExtensionIsRefusedBeforeReading() {
        Run r = Run.of("convert", "no-such-file.obj", dir.resolve("x.png").toString());
        assertEquals(1, r.code());
        assertEquals("beziertracer convert: " + dir.resolve("x.png") + ": expected a file name ending in .bpt, .obj, "
                + ".igs, .iges, .stp, .step or .json (the format to write)\n", r.err());
    }

    @Test
    void theInputIsNeverOverwritten() throws Exception {
        Path in = dir.resolve("a.obj");
        assertEquals(0, Run.of("convert", "teapot", in.toString()).code());
        String before = Files.readString(in);
        Run r = Run.of("convert", in.toString(), dir.resolve(".").resolve("a.obj").toString());
        assertEquals(1, r.code());
        assertTrue(r.err().endsWith(": is the input file; write to another name\n"), r.err());
        assertEquals(before, Files.readString(in));
    }

    @Test
    void aModelTheFormatCannotHoldLeavesTheOldFileAsItWas() throws Exception {
        Path mesh = dir.resolve("mesh.obj");
        Files.writeString(mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        Path out = dir.resolve("old.igs");
        Files.writeString(out, "old");
        Run r = Run.of("convert", mesh.toString(), out.toString());
        assertEquals(1, r.code());
        assertEquals(1, r.err().lines().count(), r.err());
        assertTrue(r.err().contains("triangle mesh"), r.err());
        assertEquals("old", Files.readString(out));
    }

    @Test
    void whatTheReaderSkippedIsNotedOnStandardError() throws Exception {
        Path in = Path.of(ConvertCommandTest.class.getResource("/org/beziertracer/model/io/cad-export.obj").toURI());
        Path out = dir.resolve("cad.igs");
        Run r = Run.of("convert", in.toString(), out.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.err().startsWith("note: " + in + ": skipped 2 curv"), r.err());
        assertEquals(SceneFiles.load(in.toString()).scene().patchCount(), SceneFiles.load(out.toString()).scene().patchCount());
    }
}
