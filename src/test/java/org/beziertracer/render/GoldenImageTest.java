package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Small renders of the scenes in {@link TestScenes} compared with reference PNGs in
 * {@code src/test/resources/golden/} within a tolerance: mean absolute difference per channel
 * at most {@value #MAX_MEAN} (8-bit levels) and at most {@value #MAX_OUTLIERS} of the pixels
 * differing by more than {@value #OUTLIER_LEVELS} levels in some channel.
 *
 * <p>To regenerate after an intended change, run
 * {@code mvn -B -q test -Dtest=GoldenImageTest -Dgolden.update=true}, look at the new PNGs, and commit them.
 */
class GoldenImageTest {
    static final int W = 128, H = 96;
    static final double MAX_MEAN = 1.0, MAX_OUTLIERS = 0.005;
    static final int OUTLIER_LEVELS = 16;
    static final Path DIR = Path.of("src/test/resources/golden");

    record Case(String name, Supplier<Scene> scene, String shading, int checker, int spp) {
        RenderJob job(int w, int h) {
            RenderSettings s = new RenderSettings(w, h, spp, "jittered", "clipping", true, shading, checker, true, 5);
            return TestScenes.job(scene.get(), s);
        }

        @Override
        public String toString() { return name; }
    }

    static List<Case> cases() {
        return List.of(
                new Case("phong", TestScenes::bumpOnly, "phong", 0, 1),
                new Case("shadows", TestScenes::shadows, "phong", 0, 1),
                new Case("reflection", TestScenes::reflection, "phong", 0, 4),
                new Case("refraction", TestScenes::refraction, "phong", 0, 4),
                new Case("checker", TestScenes::shadows, "phong", 6, 1),
                new Case("normals", TestScenes::shadows, "normals", 0, 1),
                new Case("flat", TestScenes::reflection, "flat", 0, 1),
                new Case("uv", TestScenes::bumpOnly, "uv", 0, 1),
                new Case("patch-id", TestScenes::shadows, "patch-id", 0, 1));
    }

    static Stream<Case> goldenCases() { return cases().stream(); }

    @ParameterizedTest(name = "{0}")
    @MethodSource("goldenCases")
    void renderMatchesTheGoldenImage(Case c) throws IOException {
        RenderResult r = Renderer.renderOnce(c.job(W, H));
        int[] argb = r.argb();
        Path file = DIR.resolve(c.name() + ".png");
        if (Boolean.getBoolean("golden.update")) {
            BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
            img.setRGB(0, 0, W, H, argb, 0, W);
            Files.createDirectories(DIR);
            ImageIO.write(img, "png", file.toFile());
            return;
        }
        BufferedImage golden;
        try (InputStream in = GoldenImageTest.class.getResourceAsStream("/golden/" + c.name() + ".png")) {
            if (in == null) {
                fail("no golden image " + file + "; run with -Dgolden.update=true to create it");
            }
            golden = ImageIO.read(in);
        }
        assertTrue(golden.getWidth() == W && golden.getHeight() == H, "golden " + c.name() + " has the wrong size");
        long sum = 0;
        int outliers = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int a = argb[y * W + x], b = golden.getRGB(x, y);
                int worst = 0;
                for (int shift = 0; shift <= 16; shift += 8) {
                    int d = Math.abs((a >> shift & 0xFF) - (b >> shift & 0xFF));
                    sum += d;
                    worst = Math.max(worst, d);
                }
                if (worst > OUTLIER_LEVELS) {
                    outliers++;
                }
            }
        }
        double mean = sum / (3.0 * W * H);
        double outlierFraction = outliers / (double) (W * H);
        assertTrue(mean <= MAX_MEAN && outlierFraction <= MAX_OUTLIERS, String.format(Locale.ROOT,
                "%s differs from %s: mean abs diff %.3f (max %.1f), outliers %.4f (max %.4f)", c.name(), file, mean,
                MAX_MEAN, outlierFraction, MAX_OUTLIERS));
    }
}
