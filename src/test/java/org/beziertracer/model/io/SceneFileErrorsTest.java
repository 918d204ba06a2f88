package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every bad scene file fails with one line naming the file and the offending key or position. */
class SceneFileErrorsTest {

    @TempDir
    Path dir;

    /** Parses {@code json} as "room.json" and returns the error message ({@link UserMessages} checks it). */
    private static String error(String json) {
        String message = UserMessages.of(ModelFormatException.class, () -> SceneFiles.parse(json, "room.json", null));
        return checkedFile(message, "room.json");
    }

    private static String checkedFile(String message, String fileName) {
        assertTrue(message.startsWith(fileName + ":"), "names the file: " + message);
        return message;
    }

    private static void assertMessage(String expectedPart, String json) {
        String message = error(json);
        assertTrue(message.contains(expectedPart), "expected \"" + expectedPart + "\" in: " + message);
    }

    private static final String SPHERE = "\"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1}]";

    @Test
    void anUnknownTopLevelKeyIsNamedWithItsPath() {
        assertMessage("room.json: unknown key \"lightz\" (expected one of:",
                "{\"version\": 1, " + SPHERE + ", \"lightz\": []}");
    }

    @Test
    void anUnknownNestedKeyIsNamedWithItsPath() {
        assertMessage("room.json: lights[0]: unknown key \"lightz\"",
                "{\"version\": 1, " + SPHERE + ", \"lights\": [{\"position\": [0, 0, 1], \"lightz\": 1}]}");
        assertMessage("materials.red: unknown key \"colour\"",
                "{\"version\": 1, " + SPHERE + ", \"materials\": {\"red\": {\"colour\": [1, 0, 0]}}}");
        assertMessage("render: unknown key \"size\"",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"size\": 3}}");
        assertMessage("models[0].transform: unknown key \"shear\"",
                "{\"version\": 1, \"models\": [{\"builtin\": \"patch\", \"transform\": {\"shear\": 1}}]}");
    }

    @Test
    void wrongTypesNameThePathAndWhatWasFound() {
        assertMessage("room.json: camera.eye: expected an array of 3 numbers, found an array of 2 items",
                "{\"version\": 1, " + SPHERE + ", \"camera\": {\"eye\": [1, 2], \"target\": [0, 0, 0]}}");
        assertMessage("camera.eye: expected an array of 3 numbers, found \"here\"",
                "{\"version\": 1, " + SPHERE + ", \"camera\": {\"eye\": \"here\", \"target\": [0, 0, 0]}}");
        assertMessage("spheres[0].center[1]: expected a number, found \"0\"",
                "{\"version\": 1, \"spheres\": [{\"center\": [0, \"0\", 0], \"radius\": 1}]}");
        assertMessage("spheres: expected an array, found an object",
                "{\"version\": 1, \"spheres\": {}}");
        assertMessage("render.shadows: expected true or false, found \"yes\"",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"shadows\": \"yes\"}}");
        assertMessage("render.spp: expected a whole number, found 2.5",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"spp\": 2.5}}");
        assertMessage("models[0].material: unknown material \"gold\" (defined: none)",
                "{\"version\": 1, \"models\": [{\"builtin\": \"patch\", \"material\": \"gold\"}]}");
        assertMessage("models[0].builtin: unknown built-in model \"kettle\"",
                "{\"version\": 1, \"models\": [{\"builtin\": \"kettle\"}]}");
        assertMessage("models[0]: expected exactly one of \"file\", \"builtin\", \"patches\" or \"mesh\", found 2",
                "{\"version\": 1, \"models\": [{\"builtin\": \"patch\", \"file\": \"a.bpt\"}]}");
        assertMessage("lights[0]: missing key \"position\"",
                "{\"version\": 1, " + SPHERE + ", \"lights\": [{}]}");
        assertMessage("room.json: expected an object, found an array of 0 items", "[]");
    }

    @Test
    void aNegativeRadiusIsRejectedWithItsValue() {
        assertMessage("room.json: spheres[1].radius: expected a positive number, found -2",
                "{\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1},"
                        + " {\"center\": [0, 0, 0], \"radius\": -2}]}");
    }

    @Test
    void otherVersionsAndAMissingVersionAreRejected() {
        assertMessage("room.json: version: unsupported scene version 2 (this program reads version 1)",
                "{\"version\": 2, " + SPHERE + "}");
        assertMessage("room.json: version: unsupported scene version 2 (this program reads version 1)",
                "{\"version\": 2, \"fog\": {\"density\": 1}}");
        assertMessage("room.json: missing key \"version\" (this program reads version 1)", "{" + SPHERE + "}");
        assertMessage("version: expected a version number, found \"1\"", "{\"version\": \"1\", " + SPHERE + "}");
    }

    @Test
    void syntaxErrorsGiveTheLineAndColumn() {
        assertMessage("room.json:3: invalid JSON at column ",
                "{\n  \"version\": 1,\n  \"spheres\" []\n}");
        assertMessage("room.json:2: invalid JSON", "{\"version\": 1,\n \"spheres\": [1, 2,]}");
        assertMessage("room.json:1: invalid JSON", "{\"version\": 1, // comment\n}");
        assertMessage("room.json:2: invalid JSON", "{\"version\": 1,\n");
        assertMessage("room.json: duplicate key \"version\"", "{\"version\": 1, \"version\": 1}");
        assertMessage("room.json:1: invalid JSON at column 66: not strict JSON", "{\"version\": 1, " + SPHERE + "} {}");
        assertMessage("nested more than", "[".repeat(100) + "]".repeat(100));
    }

    @Test
    void nanInfinityAndOutOfRangeNumbersAreRejected() {
        assertMessage("room.json:1: invalid JSON", "{\"version\": 1, \"spheres\": [{\"center\": [NaN, 0, 0], \"radius\": 1}]}");
        assertMessage("room.json:1: invalid JSON", "{\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": Infinity}]}");
        assertMessage("spheres[0].center[0]: expected a finite number, found 1e400",
                "{\"version\": 1, \"spheres\": [{\"center\": [1e400, 0, 0], \"radius\": 1}]}");
        assertMessage("spheres[0].radius: expected a positive number, found 1e999",
                "{\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1e999}]}");
        assertMessage("spheres[0].center[0]: expected a number, found \"NaN\"",
                "{\"version\": 1, \"spheres\": [{\"center\": [\"NaN\", 0, 0], \"radius\": 1}]}");
        assertMessage("render.width: expected a whole number from -2147483648 to 2147483647, found 1e10",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"width\": 1e10}}");
    }

    @Test
    void hugeSizesAreOneLineErrorsFromTheRenderSettingsWithThePath() {
        assertMessage("room.json: render.width: image size must be 1..16384",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"width\": 100000}}");
        assertMessage("room.json: render.height: image of 16384x16384 pixels is too large",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"width\": 16384, \"height\": 16384}}");
        assertMessage("room.json: render.spp: samples per pixel must be 1..1024, got 5000",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"spp\": 5000}}");
        assertMessage("room.json: render.sampler: unknown sampler 'fancy'",
                "{\"version\": 1, " + SPHERE + ", \"render\": {\"sampler\": \"fancy\"}}");
    }

    @Test
    void modelRecordValidationIsReportedWithThePath() {
        assertMessage("room.json: materials.shiny: reflectivity and transparency must be in 0..1",
                "{\"version\": 1, " + SPHERE + ", \"materials\": {\"shiny\": {\"reflectivity\": 2}}}");
        assertMessage("room.json: camera: camera eye and target must differ",
                "{\"version\": 1, " + SPHERE + ", \"camera\": {\"eye\": [1, 1, 1], \"target\": [1, 1, 1]}}");
        assertMessage("room.json: planes[0]: plane normal must be finite and non-zero",
                "{\"version\": 1, \"planes\": [{\"point\": [0, 0, 0], \"normal\": [0, 0, 0]}]}");
        assertMessage("room.json: a scene needs at least one patch, mesh, plane or sphere", "{\"version\": 1}");
        assertMessage("models[0].patches[0].points: a degree 1x1 patch needs 4 points",
                "{\"version\": 1, \"models\": [{\"patches\": [{\"degree\": [1, 1], \"points\": [[0, 0, 0]]}]}]}");
        assertMessage("models[0].patches[0].degree: degree in u must be 1..15, got 0",
                "{\"version\": 1, \"models\": [{\"patches\": [{\"degree\": [0, 1], \"points\": []}]}]}");
        assertMessage("models[0].transform.scale: scale factors must be non-zero",
                "{\"version\": 1, \"models\": [{\"builtin\": \"patch\", \"transform\": {\"scale\": 0}}]}");
    }

    @Test
    void aMissingModelFileIsNamed() throws IOException {
        Path scene = dir.resolve("room.json");
        Files.writeString(scene, "{\"version\": 1, \"models\": [{\"file\": \"gone.bpt\"}]}");
        String message = checkedFile(UserMessages.of(ModelFormatException.class, () -> FileFormats.SCENE.read(scene)),
                scene.toString());
        assertTrue(message.endsWith("models[0].file: no such model file \"gone.bpt\" in " + dir), message);
    }

    @Test
    void aBrokenModelFileIsReportedWithBothFiles() throws IOException {
        Files.writeString(dir.resolve("bad.bpt"), "1\n3 3\n0 0 0\n");
        Path scene = dir.resolve("room.json");
        Files.writeString(scene, "{\"version\": 1, \"models\": [{\"file\": \"bad.bpt\"}]}");
        String message = checkedFile(UserMessages.of(ModelFormatException.class, () -> FileFormats.SCENE.read(scene)),
                scene.toString());
        assertTrue(message.contains("models[0].file: " + dir.resolve("bad.bpt") + ":3: "), message);
    }

    @Test
    void aMissingSceneFileIsNamed() {
        ModelFormatException e = org.junit.jupiter.api.Assertions.assertThrows(ModelFormatException.class,
                () -> SceneFiles.load(dir.resolve("none.json").toString()));
        String message = checkedFile(UserMessages.check(e.getMessage()), dir.resolve("none.json").toString());
        assertTrue(message.contains("no such file"), message);
        assertEquals(dir.resolve("none.json").toString(), e.fileName());
    }
}
