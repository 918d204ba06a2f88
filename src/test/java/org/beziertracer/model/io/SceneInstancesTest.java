package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.Instance;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A model listed again in a scene file's {@code models} (the same built-in, or the same file) is one
 * model used several times: one {@link Instance} a use, every use holding the same list of model
 * patches (read once), each placed by its own transform.
 */
class SceneInstancesTest {

    @TempDir
    Path dir;

    @Test
    void aBuiltInListedThreeTimesIsOneModelPlacedThreeTimes() {
        Scene scene = SceneFiles.parse("""
                {"version": 1, "models": [
                  {"builtin": "teapot"},
                  {"builtin": "teapot", "transform": {"translate": [10, 0, 0]}},
                  {"patches": [{"degree": [1, 1], "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]}]},
                  {"builtin": "teapot", "transform": {"scale": 0.5, "rotate": [10, 20, 30], "translate": [1, 2, 3]}}]}
                """, "test.json", null).scene();
        List<Instance> uses = scene.instances();
        assertEquals(List.of(0, 32, 65), uses.stream().map(Instance::first).toList(), "the inline patch is the scene's own");
        assertSame(uses.get(0).model(), uses.get(1).model(), "one model list");
        assertSame(uses.get(0).model(), uses.get(2).model(), "one model list");
        assertEquals(Models.teapot().patches(), uses.get(0).model());
        ModelTransform t = new ModelTransform(new double[] {1, 2, 3}, new double[] {.5, .5, .5}, new double[] {10, 20, 30});
        for (int k = 0; k < 32; k++) {
            assertEquals(t.apply(Models.teapot().patches().get(k), k + 1), scene.patches().get(65 + k), "patch " + k);
        }
        assertTrue(uses.get(2).placement().similarity(), "a uniform scale, rotations and a translation");
    }

    @Test
    void aFileListedTwiceIsReadOnceAndIsOneModel() throws IOException {
        BptWriter.write(dir.resolve("cup.bpt"), Models.teapot().patches().subList(0, 4));
        Scene scene = SceneFiles.parse("""
                {"version": 1, "models": [{"file": "cup.bpt"}, {"file": "./cup.bpt", "transform": {"rotate": [0, 0, 45]}}]}
                """, "test.json", dir).scene();
        assertEquals(2, scene.instances().size());
        assertSame(scene.instances().get(0).model(), scene.instances().get(1).model(), "read once: one model list");
    }

    @Test
    void aScaleThatDiffersBetweenAxesIsNotASimilarity() {
        assertTrue(new ModelTransform(new double[3], new double[] {2, -2, 2}, new double[] {0, 90, 0}).similarity());
        assertFalse(new ModelTransform(new double[3], new double[] {2, 1, 2}, new double[3]).similarity());
    }
}
