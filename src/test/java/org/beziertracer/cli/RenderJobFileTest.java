package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.Method;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraPath;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.io.JobFiles;
import org.beziertracer.render.FrameAssembly;
import org.beziertracer.render.JobFrames;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code render JOB.json} (issue 37): every frame of a job, or some, or a piece of some; bad jobs fail in one line. */
class RenderJobFileTest {

    @TempDir
    Path dir;

    private static final Vec3 EYE = new Vec3(-20, -35, 25), TARGET = new Vec3(0, 0, 7);

    private Path scene() throws IOException {
        Path room = dir.resolve("room.json");
        Files.writeString(room, "{\"version\": 1, \"models\": [{\"builtin\": \"teapot\"}],"
                + " \"lights\": [{\"position\": [-200, -350, 450]}],"
                + " \"camera\": {\"eye\": [-20, -35, 25], \"target\": [0, 0, 7], \"up\": [0, 0, 1], \"fov\": 40},"
                + " \"render\": {\"width\": 40, \"height\": 30}}");
        return room;
    }

    private Path job(String json) throws IOException {
        Path job = dir.resolve("job.json");
        Files.writeString(job, json);
        return job;
    }

    @Test
    void aThreeFrameTurntableJobWritesThreePngsAndEachFrameIsTheRenderOfItsCamera() throws IOException {
        scene();
        Path job = job("{\"job\": 1, \"scene\": \"room.json\", \"settings\": {\"spp\": 2, \"sampler\": \"jittered\"},"
                + " \"camera\": {\"turntable\": {\"frames\": 3}}, \"output\": \"out/f-###.png\"}");
        Run r = Run.of("render", job.toString(), "--threads", "2");
        assertEquals(0, r.code(), r.err());
        BufferedImage[] frames = new BufferedImage[3];
        for (int k = 1; k <= 3; k++) {
            Path png = dir.resolve("out/f-00" + k + ".png");
            assertTrue(Files.isRegularFile(png), png + " written");
            frames[k - 1] = ImageIO.read(png.toFile());
            assertEquals(40, frames[k - 1].getWidth());
        }
        assertFalse(java.util.Arrays.equals(pixels(frames[0]), pixels(frames[1])), "the camera turned");
        // Frame 2, rendered by hand with its camera: the same bytes
        CameraSpec c = new CameraPath.Turntable(3, Vec3.Z, null, 360)
                .at(2, CameraSpec.perspective(EYE, TARGET, Vec3.Z, 40));
        Path alone = dir.resolve("alone.png");
        Run one = Run.of("render", dir.resolve("room.json").toString(), "-o", alone.toString(), "--threads", "1",
                "--spp", "2", "--sampler", "jittered", "--eye", text(c.eye()), "--target", text(c.target()),
                "--up", text(c.up()), "--fov", Double.toString(c.fovDegrees()));
        assertEquals(0, one.code(), one.err());
        assertArrayEquals(pixels(ImageIO.read(alone.toFile())), pixels(frames[1]), "frame 2 of the job");
    }

    @Test
    void eachFramesPngAndLinearPfmAreTheBytesOfTheFrameAssembledFromTiles() throws Exception {
        scene();
        Path job = job("{\"job\": 1, \"scene\": \"room.json\", \"seed\": 4, \"settings\": {\"spp\": 2,"
                + " \"sampler\": \"jittered\"}, \"camera\": {\"turntable\": {\"frames\": 2}}, \"output\": \"out/f-#.png\"}");
        Run r = Run.of("render", job.toString(), "--threads", "2");
        assertEquals(0, r.code(), r.err());
        // what the Spark module writes: frames put together from tiles rendered apart
        JobFrames frames = JobFrames.of(JobFiles.load(job, Method::parse), 1, "job.json");
        for (int f = 1; f <= 2; f++) {
            FrameAssembly assembled = new FrameAssembly(40, 30);
            for (int i = 1; i <= 3; i++) {
                assembled.add(frames.renderTile(f, i, 3));
            }
            assertArrayEquals(assembled.png(), Files.readAllBytes(dir.resolve("out/f-" + f + ".png")),
                    "the PNG bytes of frame " + f);
            assertArrayEquals(assembled.pfm(), Files.readAllBytes(dir.resolve("out/f-" + f + ".pfm")),
                    "the .pfm bytes of frame " + f);
        }
        try (var files = Files.list(dir.resolve("out"))) {
            assertEquals(4, files.count(), "two PNGs, two .pfm, no temporary file");
        }
    }

    @Test
    void someFramesAndAPieceOfThemAreTheSameBytesAsTheWholeFrames() throws IOException {
        scene();
        Path job = job("{\"job\": 1, \"scene\": \"room.json\", \"camera\": {\"keyframes\": ["
                + "{\"frame\": 1, \"eye\": [-20, -35, 25], \"target\": [0, 0, 7]},"
                + "{\"frame\": 5, \"eye\": [30, -30, 20], \"target\": [0, 0, 5], \"fov\": 50}]},"
                + " \"output\": \"k-#.png\"}");
        assertEquals(0, Run.of("render", job.toString(), "--frames", "2-3").code());
        assertTrue(Files.exists(dir.resolve("k-2.png")) && Files.exists(dir.resolve("k-3.png")));
        assertFalse(Files.exists(dir.resolve("k-1.png")) || Files.exists(dir.resolve("k-4.png")), "only frames 2-3");
        BufferedImage whole = ImageIO.read(dir.resolve("k-3.png").toFile());
        Path piece = dir.resolve("piece-#.png");
        Run r = Run.of("render", job.toString(), "--frames", "3", "--crop", "5,4,33,21", "-o", piece.toString());
        assertEquals(0, r.code(), r.err());
        BufferedImage crop = ImageIO.read(dir.resolve("piece-3.png").toFile());
        assertEquals(28, crop.getWidth());
        assertArrayEquals(whole.getRGB(5, 4, 28, 17, null, 0, 28), crop.getRGB(0, 0, 28, 17, null, 0, 28));
        String pfm = new String(Files.readAllBytes(dir.resolve("piece-3.pfm")), java.nio.charset.StandardCharsets.ISO_8859_1);
        assertTrue(pfm.startsWith("PF\n28 17\n-1.0\n"), "the piece's linear image beside its PNG");
    }

    @Test
    void badJobsFailInOneLineNamingFileAndKeyBeforeRendering() throws IOException {
        scene();
        assertError("job.json: camera.turntable.degrees: expected a number", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"camera\": {\"turntable\": {\"frames\": 3, \"degrees\": \"full\"}}, \"output\": \"f-#.png\"}");
        assertError("job.json: settings.width: image size must be", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"settings\": {\"width\": 0}, \"output\": \"f.png\"}");
        assertError("no \"output\"", "{\"job\": 1, \"scene\": \"room.json\"}");
        assertError("--frames 4-9: the job has frames 1-3", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"camera\": {\"turntable\": {\"frames\": 3}}, \"output\": \"f-#.png\"}", "--frames", "4-9");
        assertError("--eye does not go with a job file", "{\"job\": 1, \"scene\": \"room.json\", \"output\": \"f.png\"}",
                "--eye", "1,2,3");
        // up turns over from +z to -z: half way it is zero, found before frame 0 renders
        assertError("camera: frame 1: camera up must not be the zero vector", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"camera\": {\"keyframes\": [{\"frame\": 0, \"eye\": [60, 0, 0], \"target\": [0, 0, 0]},"
                + " {\"frame\": 2, \"eye\": [60, 0, 0], \"target\": [0, 0, 0], \"up\": [0, 0, -1]}]},"
                + " \"output\": \"f-#.png\"}");
    }

    @Test
    void aPathTracedJobIsTheRenderOfItsSceneWithThePathTracer() throws IOException {
        scene();
        Path job = job("{\"job\": 1, \"scene\": \"room.json\", \"seed\": 5, \"settings\": {\"spp\": 2,"
                + " \"sampler\": \"jittered\", \"integrator\": \"path\", \"pathDepth\": 3, \"exposure\": 1},"
                + " \"output\": \"p.png\"}");
        Run r = Run.of("render", job.toString(), "--threads", "2");
        assertEquals(0, r.code(), r.err());
        Path alone = dir.resolve("alone.png");
        Run one = Run.of("render", dir.resolve("room.json").toString(), "-o", alone.toString(), "--threads", "1",
                "--spp", "2", "--sampler", "jittered", "--integrator", "path", "--depth", "3", "--exposure", "1",
                "--seed", "5");
        assertEquals(0, one.code(), one.err());
        int[] fromJob = pixels(ImageIO.read(dir.resolve("p.png").toFile()));
        assertArrayEquals(pixels(ImageIO.read(alone.toFile())), fromJob, "the job's path-traced frame");
        Path whitted = dir.resolve("w.png");
        assertEquals(0, Run.of("render", job.toString(), "--integrator", "whitted", "-o", whitted.toString()).code());
        assertFalse(java.util.Arrays.equals(pixels(ImageIO.read(whitted.toFile())), fromJob),
                "--integrator whitted overrides the job's path tracer");
    }

    @Test
    void theSeedOptionChangesAJitteredRenderAndTheJobsSeedIsTheSameAsSeedOnTheCommandLine() throws IOException {
        Path room = scene();
        Path[] out = {dir.resolve("s1.png"), dir.resolve("s9.png"), dir.resolve("job9.png")};
        assertEquals(0, Run.of("render", room.toString(), "-o", out[0].toString(), "--sampler", "jittered",
                "--spp", "2").code());
        assertEquals(0, Run.of("render", room.toString(), "-o", out[1].toString(), "--sampler", "jittered",
                "--spp", "2", "--seed", "9").code());
        Path job = job("{\"job\": 1, \"scene\": \"room.json\", \"seed\": 3, \"settings\": {\"spp\": 2,"
                + " \"sampler\": \"jittered\"}, \"output\": \"job9.png\"}");
        assertEquals(0, Run.of("render", job.toString(), "--seed", "9").code());
        int[] s1 = pixels(ImageIO.read(out[0].toFile())), s9 = pixels(ImageIO.read(out[1].toFile()));
        assertFalse(java.util.Arrays.equals(s1, s9), "another seed, other jitter");
        assertArrayEquals(s9, pixels(ImageIO.read(out[2].toFile())), "--seed 9 replaces the job's seed 3");
        Run bad = Run.of("render", room.toString(), "-o", out[0].toString(), "--seed", "x");
        assertEquals(2, bad.code(), "a usage error");
        assertTrue(UserMessages.checkOneLineOutput(bad.err()).contains("--seed: expected a whole number, found \"x\""),
                bad.err());
    }

    @Test
    void badIntegratorValuesOfAJobFailInOneLineNamingFileAndKey() throws IOException {
        scene();
        assertError("job.json: settings.integrator: unknown integrator 'photon'", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"settings\": {\"integrator\": \"photon\"}, \"output\": \"f.png\"}");
        assertError("job.json: settings.exposure: needs \"integrator\": \"path\"", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"settings\": {\"exposure\": 1}, \"output\": \"f.png\"}");
        assertError("--clamp and --exposure need --integrator path", "{\"job\": 1, \"scene\": \"room.json\","
                + " \"output\": \"f.png\"}", "--clamp", "3");
    }

    private void assertError(String expected, String json, String... options) throws IOException {
        Path job = job(json);
        String[] args = new String[2 + options.length];
        args[0] = "render";
        args[1] = job.toString();
        System.arraycopy(options, 0, args, 2, options.length);
        Run r = Run.of(args);
        assertEquals(1, r.code(), r.err());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.contains(expected), "expected \"" + expected + "\" in: " + line);
        try (var files = Files.list(dir)) {
            assertEquals(0, files.filter(p -> p.toString().endsWith(".png")).count(), "no frame rendered: " + line);
        }
    }

    private static String text(Vec3 v) {
        return v.x() + "," + v.y() + "," + v.z();
    }

    private static int[] pixels(BufferedImage img) {
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }
}
