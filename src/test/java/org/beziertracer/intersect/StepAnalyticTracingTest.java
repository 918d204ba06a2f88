package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneFiles;
import org.beziertracer.model.io.TextSource;
import org.junit.jupiter.api.Test;

/**
 * The analytic faces of the STEP sampler ({@code step/make_fixtures.py}: a whole cylinder, a half
 * cone, a sphere patch, a torus patch), read as exact rational B-splines and traced: each ray's
 * hit distance matches the closed form of the surface, and a ray through the part the trims
 * leave out goes on to the face behind (the cone) or misses.
 */
class StepAnalyticTracingTest {

    private static final double T = 1e-7;

    private static List<FreeFormSurface> faces() throws Exception {
        var url = StepAnalyticTracingTest.class.getResource("/step/sampler.stp");
        String text = new String(url.openStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        return org.beziertracer.model.io.StepReader.readModel(TextSource.of(text, "sampler.stp")).surfaces();
    }

    private static SceneIntersector traced(FreeFormSurface s) {
        return SceneIntersector.build(new Scene(s.toPatches()), IntersectOptions.defaults());
    }

    @Test
    void raysMeetTheCylinderConeSphereAndTorusWhereTheirClosedFormsSay() throws Exception {
        List<FreeFormSurface> f = faces();
        SceneIntersector cylinder = traced(f.get(3)), cone = traced(f.get(4)), sphere = traced(f.get(5)),
                torus = traced(f.get(6));
        TraceContext ctx = cylinder.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(214);
        int behind = 0;
        for (int k = 0; k < 200; k++) {
            double th = 2 * Math.PI * rnd.nextDouble(), z = 0.05 + 1.9 * rnd.nextDouble();
            double c = Math.cos(th), s = Math.sin(th);
            // the cylinder of radius 1.5 about (5, 0): from 10 away towards the axis
            assertTrue(cylinder.closestHit(ctx, 5 + 10 * c, 10 * s, z, -c, -s, 0, 0, 100, hit), "cylinder at " + th);
            assertEquals(10 - 1.5, hit.t, T, "cylinder at " + th + ", " + z);
            // the half cone u in [0, π] about (0, 10): ρ = 1 + z tan 0.3; beyond π the ray meets the far side
            double rho = 1 + z * Math.tan(0.3);
            boolean front = Math.sin(th) > 0.05, back = Math.sin(th) < -0.05;
            if (front || back) {
                assertTrue(cone.closestHit(ctx, 10 * c, 10 + 10 * s, z, -c, -s, 0, 0, 100, hit), "cone at " + th);
                assertEquals(front ? 10 - rho : 10 + rho, hit.t, T, "cone at " + th + ", " + z);
                behind += back ? 1 : 0;
            }
            // the sphere patch u in [0, π/2], v in [0, π/4] of radius 2 about (0, 0, 10): from its centre
            double u = Math.PI / 2 * (0.02 + 0.96 * rnd.nextDouble()), v = Math.PI / 4 * (0.02 + 0.96 * rnd.nextDouble());
            double[] d = {Math.cos(v) * Math.cos(u), Math.cos(v) * Math.sin(u), Math.sin(v)};
            assertTrue(sphere.closestHit(ctx, 0, 0, 10, d[0], d[1], d[2], 0, 100, hit), "sphere at " + u + ", " + v);
            assertEquals(2, hit.t, T, "sphere at " + u + ", " + v);
            // outside the patch (u beyond π/2): nothing
            assertTrue(!sphere.closestHit(ctx, 0, 0, 10, -d[0], d[1], d[2], 0, 100, hit), "sphere behind at " + u);
            // the torus patch R = 3, r = 1 about (10, 10, 0), u, v in [−π/2, π/2]: from the tube's centre line
            u = Math.PI * (0.49 * (2 * rnd.nextDouble() - 1));
            v = Math.PI * (0.49 * (2 * rnd.nextDouble() - 1));
            double[] o = {10 + 3 * Math.cos(u), 10 + 3 * Math.sin(u), 0};
            d = new double[] {Math.cos(v) * Math.cos(u), Math.cos(v) * Math.sin(u), Math.sin(v)};
            assertTrue(torus.closestHit(ctx, o[0], o[1], o[2], d[0], d[1], d[2], 0, 100, hit), "torus at " + u + ", " + v);
            assertEquals(1, hit.t, T, "torus at " + u + ", " + v);
        }
        assertTrue(behind > 50, "rays through the cone's missing half: " + behind);
    }

    @Test
    void theSamplerOpensThroughTheRegistry() {
        var doc = SceneFiles.load("src/test/resources/step/sampler.stp");
        assertEquals(1 + 1 + 1 + 4 + 2 + 1 + 4 + 1, doc.scene().patchCount(),
                "pieces: quarter cylinder 1, polynomial 1, plane 1, cylinder 4 quarter arcs, half cone 2, sphere 1·1, "
                        + "torus 2·2, the polynomial again 1");
    }
}
