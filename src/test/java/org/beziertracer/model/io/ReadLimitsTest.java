package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

/** Every cap of {@link ReadLimits} is enforced and named in its message (checked with small caps). */
class ReadLimitsTest {

    /** Lines of 40 characters, 1 MB in memory, 3 patches, 5 vertices, 2 models, 2 of each object. */
    static final ReadLimits SMALL = new ReadLimits(40, 1 << 20, 3, 5, 2, 2);

    private static TextSource text(String s, String name) {
        return new TextSource(new ByteArrayInputStream(s.getBytes(StandardCharsets.UTF_8)), name, SMALL);
    }

    private static String objError(String obj) {
        return UserMessages.of(ModelFormatException.class, () -> ObjReader.read(text(obj, "m.obj")));
    }

    private static String sceneError(String json) {
        return UserMessages.of(ModelFormatException.class, () -> SceneFiles.read(text(json, "s.json"), null));
    }

    @Test
    void objVertexAndPatchCountsAreCapped() {
        assertEquals("m.obj:6: a file may have at most 5 vertices; this is one more",
                objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\n"));
        String quad = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\ncstype bezier\ndeg 1 1\n";
        String surf = "surf 0 1 0 1 1 2 3 4\nend\n";
        assertEquals("m.obj:13: a model may have at most 3 patches; this surf makes 1 more after 3",
                objError(quad + surf + surf + surf + surf));
    }

    @Test
    void objLinesAndJoinedStatementsAreCapped() {
        assertEquals("m.obj:2: line longer than 40 characters, the most a line may hold",
                objError("v 0 0 0\n#" + "x".repeat(40) + "\n"));
        String continued = ("surf 0 1 0 1 1 1 1 1 1 1 1 1 \\\n").repeat(8);
        assertEquals("m.obj:1: statement longer than " + ObjReader.STATEMENT_LINES * 40 + " characters (joined"
                + " continuation lines), the most a statement may hold", objError(continued));
    }

    @Test
    void bptPatchCountsAreCapped() {
        String message = UserMessages.of(ModelFormatException.class, () -> BptReader.read(text("4\n", "m.bpt")));
        assertEquals("m.bpt:1: expected the patch count, found \"4\": patch count 4 out of range 1..3", message);
    }

    @Test
    void sceneListsAndPatchTotalsAreCapped() {
        String sphere = "{\"center\": [0, 0, 0], \"radius\": 1}";
        assertEquals("s.json: spheres: 3 spheres, more than the 2 a scene may hold", sceneError(
                "{\"version\": 1, \"spheres\": [" + sphere + ", " + sphere + ", " + sphere + "]}"));
        String model = "{\"builtin\": \"patch\"}";
        assertEquals("s.json: models: 3 models, more than the 2 a scene may hold", sceneError(
                "{\"version\": 1, \"models\": [" + model + ", " + model + ", " + model + "]}"));
        assertEquals("s.json: materials: 3 materials, more than the 2 a scene may hold", sceneError(
                "{\"version\": 1, \"materials\": {\"a\": {}, \"b\": {}, \"c\": {}}, \"spheres\": [" + sphere + "]}"));
        assertEquals("s.json: models[1]: the scene would hold 33 patches, more than the 3 a scene may hold",
                sceneError("{\"version\": 1, \"models\": [" + model + ", {\"builtin\": \"teapot\"}]}"));
    }
}
