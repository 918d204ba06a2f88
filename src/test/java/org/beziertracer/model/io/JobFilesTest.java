package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.model.CameraPath;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Job files (issue 37): read into a checked {@link JobDocument}; every bad value is one line naming file and key. */
class JobFilesTest {

    @TempDir
    Path dir;

    private JobDocument parse(String json) {
        return JobFiles.parse(json, "job.json", dir, m -> { });
    }

    private String error(String json) {
        String m = UserMessages.of(ModelFormatException.class, () -> parse(json));
        assertTrue(m.startsWith("job.json:"), "names the file: " + m);
        return m;
    }

    private void assertMessage(String expectedPart, String json) {
        String m = error(json);
        assertTrue(m.contains(expectedPart), "expected \"" + expectedPart + "\" in: " + m);
    }

    @Test
    void aTurntableJobRendersFramesOneToNWithTheSettingsOverTheScenes() {
        JobDocument job = parse("{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"width\": 64, \"spp\": 3},"
                + " \"seed\": 42, \"camera\": {\"turntable\": {\"frames\": 36, \"center\": [0, 0, 1]}},"
                + " \"output\": \"frames/teapot-####.png\"}");
        assertEquals(64, job.scene().settings().width());
        assertEquals(3, job.scene().settings().spp());
        assertEquals(SceneFiles.load("teapot").settings().height(), job.scene().settings().height(), "the scene's own");
        assertEquals(42, job.seed());
        assertEquals(1, job.firstFrame());
        assertEquals(36, job.lastFrame());
        CameraPath.Turntable t = (CameraPath.Turntable) job.camera();
        assertEquals(360, t.degrees());
        assertEquals(dir.resolve("frames/teapot-0007.png"), job.outputOf(7));
        assertEquals(dir.resolve("frames/teapot-12345.png"), job.outputOf(12345));
    }

    @Test
    void keyframesAnInlineSceneAndAFrameRangeAreRead() {
        JobDocument job = parse("{\"job\": 1, \"scene\": {\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 1}]},"
                + " \"camera\": {\"keyframes\": [{\"frame\": 0, \"eye\": [5, 0, 0], \"target\": [0, 0, 0]},"
                + " {\"frame\": 8, \"eye\": [0, 5, 0], \"target\": [0, 0, 0], \"fov\": 60}]}, \"frames\": \"2-4\","
                + " \"output\": \"k-##.png\"}");
        assertEquals(1, job.scene().scene().spheres().size());
        assertEquals(2, job.firstFrame());
        assertEquals(4, job.lastFrame());
        assertEquals(2, ((CameraPath.Keyframes) job.camera()).keys().size());
        assertEquals(dir.resolve("k-03.png"), job.outputOf(3));
        JobDocument still = parse("{\"job\": 1, \"scene\": \"teapot\"}");
        assertNull(still.camera());
        assertNull(still.output());
        assertEquals(1, still.firstFrame());
        assertEquals(1, still.lastFrame());
    }

    @Test
    void aScenePathIsReadRelativeToTheJobFile() throws IOException {
        Files.writeString(dir.resolve("room.json"), "{\"version\": 1, \"spheres\": [{\"center\": [0, 0, 0], \"radius\": 2}]}");
        Path jobFile = dir.resolve("job.json");
        Files.writeString(jobFile, "{\"job\": 1, \"scene\": \"room.json\", \"output\": \"out.png\"}");
        assertTrue(JobFiles.isJob(jobFile.toString()));
        assertFalse(JobFiles.isJob(dir.resolve("room.json").toString()), "a scene file is not a job");
        JobDocument job = JobFiles.load(jobFile, m -> { });
        assertEquals(2, job.scene().scene().spheres().get(0).radius());
    }

    @Test
    void badValuesNameTheFileAndTheKey() {
        assertMessage("missing key \"job\"", "{\"scene\": \"teapot\"}");
        assertMessage("job: unsupported job version 2", "{\"job\": 2, \"scene\": \"teapot\"}");
        assertMessage("job.json: missing key \"scene\"", "{\"job\": 1}");
        assertMessage("job.json: unknown key \"camra\"", "{\"job\": 1, \"scene\": \"teapot\", \"camra\": {}}");
        assertMessage("scene: not a built-in name and no such file: \"nowhere.json\"",
                "{\"job\": 1, \"scene\": \"nowhere.json\"}");
        assertMessage("settings.spp: samples per pixel must be 1..1024",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"spp\": 0}}");
        assertMessage("seed: expected a whole number", "{\"job\": 1, \"scene\": \"teapot\", \"seed\": 1.5}");
        assertMessage("camera.turntable.frames: expected a frame count from 1",
                "{\"job\": 1, \"scene\": \"teapot\", \"camera\": {\"turntable\": {\"frames\": 0}}}");
        assertMessage("camera.turntable.axis: expected a nonzero direction",
                "{\"job\": 1, \"scene\": \"teapot\", \"camera\": {\"turntable\": {\"frames\": 3, \"axis\": [0, 0, 0]}}}");
        assertMessage("camera: expected exactly one of",
                "{\"job\": 1, \"scene\": \"teapot\", \"camera\": {}}");
        assertMessage("camera.keyframes[1].frame: keyframes must be in increasing frame order",
                "{\"job\": 1, \"scene\": \"teapot\", \"camera\": {\"keyframes\": [{\"frame\": 3, \"eye\": [5, 0, 0],"
                        + " \"target\": [0, 0, 0]}, {\"frame\": 3, \"eye\": [0, 5, 0], \"target\": [0, 0, 0]}]}}");
        assertMessage("camera.keyframes[0]: camera eye and target must differ",
                "{\"job\": 1, \"scene\": \"teapot\", \"camera\": {\"keyframes\": [{\"frame\": 0, \"eye\": [0, 0, 0],"
                        + " \"target\": [0, 0, 0]}]}}");
        assertMessage("frames: must be A-B or A", "{\"job\": 1, \"scene\": \"teapot\", \"frames\": \"1..3\"}");
        assertMessage("frames: 3-1: the last frame is before the first",
                "{\"job\": 1, \"scene\": \"teapot\", \"frames\": \"3-1\"}");
        assertMessage("output: the output must be a .png file name",
                "{\"job\": 1, \"scene\": \"teapot\", \"output\": \"a.jpg\"}");
        assertMessage("output: several frames need a #",
                "{\"job\": 1, \"scene\": \"teapot\", \"frames\": \"1-3\", \"output\": \"a.png\"}");
    }

    @Test
    void theIntegratorAndThePathTracersSettingsAreReadFromTheSettings() {
        JobDocument job = parse("{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"Path\","
                + " \"pathDepth\": 7, \"clamp\": 4.5, \"exposure\": -1, \"spp\": 2}}");
        assertEquals(new JobTracer("path", 7, 4.5, -1.0), job.tracer());
        assertEquals(2, job.scene().settings().spp(), "the render keys beside them still apply");
        assertEquals(JobTracer.NONE, parse("{\"job\": 1, \"scene\": \"teapot\"}").tracer());
        assertEquals("whitted", parse("{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"whitted\"}}")
                .tracer().integrator());
    }

    @Test
    void badIntegratorValuesNameTheFileAndTheKey() {
        assertMessage("job.json: settings.integrator: unknown integrator 'photon': expected whitted or path",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"photon\"}}");
        assertMessage("job.json: settings.integrator: expected a string",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": 2}}");
        assertMessage("job.json: settings.pathDepth: the path depth must be 1..1024, got 0",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"path\", \"pathDepth\": 0}}");
        assertMessage("job.json: settings.clamp: the clamp must be a finite number >= 0",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"path\", \"clamp\": -1}}");
        assertMessage("job.json: settings.exposure: the exposure must be -64..64 stops, got 65",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"integrator\": \"path\", \"exposure\": 65}}");
        assertMessage("job.json: settings.clamp: needs \"integrator\": \"path\"",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"clamp\": 2}}");
        assertMessage("job.json: settings: unknown key \"depth\"",
                "{\"job\": 1, \"scene\": \"teapot\", \"settings\": {\"depth\": 2}}");
    }
}
