package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.io.Models;
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
    void infoPrintsTheBytesTheAccelerationDataHolds() {
        Run r = run("info", "--accel", "teapot");
        assertEquals(0, r.code(), r.err());
        SceneIntersector si = SceneIntersector.build(Models.teapot(), IntersectOptions.defaults());
        long leaves = si.leafBytes(), nodes = si.accelBytes();
        assertTrue(leaves > 1566 * 48L && nodes >= 32L * si.nodeCount(), leaves + " / " + nodes);
        String expected = String.format(java.util.Locale.ROOT, "acceleration data: %,d bytes (", leaves + nodes);
        assertTrue(r.out().contains(expected), r.out());
        assertTrue(r.out().contains(String.format(java.util.Locale.ROOT, "%,d a patch): sub-patches %,d, BVH %,d\n",
                (leaves + nodes) / 32, leaves, nodes)), r.out());
    }

    @Test
    void withoutAccelInfoPrintsTheSummaryOnlyAndBuildsNothing() {
        Run r = run("info", "teapot");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().endsWith("control-point bounds: x[-120,141] y[-80,80] z[0,120]\n"), r.out());
        for (String absent : new String[] {"sub-patches:", "bvh:", "build:", "acceleration data:"}) {
            assertTrue(!r.out().contains(absent), absent + " in " + r.out());
        }
    }

    @Test
    void accelAddsTheSplitAndBvhFiguresAfterTheSameSummary() {
        Run plain = run("info", "teapot");
        Run accel = run("info", "--accel", "teapot");
        assertEquals(0, accel.code(), accel.err());
        assertTrue(accel.out().startsWith(plain.out()), accel.out());
        String tail = accel.out().substring(plain.out().length());
        assertTrue(tail.matches("sub-patches: \\d+\nbvh: \\d+ nodes, depth \\d+\nbuild: [0-9.]+ ms \\(split \\+ BVH\\)\n"
                + "acceleration data: [0-9,]+ bytes .*\n"), tail);
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
    void infoSpherePrintsTheRationalSurfaceAndItsPieces() {
        Run r = run("info", "sphere");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("patches: 8\n"), r.out());
        assertTrue(r.out().contains("rational patches: 8\n"), r.out());
        assertTrue(r.out().contains("surfaces: 1\n"), r.out());
        assertTrue(r.out().contains("  surface 1: rational bspline, degree 2x2, 9x5 control points, u[0,4] v[0,2],"
                + " untrimmed -> 8 Bézier pieces (patches 1-8)\n"), r.out());
    }

    @Test
    void infoTrimmedPlatePrintsItsTrimLoops() {
        Run r = run("info", "trimmed-plate");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("trimmed patches: 1\n"), r.out());
        assertTrue(r.out().contains("trimmed by 1 outer loop (8 curves) and 3 holes (1 curve, 1 curve, 1 curve)"),
                r.out());
    }

    @Test
    void plainPatchesHaveNoSurfaces() {
        Run r = run("info", "teapot");
        assertTrue(r.out().contains("rational patches: 0\ntrimmed patches: 0\nsurfaces: 0\n"), r.out());
    }

    @Test
    void helpDescribesTheCommand() {
        Run r = run("info", "--help");
        assertEquals(0, r.code());
        assertTrue(r.out().contains("MODEL"), r.out());
        assertTrue(r.out().contains("--accel"), r.out());
    }
}
