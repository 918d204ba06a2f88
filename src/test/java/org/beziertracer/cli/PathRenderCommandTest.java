package org.beziertracer.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * {@code render --integrator path}: PNG through the ACES curve, linear .pfm output, the path
 * tracer's options and their one-line errors.
 */
class PathRenderCommandTest {
    @TempDir
    Path dir;

    /** A white diffuse sphere in a uniform environment of radiance 0.5: every pixel is 0.5 (a furnace). */
    private Path furnace() throws IOException {
        Path scene = dir.resolve("furnace.json");
        Files.writeString(scene, "{\"version\": 1, \"materials\": {\"white\": {\"type\": \"diffuse\", \"color\": [1, 1, 1]}},"
                + " \"models\": [{\"builtin\": \"sphere\", \"material\": \"white\"}],"
                + " \"environment\": {\"color\": [0.5, 0.5, 0.5]},"
                + " \"camera\": {\"eye\": [0, -4, 0], \"target\": [0, 0, 0], \"fov\": 30}}");
        return scene;
    }

    @Test
    void aPathTracedPfmHoldsTheLinearRadiance() throws IOException {
        Path pfm = dir.resolve("furnace.pfm");
        Run r = Run.of("render", furnace().toString(), "-o", pfm.toString(), "--integrator", "path", "--size", "16x12",
                "--spp", "16", "--sampler", "jittered", "--depth", "64", "--threads", "2", "--stats");
        assertEquals(0, r.code(), r.err());
        byte[] bytes = Files.readAllBytes(pfm);
        String header = "PF\n16 12\n-1.0\n";
        assertEquals(header, new String(bytes, 0, header.length(), StandardCharsets.US_ASCII));
        assertEquals(header.length() + 12 * 16 * 12, bytes.length);
        ByteBuffer b = ByteBuffer.wrap(bytes, header.length(), 12 * 16 * 12).order(ByteOrder.LITTLE_ENDIAN);
        double sum = 0;
        for (int i = 0; i < 3 * 16 * 12; i++) {
            sum += b.getFloat();
        }
        assertEquals(0.5, sum / (3 * 16 * 12), 0.01, "the furnace's mean radiance");
        JsonObject stats = JsonParser.parseString(r.out().strip()).getAsJsonObject();
        assertEquals("path", stats.get("integrator").getAsString());
        assertEquals(64, stats.get("pathDepth").getAsInt());
        assertTrue(stats.get("samplesPerSecond").getAsDouble() > 0, stats.toString());
    }

    @Test
    void aPathTracedPngGoesThroughTheAcesCurveAndExposure() throws IOException {
        Path png = dir.resolve("furnace.png"), bright = dir.resolve("bright.png");
        String scene = furnace().toString();
        Run r = Run.of("render", scene, "-o", png.toString(), "--integrator", "path", "--size", "8x6", "--spp", "16",
                "--sampler", "jittered", "--depth", "64", "--threads", "1");
        assertEquals(0, r.code(), r.err());
        Run r2 = Run.of("render", scene, "-o", bright.toString(), "--integrator", "path", "--size", "8x6", "--spp", "16",
                "--sampler", "jittered", "--depth", "64", "--threads", "1", "--exposure", "1");
        assertEquals(0, r2.code(), r2.err());
        // radiance 0.5 → ACES 0.5·(2.51·0.5+0.03)/(0.5·(2.43·0.5+0.59)+0.14) = 0.616 → sRGB 205;
        // one stop up: 1.0 → 0.804 → 231
        assertEquals(205, green(ImageIO.read(png.toFile())), 3);
        assertEquals(231, green(ImageIO.read(bright.toFile())), 3);
    }

    private static double green(BufferedImage img) {
        double sum = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                sum += img.getRGB(x, y) >> 8 & 0xFF;
            }
        }
        return sum / (img.getWidth() * img.getHeight());
    }

    @Test
    void badPathOptionsAreOneLineErrors() throws IOException {
        String scene = furnace().toString(), out = dir.resolve("x.png").toString();
        assertError("unknown integrator 'bidirectional': expected whitted or path",
                "render", scene, "-o", out, "--integrator", "bidirectional");
        assertError("--depth must be 1..1024 for the path tracer, got 0",
                "render", scene, "-o", out, "--integrator", "path", "--depth", "0");
        assertError("--clamp must be a finite number >= 0 (0 = off), got -1.0",
                "render", scene, "-o", out, "--integrator", "path", "--clamp", "-1");
        assertError("--clamp and --exposure need --integrator path", "render", scene, "-o", out, "--clamp", "4");
        assertError("--pixel traces the Whitted renderer; it does not take --integrator path",
                "render", scene, "--pixel", "1,1", "--integrator", "path");
        assertError("--difference-to compares Whitted renders", "render", scene, "-o", out, "--integrator", "path",
                "--difference-to", "newton");
        assertError("the output must be a .png (or .hdr or .pfm) file", "render", scene, "-o", dir.resolve("x.exr").toString());
        assertTrue(Files.notExists(dir.resolve("x.png")), "nothing written");
    }

    private static void assertError(String expected, String... args) {
        Run r = Run.of(args);
        assertEquals(1, r.code(), r.out());
        String line = UserMessages.checkOneLineOutput(r.err());
        assertTrue(line.contains(expected), "expected \"" + expected + "\" in: " + line);
    }
}
