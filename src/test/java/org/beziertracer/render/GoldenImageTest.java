package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.Supplier;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.beziertracer.intersect.Method;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Small renders of the scenes in {@link TestScenes} compared with reference PNGs in
 * {@code src/test/resources/golden/}: a render passes when the mean absolute difference per
 * channel is at most {@value #MAX_MEAN} (8-bit levels) and at most {@value #MAX_OUTLIERS} of the
 * pixels (0.05 %: 6 of 128×96) differ by more than {@value #OUTLIER_LEVELS} levels in some
 * channel.
 *
 * <p>The reference images are rendered with Bézier clipping, the exact method. Newton and
 * subdivision render the same scenes and are compared with the same references, so a golden
 * image also checks that a method finds the surface the exact method finds, on every scene.
 *
 * <p>To regenerate after an intended change, run
 * {@code mvn -B -q test -Dtest=GoldenImageTest -Dgolden.update=true}. That run compares first,
 * rewrites only the images that differ, and <b>fails</b> either way, naming what it rewrote, so
 * it can never pass a build; look at the new PNGs, then commit them and run the tests again
 * without the flag.
 */
class GoldenImageTest {
    static final int W = 128, H = 96;
    static final double MAX_MEAN = 1.0, MAX_OUTLIERS = 0.0005;
    static final int OUTLIER_LEVELS = 16;
    static final Path DIR = Path.of("src/test/resources/golden");
    static final boolean UPDATE = Boolean.getBoolean("golden.update");

    /** One render, compared with the reference image {@code golden}. */
    record Case(String name, Supplier<Scene> scene, String shading, int checker, int spp, Method method,
                String golden) {
        Case(String name, Supplier<Scene> scene, String shading, int checker, int spp) {
            this(name, scene, shading, checker, spp, Method.CLIPPING, name);
        }

        /** The same scene rendered with {@code m}, compared with {@code goldenName}. */
        Case with(Method m, String goldenName) {
            return new Case(name + "-" + m.label(), scene, shading, checker, spp, m, goldenName);
        }

        RenderJob job(int w, int h) {
            RenderSettings s = new RenderSettings(w, h, spp, "jittered", method.label(), true, shading, checker, true, 5);
            return TestScenes.job(scene.get(), s);
        }

        /** True when update mode writes this case's render as the golden image (the one named after it). */
        boolean makesGolden() {
            return golden.equals(name);
        }

        @Override
        public String toString() { return name; }
    }

    static List<Case> cases() {
        List<Case> reference = List.of(
                new Case("phong", TestScenes::bumpOnly, "phong", 0, 1),
                new Case("shadows", TestScenes::shadows, "phong", 0, 1),
                new Case("reflection", TestScenes::reflection, "phong", 0, 4),
                new Case("refraction", TestScenes::refraction, "phong", 0, 4),
                new Case("teapot", TestScenes::teapot, "phong", 0, 1),
                new Case("checker", TestScenes::shadows, "phong", 6, 1),
                new Case("normals", TestScenes::shadows, "normals", 0, 1),
                new Case("flat", TestScenes::reflection, "flat", 0, 1),
                new Case("uv", TestScenes::bumpOnly, "uv", 0, 1),
                new Case("patch-id", TestScenes::shadows, "patch-id", 0, 1));
        List<Case> all = new ArrayList<>(reference);
        for (Case c : reference) {
            // Subdivision's hits are approximate (the control mesh of pieces 1e-3 of a leaf), but
            // at 128×96 they move no pixel of any scene: the clipping references hold
            all.add(c.with(Method.SUBDIVISION, c.golden()));
            // Newton's roots are exact like clipping's (no cracks at leaf or patch borders since
            // issue #10): the clipping references hold
            all.add(c.with(Method.NEWTON, c.golden()));
        }
        // The analysis views (issue [2 of 6]) on the teapot, with the exact methods: the colour
        // comes from derivatives at the root, which subdivision's approximate (u,v) only nears
        for (String view : List.of("zebra", "emap", "isophotes", "gaussian", "mean", "min-radius", "max-radius", "draft")) {
            Case c = new Case("analysis-" + view, TestScenes::teapot, view, 0, 1);
            all.add(c);
            all.add(c.with(Method.NEWTON, c.golden()));
        }
        return all;
    }

    static Stream<Case> goldenCases() { return cases().stream(); }

    /** Mean absolute channel difference and the fraction of pixels off by more than {@value #OUTLIER_LEVELS}. */
    record Difference(double mean, double outliers) {
        boolean withinBudget() { return mean <= MAX_MEAN && outliers <= MAX_OUTLIERS; }

        @Override
        public String toString() {
            return String.format(Locale.ROOT, "mean abs diff %.3f (max %.1f), outliers %.4f %% (max %.2f %%)", mean, MAX_MEAN,
                    100 * outliers, 100 * MAX_OUTLIERS);
        }
    }

    static Difference compare(int[] argb, BufferedImage golden) {
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
        return new Difference(sum / (3.0 * W * H), outliers / (double) (W * H));
    }

    static BufferedImage readGolden(String name) throws IOException {
        try (InputStream in = GoldenImageTest.class.getResourceAsStream("/golden/" + name + ".png")) {
            if (in == null) {
                return null;
            }
            BufferedImage img = ImageIO.read(in);
            assertTrue(img.getWidth() == W && img.getHeight() == H, "golden " + name + " has the wrong size");
            return img;
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("goldenCases")
    void renderMatchesTheGoldenImage(Case c) throws IOException {
        int[] argb = Renderer.renderOnce(c.job(W, H)).argb();
        BufferedImage golden = readGolden(c.golden());
        Difference d = golden == null ? null : compare(argb, golden);
        Path file = DIR.resolve(c.golden() + ".png");
        if (UPDATE) {
            update(c, argb, d, file);
        }
        if (golden == null) {
            fail("no golden image " + file + "; run with -Dgolden.update=true to create it");
        }
        assertTrue(d.withinBudget(), c.name() + " differs from " + file + ": " + d);
    }

    /** Update mode: rewrites the golden image if this case makes it and it differs; always fails. */
    private static void update(Case c, int[] argb, Difference d, Path file) throws IOException {
        if (!c.makesGolden()) {
            fail("golden.update is set: " + c.name() + " is compared with " + file + " (made by another case): "
                    + (d == null ? "missing" : d) + "; run again without -Dgolden.update");
        }
        if (d != null && d.mean() == 0) {
            fail("golden.update is set: " + file + " already matches " + c.name() + " exactly, not rewritten; run again"
                    + " without -Dgolden.update");
        }
        BufferedImage img = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, W, H, argb, 0, W);
        Files.createDirectories(DIR);
        ImageIO.write(img, "png", file.toFile());
        fail("golden.update is set: rewrote " + file + " (" + (d == null ? "new" : "was " + d) + "); look at it, commit it"
                + " and run again without -Dgolden.update");
    }
}
