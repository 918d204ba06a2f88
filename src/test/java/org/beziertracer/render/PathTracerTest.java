package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.Environment;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link PathTracer} against answers known in closed form: the white furnace (an albedo-1 diffuse
 * NURBS sphere in a uniform white environment looks exactly like the environment), a diffuse
 * plane under a constant sky (radiance albedo × L), a plane under a small sphere light (radiance
 * {@code albedo/π · π L sin²α}); MIS on and off agreeing in mean; the same bytes on any thread
 * count and tile size.
 */
class PathTracerTest {
    /** The 1 % for means. */
    private static final double PERCENT = 0.01;

    private static RenderJob job(Scene scene, int w, int h, int spp, PathOptions path, Camera camera, int threads,
                                 int tile) {
        RenderSettings s = new RenderSettings(w, h, spp, "jittered", "clipping", true, "phong", 0, true, 5);
        RenderOptions o = RenderOptions.defaults().withThreads(threads).withTileSize(tile).withProgressive(false)
                .withPath(path);
        return RenderJob.prepare(scene, s, o).withCamera(camera);
    }

    private static PathOptions path(int depth) {
        return PathOptions.defaults().withIntegrator(Integrator.PATH).withMaxDepth(depth);
    }

    /** The NURBS unit sphere with material 0 as {@code surface}, in a white environment of radiance 1. */
    private static Scene furnace(Surface surface) {
        Scene sphere = Models.sphere();
        return Scene.builder().addMaterial(Material.DEFAULT).addPatches(sphere.patches(), 0).surface(0, surface)
                .environment(Environment.color(1, 1, 1)).build();
    }

    private static double[] stats(float[] rgb) {
        double sum = 0, sum2 = 0;
        int n = rgb.length / 3;
        for (int i = 0; i < n; i++) {
            double v = rgb[3 * i + 1];
            sum += v;
            sum2 += v * v;
        }
        double mean = sum / n;
        return new double[] {mean, Math.sqrt(Math.max(0, sum2 / n - mean * mean))};
    }

    @Test
    void aWhiteDiffuseSphereVanishesInAWhiteFurnace() {
        Camera camera = Camera.lookAt(new Vec3(0, -4, 0), Vec3.ZERO, Vec3.Z, 40);
        assertFurnace(Renderer.renderOnce(job(furnace(Surface.diffuse(1, 1, 1)), 24, 24, 16, path(64), camera, 2, 8))
                .film().linearRgb(), "sphere");
    }

    @Test
    void aWhiteDiffuseTeapotVanishesInAWhiteFurnace() {
        // any shape, open or closed: white two-sided surfaces in a white sky are radiance 1 everywhere
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPatches(Models.teapot().patches(), 0)
                .surface(0, Surface.diffuse(1, 1, 1)).environment(Environment.color(1, 1, 1)).build();
        Camera camera = Camera.lookAt(new Vec3(300, -400, 250), new Vec3(0, 0, 60), Vec3.Z, 40);
        assertFurnace(Renderer.renderOnce(job(scene, 16, 12, 8, path(64), camera, 2, 8)).film().linearRgb(), "teapot");
    }

    /**
     * The furnace's answer: mean radiance 1 within 1 %, and no value beyond 5 σ, σ the spread of the
     * shape's own pixels (the sky's are exactly 1, without noise, and would shrink it).
     */
    private static void assertFurnace(float[] rgb, String shape) {
        assertEquals(1, stats(rgb)[0], PERCENT, "mean radiance of the " + shape + " furnace");
        double sum2 = 0;
        int n = 0;
        for (float v : rgb) {
            if (v != 1f) {
                sum2 += (v - 1) * (v - 1);
                n++;
            }
        }
        assertTrue(n > rgb.length / 10, "the " + shape + " is in view: " + n + " noisy values");
        double sigma = Math.sqrt(sum2 / n);
        for (int i = 0; i < rgb.length; i++) {
            assertTrue(Math.abs(rgb[i] - 1) <= 5 * sigma, shape + ": value " + rgb[i] + " at " + i + ", σ " + sigma);
        }
    }

    @Test
    void aWhiteDiffuseSphereVanishesInAWhiteImageFurnaceToo() {
        // the same furnace lit by an HDR image of radiance 1 everywhere, importance-sampled
        float[] white = new float[3 * 8 * 4];
        java.util.Arrays.fill(white, 1f);
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPatches(Models.sphere().patches(), 0)
                .surface(0, Surface.diffuse(1, 1, 1))
                .environment(Environment.image("white.hdr", new org.beziertracer.model.HdrImage(8, 4, white), 1, 30))
                .build();
        Camera camera = Camera.lookAt(new Vec3(0, -4, 0), Vec3.ZERO, Vec3.Z, 40);
        float[] rgb = Renderer.renderOnce(job(scene, 16, 16, 16, path(64), camera, 2, 8)).film().linearRgb();
        assertEquals(1, stats(rgb)[0], PERCENT, "mean radiance of the image furnace");
    }

    @Test
    void roughGlassAndMetalLoseNoMoreThanSingleScatteringInTheFurnace() {
        Camera camera = Camera.lookAt(new Vec3(0, -4, 0), Vec3.ZERO, Vec3.Z, 30);
        for (Surface s : new Surface[] {Surface.dielectric(1.5, 0.3), Surface.dielectric(1.5, 0)}) {
            float[] rgb = Renderer.renderOnce(job(furnace(s), 16, 16, 16, path(64), camera, 2, 8)).film().linearRgb();
            double mean = stats(rgb)[0];
            assertTrue(mean <= 1 + PERCENT && mean > 0.9, s.kind() + " roughness " + s.roughness() + ": mean " + mean);
        }
    }

    @Test
    void aDiffusePlaneUnderAConstantSkyHasRadianceAlbedoTimesSky() {
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(0.5, 0.5, 0.5)).environment(Environment.color(2, 2, 2)).build();
        Camera down = Camera.lookAt(new Vec3(0, 0, 5), Vec3.ZERO, Vec3.Y, 30);
        float[] rgb = Renderer.renderOnce(job(scene, 16, 16, 16, path(8), down, 2, 8)).film().linearRgb();
        assertEquals(1, stats(rgb)[0], PERCENT, "albedo 0.5 × sky 2");
    }

    @Test
    void aPlaneBelowASmallSphereLightHasTheAnalyticRadiance() {
        // L_o = albedo/π · E, E = π L sin²α at the foot of the light: albedo · L · (r/h)²
        double r = 0.2, h = 3, light = 50;
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(0.8, 0.8, 0.8))
                .addAreaLight(AreaLight.sphere(new Vec3(0, 0, h), r, light, light, light, Double.NaN)).build();
        // a narrow view of the foot of the light, from beside it (the light out of the picture)
        Camera camera = Camera.lookAt(new Vec3(0.5, 0, 1), Vec3.ZERO, Vec3.Z, 0.5);
        float[] rgb = Renderer.renderOnce(job(scene, 8, 8, 64, path(1), camera, 2, 8)).film().linearRgb();
        double expected = 0.8 * light * (r / h) * (r / h);
        assertEquals(expected, stats(rgb)[0], PERCENT * expected);
    }

    @Test
    void theLastBounceKeepsAllOfItsLightSamplesShare() {
        // a big rect light just above the plane: at the last bounce (depth 1, no BSDF sample follows) the
        // light sample must count whole, not with the MIS weight it would share with that sample.
        // L_o = albedo · L · 4 F, F the form factor of a quarter a × a at height h (Howell's table, C-11)
        double a = 2, h = 0.5, light = 3, x = a / h, r = Math.sqrt(1 + x * x);
        double quarter = (2 * x / r * Math.atan(x / r)) / (2 * Math.PI);
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(0.8, 0.8, 0.8))
                .addAreaLight(AreaLight.rect(new Vec3(-a, -a, h), new Vec3(0, 2 * a, 0), new Vec3(2 * a, 0, 0), light, light,
                        light, Double.NaN)).build();
        Camera foot = Camera.lookAt(new Vec3(0.3, 0, 0.2), Vec3.ZERO, Vec3.Z, 0.5);
        double expected = 0.8 * light * 4 * quarter;
        for (int depth : new int[] {1, 2}) {
            double mean = stats(Renderer.renderOnce(job(scene, 8, 8, 1024, path(depth), foot, 2, 8)).film().linearRgb())[0];
            assertEquals(expected, mean, PERCENT * expected, "depth " + depth);
        }
    }

    @Test
    void aSpotLightLightsItsFootAsAPointSourceAndNothingOutsideItsCone() {
        // intensity C·d², d = h (the plane's bounds are centred on its point): E = C, L = albedo · C / π
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(0.8, 0.8, 0.8))
                .addSpotLight(new org.beziertracer.model.SpotLight(new Vec3(0, 0, 3), new Vec3(0, 0, -1), 20, 15, 2, 2, 2))
                .build();
        Camera foot = Camera.lookAt(new Vec3(0.5, 0, 1), Vec3.ZERO, Vec3.Z, 0.5);
        double lit = stats(Renderer.renderOnce(job(scene, 8, 8, 4, path(1), foot, 1, 8)).film().linearRgb())[0];
        assertEquals(0.8 * 2 / Math.PI, lit, PERCENT * lit);
        Camera aside = Camera.lookAt(new Vec3(3.5, 0, 1), new Vec3(3, 0, 0), Vec3.Z, 0.5);
        assertEquals(0, stats(Renderer.renderOnce(job(scene, 8, 8, 4, path(1), aside, 1, 8)).film().linearRgb())[0],
                "45° off the axis, outside the 20° cone");
    }

    @Test
    void misOnAndOffAgreeInMean() {
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addMaterial(Material.DEFAULT)
                .addPatches(Models.sphere().patches(), 0).surface(0, Surface.plastic(0.6, 0.3, 0.2, 0.3))
                .addPlane(new Plane(new Vec3(0, 0, -1), Vec3.Z, 1, 1)).surface(1, Surface.diffuse(0.7, 0.7, 0.7))
                .addAreaLight(AreaLight.rect(new Vec3(-1, -1, 3), new Vec3(0, 2, 0), new Vec3(2, 0, 0), 5, 5, 5, Double.NaN))
                .environment(Environment.color(0.2, 0.2, 0.3)).build();
        Camera camera = Camera.lookAt(new Vec3(0, -5, 2), Vec3.ZERO, Vec3.Z, 45);
        double on = stats(Renderer.renderOnce(job(scene, 24, 24, 32, path(6), camera, 2, 8)).film().linearRgb())[0];
        double off = stats(Renderer.renderOnce(job(scene, 24, 24, 32, path(6).withMis(false), camera, 2, 8)).film()
                .linearRgb())[0];
        assertEquals(on, off, 0.02 * on, "MIS on " + on + ", off " + off);
    }

    @Test
    void anAreaLightHidesTheEnvironmentBehindItFromLightSamples() {
        // A diffuse plane under a 4 x 4 rect light (radiance 0.5, facing down) at height 2, in a white
        // environment of radiance 1. Below the rect's centre its cosine-weighted share of the sky is the
        // form factor F (four corner rectangles, A = B = 1); a path that meets the rect's front stops
        // there, so the plane sees L = albedo · (0.5 F + 1 · (1 − F)), not the whole sky behind the rect.
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(0.8, 0.8, 0.8))
                .addAreaLight(AreaLight.rect(new Vec3(-2, -2, 2), new Vec3(0, 4, 0), new Vec3(4, 0, 0), 0.5, 0.5, 0.5,
                        Double.NaN))
                .environment(Environment.color(1, 1, 1)).build();
        double a = 1 / Math.sqrt(2);
        double formFactor = 4 / (2 * Math.PI) * 2 * a * Math.atan(a);
        double expected = 0.8 * (0.5 * formFactor + (1 - formFactor));
        Camera foot = Camera.lookAt(new Vec3(0.5, 0, 1), Vec3.ZERO, Vec3.Z, 0.5);
        for (int depth : new int[] {1, 3}) { // past one bounce nothing is added: the plane faces no surface
            for (boolean mis : new boolean[] {true, false}) {
                double mean = stats(Renderer.renderOnce(job(scene, 8, 8, 512, path(depth).withMis(mis), foot, 2, 8))
                        .film().linearRgb())[0];
                assertEquals(expected, mean, PERCENT * expected, "depth " + depth + ", MIS " + mis);
            }
        }
    }

    @Test
    void theErrorFallsAsOneOverTheSquareRootOfTheSamples() {
        // RMSE against a reference of 16 × the larger count: 4 × the samples halves the error
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addMaterial(Material.DEFAULT)
                .addPatches(Models.sphere().patches(), 0).surface(0, Surface.plastic(0.6, 0.3, 0.2, 0.3))
                .addPlane(new Plane(new Vec3(0, 0, -1), Vec3.Z, 1, 1)).surface(1, Surface.diffuse(0.7, 0.7, 0.7))
                .addAreaLight(AreaLight.sphere(new Vec3(1, -1, 3), 0.4, 20, 20, 20, Double.NaN))
                .environment(Environment.color(0.2, 0.2, 0.3)).build();
        Camera camera = Camera.lookAt(new Vec3(0, -5, 2), Vec3.ZERO, Vec3.Z, 45);
        float[] reference = Renderer.renderOnce(job(scene, 12, 12, 256, path(6), camera, 2, 8)).film().linearRgb();
        double e4 = rmse(Renderer.renderOnce(job(scene, 12, 12, 4, path(6), camera, 2, 8)).film().linearRgb(), reference);
        double e16 = rmse(Renderer.renderOnce(job(scene, 12, 12, 16, path(6), camera, 2, 8)).film().linearRgb(), reference);
        double ratio = e4 / e16;
        assertTrue(ratio > 1.6 && ratio < 2.5, "RMSE at 4 spp " + e4 + ", at 16 spp " + e16 + ": ratio " + ratio);
    }

    private static double rmse(float[] a, float[] b) {
        double sum = 0;
        for (int i = 0; i < a.length; i++) {
            sum += (a[i] - b[i]) * (a[i] - b[i]);
        }
        return Math.sqrt(sum / a.length);
    }

    @Test
    void thePictureIsTheSameOnAnyThreadCountAndTileSize() {
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPatches(Models.sphere().patches(), 0)
                .surface(0, Surface.dielectric(1.5, 0.2))
                .addAreaLight(AreaLight.sphere(new Vec3(2, -2, 3), 0.5, 8, 8, 8, Double.NaN))
                .environment(Environment.color(0.3, 0.3, 0.3)).build();
        Camera camera = Camera.lookAt(new Vec3(0, -4, 1), Vec3.ZERO, Vec3.Z, 40);
        float[] reference = null;
        for (int threads : new int[] {1, 2}) {
            for (int tile : new int[] {8, 32}) {
                float[] rgb = Renderer.renderOnce(job(scene, 40, 30, 4, path(8), camera, threads, tile)).film()
                        .linearRgb();
                if (reference == null) {
                    reference = rgb;
                    assertTrue(stats(rgb)[0] > 0.05, "the picture is not black");
                } else {
                    assertArrayEquals(reference, rgb, threads + " threads, tiles of " + tile);
                }
            }
        }
    }

    @Test
    void theClampLimitsEverySample() {
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(0.5, 0.5, 0.5)).environment(Environment.color(2, 2, 2)).build();
        Camera down = Camera.lookAt(new Vec3(0, 0, 5), Vec3.ZERO, Vec3.Y, 30);
        float[] rgb = Renderer.renderOnce(job(scene, 8, 8, 4, path(8).withClamp(0.25), down, 1, 8)).film().linearRgb();
        for (float v : rgb) {
            assertTrue(v <= 0.25f + 1e-6f, "clamped value " + v);
        }
    }
}
