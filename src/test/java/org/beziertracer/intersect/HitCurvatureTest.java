package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.SurfaceCurvature;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.Plane;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link SceneIntersector#curvature} at real hits, for every method: the built-in unit sphere has
 * K = 1 and |H| = 1 (its rational pieces and their collapsed poles), the torus its closed form;
 * an analytic sphere is −1/r against its outward normal, a plane is flat.
 */
class HitCurvatureTest {

    /** Seeded rays from outside toward the unit ball around the origin. */
    private static void eachHit(SceneIntersector si, int rays, long seed, HitCheck check) {
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] c = new double[SurfaceCurvature.LENGTH];
        Random rnd = new Random(seed);
        int hits = 0;
        for (int r = 0; r < rays; r++) {
            double gx = rnd.nextGaussian(), gy = rnd.nextGaussian(), gz = rnd.nextGaussian();
            double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
            double ox = 4 * gx / len, oy = 4 * gy / len, oz = 4 * gz / len;
            double tx = 1.4 * (rnd.nextDouble() - 0.5), ty = 1.4 * (rnd.nextDouble() - 0.5), tz = 1.4 * (rnd.nextDouble() - 0.5);
            if (si.closestHit(ctx, ox, oy, oz, tx - ox, ty - oy, tz - oz, 0, Double.POSITIVE_INFINITY, hit)) {
                si.surfacePoint(ctx, hit, sp);
                si.curvature(ctx, hit, sp, c);
                check.at(hit, sp, c);
                hits++;
            }
        }
        assertTrue(hits > rays / 4, "the rays hit: " + hits);
    }

    interface HitCheck {
        void at(Hit hit, SurfacePoint sp, double[] c);
    }

    @Test
    void theBuiltInSphereHasKOneAndHMinusOneAtEveryHitForEveryMethod() {
        for (Method method : Method.values()) {
            SceneIntersector si = SceneIntersector.build(Models.sphere(), IntersectOptions.defaults().withMethod(method));
            double tol = 1e-9;
            eachHit(si, 2000, 34 + method.ordinal(), (hit, sp, c) -> {
                assertEquals(1, c[SurfaceCurvature.GAUSSIAN], tol, method + " K at " + hit);
                assertEquals(1, Math.abs(c[SurfaceCurvature.MEAN]), tol, method + " |H| at " + hit);
                // signed against the reported normal: the same normal as the hit's surface point
                double dot = sp.nx * c[SurfaceCurvature.NORMAL] + sp.ny * c[SurfaceCurvature.NORMAL + 1]
                        + sp.nz * c[SurfaceCurvature.NORMAL + 2];
                assertEquals(1, dot, 1e-9, method + ": the curvature's normal is the reported one");
            });
        }
    }

    @Test
    void theTorusHasItsClosedFormAtEveryHit() {
        for (Method method : Method.values()) {
            SceneIntersector si = SceneIntersector.build(Models.torus(), IntersectOptions.defaults().withMethod(method));
            eachHit(si, 2000, 35 + method.ordinal(), (hit, sp, c) -> {
                // at the surface point of the hit's (u,v): ρ = distance from the axis
                double rho = Math.hypot(sp.px, sp.py), r = 0.35;
                double expected = (rho - 1) / (r * r * rho);
                assertEquals(expected, c[SurfaceCurvature.GAUSSIAN], 1e-9 * (1 + Math.abs(expected)),
                        method + " K at " + hit);
            });
        }
    }

    @Test
    void anAnalyticSphereBendsAgainstItsOutwardNormalAndAPlaneIsFlat() {
        Scene scene = new Scene(List.of(), List.of(new Plane(new Vec3(0, 0, -3), new Vec3(0, 0, 1))),
                List.of(new Sphere(new Vec3(0, 0, 0), 0.5)));
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        int[] seen = new int[4];
        eachHit(si, 500, 36, (hit, sp, c) -> {
            seen[hit.kind]++;
            double k = hit.kind == Hit.SPHERE ? -2 : 0;
            assertEquals(k, c[SurfaceCurvature.K1], 0, "k1 of " + hit);
            assertEquals(k, c[SurfaceCurvature.K2], 0, "k2 of " + hit);
            assertEquals(k * k, c[SurfaceCurvature.GAUSSIAN], 0, "K of " + hit);
        });
        assertTrue(seen[Hit.SPHERE] > 0 && seen[Hit.PLANE] > 0, "both kinds hit: " + java.util.Arrays.toString(seen));
    }
}
