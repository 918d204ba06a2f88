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
    void laterPatchesReferToTheirOwnVertices() {
        String text = ObjWriter.toString(List.of(Models.flatGrid(2, 2), Models.flatGrid(3, 2)));
        assertTrue(text.contains("surf 0 1 0 1 5 6 7 \\\n     8 9 10\n"), text);
    }
}
