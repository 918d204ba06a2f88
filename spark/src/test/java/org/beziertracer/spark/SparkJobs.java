package org.beziertracer.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import java.util.List;
import java.util.regex.Pattern;

import javax.imageio.ImageIO;

import org.beziertracer.cli.BezierTracerCommand;
import org.beziertracer.math.Kernels;

/** Test helpers: a small job, a run of the Spark application, a one-machine render to compare with. */
final class SparkJobs {
    private SparkJobs() {}

    /** A 37×27 teapot, 2 frames of a turntable; {@code settings} adds to the job's settings. */
    static Path job(Path dir, String settings) throws IOException {
        Path job = dir.resolve("spin.json");
        Files.writeString(job, "{\"job\": 1, \"scene\": {\"version\": 1, \"models\": [{\"builtin\": \"teapot\"}],"
                + " \"lights\": [{\"position\": [-200, -350, 450]}], \"render\": {\"width\": 37, \"height\": 27}},"
                + " \"seed\": 7, \"settings\": {\"spp\": 2, \"sampler\": \"jittered\"" + settings + "},"
                + " \"camera\": {\"turntable\": {\"frames\": 2}}, \"output\": \"spin-##.png\"}");
        return job;
    }

    /** The application's exit code, standard output and standard error. */
    record Result(int code, String out, String err) {}

    static Result run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int code;
        try (PrintStream o = new PrintStream(out, true, StandardCharsets.UTF_8);
             PrintStream e = new PrintStream(err, true, StandardCharsets.UTF_8)) {
            code = SparkRender.run(args, o, e);
        }
        return new Result(code, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    /** {@code beziertracer render ARGS} in this JVM: exit code and standard error. */
    static Result cli(String... args) {
        StringWriter out = new StringWriter(), err = new StringWriter();
        int code = BezierTracerCommand.run(args, new PrintWriter(out), new PrintWriter(err));
        return new Result(code, out.toString(), err.toString());
    }

    /** Frames 1 and 2 of the job rendered by {@code render JOB.json} on one machine, to {@code dir/one-##.png}. */
    static void renderOnOneMachine(Path job, Path dir) {
        Result r = cli("render", job.toString(), "-o", dir.resolve("one-##.png").toString(), "--threads", "2", "-q");
        assertEquals(0, r.code(), r.err());
    }

    /**
     * The frames in {@code out} are the files of the one-machine render in {@code oneDir} byte for byte: each
     * frame's PNG and its linear {@code .pfm}.
     */
    static void assertSameFrames(Path oneDir, Path out, String what) throws IOException {
        for (int f = 1; f <= 2; f++) {
            String n = String.format("%02d", f);
            for (String ext : new String[] {".png", ".pfm"}) {
                assertArrayEquals(Files.readAllBytes(oneDir.resolve("one-" + n + ext)),
                        Files.readAllBytes(out.resolve("spin-" + n + ext)),
                        what + ": the " + ext + " of frame " + f + " differs from the one-machine render's");
            }
            assertArrayEquals(pixels(oneDir.resolve("one-" + n + ".png")), pixels(out.resolve("spin-" + n + ".png")));
        }
    }

    /**
     * Each executor that rendered reports (one line) the kernel this JVM chose: the SIMD one, since surefire starts
     * this JVM with {@code --add-modules jdk.incubator.vector} and Spark 4 gives executor JVMs the same option.
     */
    static void assertExecutorsUseThisJvmsKernel(String out) {
        assertTrue(Kernels.vectorModulePresent(), "the test JVM runs with the Vector API module (spark/pom.xml)");
        List<String> lines = out.lines().filter(l -> l.startsWith("executor ")).toList();
        assertTrue(!lines.isEmpty(), "one line per executor: " + out);
        for (String line : lines) {
            assertTrue(line.matches("executor \\S+: kernel " + Pattern.quote(Kernels.best().description())
                    + "; job loaded in \\d+\\.\\d\\d s"), "the executor renders with " + Kernels.best().description()
                    + ": " + line);
        }
    }

    static int[] pixels(Path png) throws IOException {
        BufferedImage img = ImageIO.read(png.toFile());
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }
}
