package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.math.Aabb;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ModelsTest {

    @TempDir
    Path dir;

    @Test
    void theDefaultPatchIsAFlatBicubicSquare() {
        Scene scene = Models.load("patch");
        assertEquals(1, scene.patchCount());
        BezierPatch p = scene.patches().get(0);
        assertEquals(3, p.degreeU());
        assertEquals(3, p.degreeV());
        double[] coords = {-1.5, -0.5, 0.5, 1.5};
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                String where = "P(" + i + "," + j + ")";
                assertEquals(coords[i], p.get(i, j, 0), where);
                assertEquals(coords[j], p.get(i, j, 1), where);
                assertEquals(0.0, p.get(i, j, 2), where);
            }
        }
    }

    @Test
    void flatGridsOfEverySizeSpanTheSameSquare() {
        for (int pu = 2; pu <= 16; pu++) {
            for (int pv = 2; pv <= 16; pv++) {
                BezierPatch p = Models.flatGrid(pu, pv);
                String where = pu + "x" + pv;
                assertEquals(pu - 1, p.degreeU(), where);
                assertEquals(pv - 1, p.degreeV(), where);
                assertEquals(new Aabb(-1.5, -1.5, 0, 1.5, 1.5, 0), p.controlBounds(), where);
            }
        }
    }

    @Test
    void flatGridsOutsideTwoToSixteenPointsAreRejected() {
        UserMessages.of(IllegalArgumentException.class, () -> Models.flatGrid(1, 4));
        UserMessages.of(IllegalArgumentException.class, () -> Models.flatGrid(4, 17));
    }

    @Test
    void theTeapotHas32BicubicPatchesInItsDocumentedBox() {
        Scene teapot = Models.load("teapot");
        assertEquals(32, teapot.patchCount());
        assertTrue(teapot.patches().stream().allMatch(p -> p.degreeU() == 3 && p.degreeV() == 3));
        assertEquals("x[-120,141] y[-80,80] z[0,120]", teapot.controlBounds().toString());
        assertEquals(teapot.patches(), Models.load("TEAPOT").patches());
    }

    @Test
    void pathsAreReadByExtension() throws IOException {
        List<BezierPatch> patches = List.of(Models.flatGrid(3, 5), Models.flatGrid(2, 2));
        Path bpt = dir.resolve("m.BPT");
        Path obj = dir.resolve("m.obj");
        FileFormats.BPT.write(bpt, new SceneDocument(new Scene(patches), RenderSettings.defaults()));
        FileFormats.OBJ.write(obj, new SceneDocument(new Scene(patches), RenderSettings.defaults()));
        assertEquals(patches, Models.load(bpt.toString()).patches());
        assertEquals(patches, Models.load(obj.toString()).patches());
        assertTrue(Files.readString(obj).contains("cstype bezier"));
    }

    @Test
    void anUnknownExtensionOrMissingFileIsAOneLineErrorNamingTheFile() {
        String e = UserMessages.of(ModelFormatException.class, () -> Models.load("model.stl"));
        assertEquals("model.stl: not a built-in name (patch, teapot, teacup, teaspoon, sphere, torus, trimmed-plate,"
                + " wavy6, wavy10, curved, teapot-room, studio) and not a .bpt, .obj, .igs, .iges, .stp, .step or .json file",
                e);
        String missing = dir.resolve("missing.bpt").toString();
        e = UserMessages.of(ModelFormatException.class, () -> Models.load(missing));
        assertEquals(missing + ": no such file", e);
    }

    @Test
    void parseErrorsInALoadedFileNameThePathAsGiven() throws IOException {
        Path bad = dir.resolve("bad.bpt");
        Files.writeString(bad, "1\n3 3\n0 0 oops\n");
        String e = UserMessages.of(ModelFormatException.class, () -> Models.load(bad.toString()));
        assertTrue(e.startsWith(bad + ":3: expected a number for the z coordinate of point 1"),
                e);
    }
}
