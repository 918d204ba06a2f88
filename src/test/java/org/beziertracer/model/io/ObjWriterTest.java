package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ObjWriterTest {

    private static final long SEED = 7_2024L;

    @TempDir
    Path dir;

    @Test
    void randomPatchesOfEveryDegreeRoundTripExactly() {
        Random random = new Random(SEED);
        for (int trial = 0; trial < 50; trial++) {
            List<BezierPatch> patches = RandomPatches.scene(random, 1 + random.nextInt(4));
            String text = ObjWriter.toString(patches);
            int t = trial;
            assertEquals(patches, ObjReader.read(text, "random.obj"),
                    () -> "trial " + t + " (seed " + SEED + ") did not round-trip:\n" + text);
        }
    }

    @Test
    void theTeapotGoesFromBptToObjAndBackToTheSameBytes() {
        List<BezierPatch> teapot = Models.teapot().patches();
        String bpt = BptWriter.toString(teapot);
        List<BezierPatch> viaObj = ObjReader.read(ObjWriter.toString(BptReader.read(bpt, "teapot.bpt")), "teapot.obj");
        assertEquals(teapot, viaObj);
        assertEquals(bpt, BptWriter.toString(viaObj));
    }

    @Test
    void theResourceTeapotRoundTripsThroughObjFiles() throws IOException {
        Path obj = dir.resolve("teapot.obj");
        Path bpt = dir.resolve("teapot.bpt");
        ObjWriter.write(obj, Models.teapot().patches());
        BptWriter.write(bpt, FileFormats.OBJ.read(obj).scene().patches());
        assertEquals(Models.teapot().patches(), FileFormats.BPT.read(bpt).scene().patches());
    }

    @Test
    void theOutputIsTheDocumentedSubset() {
        String text = ObjWriter.toString(List.of(Models.flatGrid(2, 2)));
        assertTrue(text.contains("cstype bezier\n"), text);
        assertTrue(text.contains("v -1.5 -1.5 0\n"), text);
        assertTrue(text.contains("deg 1 1\nsurf 0 1 0 1 1 2 \\\n     3 4\nparm u 0 1\nparm v 0 1\nend\n"), text);
    }

    @Test
    void aLaterPatchNamesThePointsItSharesAndWritesOnlyItsNewOnes() {
        String text = ObjWriter.toString(List.of(Models.flatGrid(2, 2), Models.flatGrid(3, 2)));
        // the 3x2 grid shares its four corners with the 2x2 one: only its two middle points are new
        assertTrue(text.contains("# patch 2\nv 0 -1.5 0\nv 0 1.5 0\ndeg 2 1\n"), text);
        assertTrue(text.contains("surf 0 1 0 1 1 5 2 \\\n     3 6 4\n"), text);
    }

    @Test
    void theTeapotWritesEachDistinctControlPointOnceAndReadsBackTheSame() {
        var teapot = Models.teapot();
        java.util.Set<java.util.List<Double>> distinct = new java.util.HashSet<>();
        for (var p : teapot.patches()) {
            double[] net = p.copyNet();
            for (int k = 0; k < net.length; k += 3) {
                distinct.add(java.util.List.of(net[k], net[k + 1], net[k + 2]));
            }
        }
        String text = ObjWriter.toString(teapot.patches());
        long vLines = text.lines().filter(l -> l.startsWith("v ")).count();
        assertEquals(distinct.size(), vLines);
        assertTrue(vLines < 32 * 16, "no point shared: " + vLines);
    }
}
