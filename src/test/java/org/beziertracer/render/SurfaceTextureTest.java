package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.Environment;
import org.beziertracer.model.HdrImage;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.Texture;
import org.junit.jupiter.api.Test;

/**
 * Textures on a typed material's colour (issue 34): {@link SurfaceTexture}'s lookups against the
 * pixels and the checker's parity; a checker-albedo diffuse plane under a constant sky has
 * radiance albedo(u,v) × L on each square in the path tracer; the Whitted renderer shows the same
 * texture.
 */
class SurfaceTextureTest {
    private static final double EXACT = 1e-12;
    private static final Texture.Checker CHECKER = new Texture.Checker(new Surface.Vec(0.9, 0.5, 0.1),
            new Surface.Vec(0.1, 0.3, 0.7), 1, 1);

    /** A 3×2 picture whose pixel (x, y) channel c is (x + 3y + 1)/10 + c/100. */
    private static HdrImage picture() {
        float[] rgb = new float[3 * 6];
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                for (int c = 0; c < 3; c++) {
                    rgb[3 * (y * 3 + x) + c] = (x + 3 * y + 1) / 10f + c / 100f;
                }
            }
        }
        return new HdrImage(3, 2, rgb);
    }

    @Test
    void anImageTextureGivesEachPixelAtItsCentreAndBlendsBetween() {
        HdrImage p = picture();
        SurfaceTexture t = new SurfaceTexture(new Texture.Image("p.png", p, 1, 1));
        double[] out = new double[3];
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                // pixel (x, y)'s centre: u = (x + ½)/w, v up from the bottom row
                t.lookup((x + 0.5) / 3, 1 - (y + 0.5) / 2, out);
                for (int c = 0; c < 3; c++) {
                    assertEquals(p.get(x, y, c), out[c], 1e-7, "pixel " + x + "," + y + " channel " + c);
                }
            }
        }
        // half-way between the centres of (0, 0) and (1, 0): their mean
        t.lookup(1.0 / 3, 0.75, out);
        assertEquals((p.get(0, 0, 0) + p.get(1, 0, 0)) / 2, out[0], 1e-7, "bilinear between columns");
        // the left border blends the first and last columns (the texture repeats)
        t.lookup(0, 0.75, out);
        assertEquals((p.get(0, 0, 1) + p.get(2, 0, 1)) / 2, out[1], 1e-7, "wraps around in u");
        // a scale of 2 repeats it twice: u = 0.5 + (x + ½)/6 is pixel x again
        SurfaceTexture twice = new SurfaceTexture(new Texture.Image("p.png", p, 2, 1));
        twice.lookup(0.5 + 2.5 / 6, 0.25, out);
        assertEquals(p.get(2, 1, 2), out[2], 1e-7, "scale 2: the second copy");
    }

    @Test
    void aCheckerPicksItsSquareByParityAtAnyScaleAndSign() {
        Random random = new Random(34);
        double[] out = new double[3];
        for (int i = 0; i < 1000; i++) {
            double su = 0.5 + 10 * random.nextDouble(), sv = 0.5 + 10 * random.nextDouble();
            double u = 20 * random.nextDouble() - 10, v = 20 * random.nextDouble() - 10;
            new SurfaceTexture(new Texture.Checker(CHECKER.even(), CHECKER.odd(), su, sv)).lookup(u, v, out);
            boolean even = (Math.floorMod((long) Math.floor(u * su) + (long) Math.floor(v * sv), 2L)) == 0;
            Surface.Vec want = even ? CHECKER.even() : CHECKER.odd();
            assertEquals(want.r(), out[0], EXACT, "u " + u + " v " + v + " su " + su + " sv " + sv);
            assertEquals(want.b(), out[2], EXACT, "u " + u + " v " + v + " su " + su + " sv " + sv);
        }
    }

    /** A plane z = 0 whose diffuse colour is {@link #CHECKER}, under a constant sky of radiance 2. */
    private static Scene checkerPlane() {
        return Scene.builder().addMaterial(Material.DEFAULT).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .surface(0, Surface.diffuse(1, 1, 1).withTexture(CHECKER)).environment(Environment.color(2, 2, 2))
                .build();
    }

    private static RenderJob job(Scene scene, int size, int spp, String shading, Integrator integrator) {
        RenderSettings s = new RenderSettings(size, size, spp, "jittered", "clipping", true, shading, 0, true, 8);
        RenderOptions o = RenderOptions.defaults().withThreads(2).withTileSize(8).withProgressive(false)
                .withPath(PathOptions.defaults().withIntegrator(integrator).withMaxDepth(8));
        return RenderJob.prepare(scene, s, o).withCamera(Camera.lookAt(new Vec3(0.3, 0.2, 5), new Vec3(0.3, 0.2, 0),
                Vec3.Y, 30));
    }

    /** The checker square (0 even, 1 odd) under the image point (x, y), or -1 when the ray misses. */
    private static int square(RenderJob job, double x, double y) {
        SceneIntersector si = job.intersector();
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double[] ray = new double[6];
        int size = job.settings().width();
        job.camera().generateRay(x, y, size, size, ray);
        if (!si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, hit)) {
            return -1;
        }
        return (int) Math.floorMod((long) Math.floor(hit.u) + (long) Math.floor(hit.v), 2L);
    }

    @Test
    void aCheckerDiffusePlaneUnderAConstantSkyHasRadianceAlbedoTimesSkyOnEachSquare() {
        int size = 32;
        RenderJob job = job(checkerPlane(), size, 16, "phong", Integrator.PATH);
        float[] rgb = Renderer.renderOnce(job).film().linearRgb();
        double[][] sum = new double[2][3];
        int[] count = new int[2];
        for (int y = 0; y < size; y++) {
            for (int x = 0; x < size; x++) {
                // only pixels wholly inside one square: all four corners agree
                int s = square(job, x, y);
                if (s < 0 || square(job, x + 1, y) != s || square(job, x, y + 1) != s || square(job, x + 1, y + 1) != s) {
                    continue;
                }
                count[s]++;
                for (int c = 0; c < 3; c++) {
                    sum[s][c] += rgb[3 * (y * size + x) + c];
                }
            }
        }
        assertTrue(count[0] > 100 && count[1] > 100, "both squares in view: " + count[0] + ", " + count[1]);
        Surface.Vec[] albedo = {CHECKER.even(), CHECKER.odd()};
        for (int s = 0; s < 2; s++) {
            double[] a = {albedo[s].r(), albedo[s].g(), albedo[s].b()};
            for (int c = 0; c < 3; c++) {
                double mean = sum[s][c] / count[s];
                assertEquals(2 * a[c], mean, 0.01 * 2 * a[c], (s == 0 ? "even" : "odd") + " squares, channel " + c);
            }
        }
    }

    @Test
    void theWhittedRendererShowsTheTextureAsTheBaseColour() {
        RenderJob job = job(checkerPlane(), 8, 1, "flat", Integrator.WHITTED);
        WhittedTracer tracer = WhittedTracer.forJob(job);
        SurfaceTexture texture = new SurfaceTexture(CHECKER);
        double[] rgb = new double[3], want = new double[3];
        SceneIntersector si = job.intersector();
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        int[] seen = new int[2];
        for (double x = -1.55; x < 1.6; x += 0.3) {
            for (double y = -1.45; y < 1.6; y += 0.3) {
                rgb[0] = 0; rgb[1] = 0; rgb[2] = 0;
                tracer.trace(x, y, 3, 0, 0, -1, rgb);
                assertTrue(si.closestHit(ctx, x, y, 3, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
                texture.lookup(hit.u, hit.v, want);
                seen[want[0] > 0.5 ? 0 : 1]++;
                for (int c = 0; c < 3; c++) {
                    assertEquals(want[c], rgb[c], EXACT, "at " + x + ", " + y + " channel " + c);
                }
            }
        }
        assertTrue(seen[0] > 10 && seen[1] > 10, "both colours met: " + seen[0] + ", " + seen[1]);
    }
}
