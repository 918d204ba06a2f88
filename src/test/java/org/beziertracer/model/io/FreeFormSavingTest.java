package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Saving rational and trimmed models: OBJ keeps them, BPT refuses, scene files keep weights and domains. */
class FreeFormSavingTest {

    @TempDir
    Path dir;

    @Test
    void objFilesKeepRationalAndTrimmedModels() throws IOException {
        for (String name : List.of("sphere", "trimmed-plate")) {
            Path file = dir.resolve(name + ".obj");
            List<BezierPatch> patches = Models.load(name).patches();
            FileFormats.OBJ.write(file, new SceneDocument(new Scene(patches), RenderSettings.defaults()));
            assertEquals(patches, Models.load(file.toString()).patches(), name);
        }
    }

    @Test
    void bptRefusesRationalAndTrimmedPatchesWithOneLineAndWritesNothing() {
        Path file = dir.resolve("sphere.bpt");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> FileFormats.BPT.write(file, new SceneDocument(Models.load("sphere"), RenderSettings.defaults())));
        assertTrue(e.getMessage().contains("patch 1 is rational; save the model as .obj"), e.getMessage());
        assertFalse(Files.exists(file));
        e = assertThrows(IllegalArgumentException.class, () -> FileFormats.BPT.write(dir.resolve("plate.bpt"),
                new SceneDocument(Models.load("trimmed-plate"), RenderSettings.defaults())));
        assertTrue(e.getMessage().contains("is trimmed"), e.getMessage());
    }

    @Test
    void bptRefusesAModelWithATriangleMeshWithOneLineAndWritesNothing() {
        Path file = dir.resolve("floor.bpt");
        org.beziertracer.model.Mesh floor = org.beziertracer.model.Mesh.faces(
                new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, null, null, new int[] {0, 1, 2});
        Scene scene = Models.load("patch").toBuilder().addMesh(floor, 0).build();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> FileFormats.BPT.write(file, new SceneDocument(scene, RenderSettings.defaults())));
        assertEquals("a BPT file holds Bézier patches only but the model has 1 triangle mesh; save the model as .obj",
                e.getMessage());
        assertFalse(Files.exists(file));
    }

    @Test
    void sceneFilesKeepWeightsDomainsAndTrims() {
        Scene sphere = Models.load("sphere");
        String json = SceneFiles.toJson(new SceneDocument(sphere, RenderSettings.defaults()));
        assertTrue(json.contains("\"weights\""), json);
        assertTrue(json.contains("\"domain\": [3, 4, 1, 2]"), json);
        assertEquals(sphere.patches(), SceneFiles.parse(json, "sphere.json", null).scene().patches());
        Scene plate = Models.load("trimmed-plate");
        String trimmed = SceneFiles.toJson(new SceneDocument(plate, RenderSettings.defaults()));
        assertTrue(trimmed.contains("\"trim\""), trimmed);
        assertEquals(plate.patches(), SceneFiles.parse(trimmed, "plate.json", null).scene().patches());
    }

    @Test
    void anOpenTrimLoopInASceneFileNamesItsJsonPath() {
        String json = "{\"version\": 1, \"models\": [{\"patches\": [{\"degree\": [1, 1], \"points\": [[0,0,0],[1,0,0],"
                + "[0,1,0],[1,1,0]], \"trim\": {\"holes\": [[{\"curve\": {\"basis\": \"bezier\", \"degree\": 1,"
                + " \"parm\": [0, 1], \"points\": [[0.2, 0.2], [0.8, 0.2]]}, \"from\": 0, \"to\": 1}]]}}]}]}";
        ModelFormatException e = assertThrows(ModelFormatException.class, () -> SceneFiles.parse(json, "t.json", null));
        assertTrue(e.getMessage().contains("trim.holes[0]"), e.getMessage());
        assertTrue(e.getMessage().contains("expected a closed trim loop"), e.getMessage());
    }

    @Test
    void aBadInlineWeightNamesItsJsonPath() {
        String json = "{\"version\": 1, \"models\": [{\"patches\": [{\"degree\": [1, 1], \"points\": [[0,0,0],[1,0,0],"
                + "[0,1,0],[1,1,0]], \"weights\": [1, 1, 0, 1]}]}]}";
        ModelFormatException e = assertThrows(ModelFormatException.class, () -> SceneFiles.parse(json, "w.json", null));
        assertTrue(e.getMessage().contains("weights"), e.getMessage());
        assertTrue(e.getMessage().contains("expected positive finite weights, found 0.0 for control point 3"),
                e.getMessage());
    }
}
