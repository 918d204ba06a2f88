package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ON_SURFACE;
import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROOT_UV;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Accuracy of the three solvers: a ray aimed at S(u*,v*) comes back with t*, u*, v*. */
class BezierClipperTest {

    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "NEWTON"})
    void rayAimedAtASurfacePointReturnsItsParameters(Method method) {
        Random rnd = new Random(20211);
        int rays = 0, earlier = 0, misses = 0;
        for (int trial = 0; trial < 1200; trial++) { // thousands of patches and rays
            int n = 1 + rnd.nextInt(9), m = 1 + rnd.nextInt(9);
            double size = Math.pow(10, rnd.nextInt(5) - 2);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, size, 0.6);
            for (IntersectOptions opts : List.of(IntersectOptions.defaults().withMethod(method),
                    IntersectOptions.defaults().withMethod(method).withBvh(false))) {
                if (method == Method.NEWTON && !opts.bvh()) {
                    continue; // Newton from the whole patch's centre is not expected to converge
                }
                SceneIntersector si = SceneIntersector.build(new Scene(List.of(patch)), opts);
                TraceContext ctx = si.newContext();
                Hit hit = new Hit();
                double[] s = new double[3];
                for (int r = 0; r < 8; r++) {
                    double us = rnd.nextDouble(), vs = rnd.nextDouble();
                    DeCasteljau.evaluate(patch.copyNet(), 0, n, m, 3, us, vs, s, 0, new double[DeCasteljau.SCRATCH_LENGTH]);
                    // origin above the surface, direction not unit
                    double ox = s[0] + size * (rnd.nextDouble() - 0.5), oy = s[1] + size * (rnd.nextDouble() - 0.5);
                    double oz = size * (1 + 2 * rnd.nextDouble());
                    double scale = 0.1 + 3 * rnd.nextDouble();
                    double dx = (s[0] - ox) * scale, dy = (s[1] - oy) * scale, dz = (s[2] - oz) * scale;
                    double tStar = 1 / scale;
                    rays++;
                    String where = method + " bvh=" + opts.bvh() + " degree " + n + "x" + m + " size " + size
                            + " (u*,v*)=(" + us + "," + vs + ") o=(" + ox + "," + oy + "," + oz + ")";
                    if (!si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
                        misses++;
                        if (method == Method.CLIPPING) {
                            fail("missed: " + where);
                        }
                        continue;
                    }
                    if (Math.abs(hit.t - tStar) <= ROOT_T * size * scale) {
                        assertEquals(us, hit.u, ROOT_UV, "u " + where);
                        assertEquals(vs, hit.v, ROOT_UV, "v " + where);
                    } else if (method == Method.NEWTON && hit.t > tStar) {
                        misses++; // Newton missed the nearer root and converged to a farther one
                    } else {
                        // a genuine nearer root: the surface meets the ray before S(u*,v*)
                        assertTrue(hit.t < tStar, "t " + hit.t + " beyond t* " + tStar + ": " + where);
                        assertOnRay(patch, hit, ox, oy, oz, dx, dy, dz, size, where);
                        earlier++;
                    }
                }
            }
        }
        assertTrue(earlier < rays / 20, "too many nearer roots: " + earlier + " of " + rays);
        if (method == Method.NEWTON) {
            assertTrue(misses < rays / 50, "Newton missed " + misses + " of " + rays);
        }
    }

    static void assertOnRay(BezierPatch patch, Hit hit, double ox, double oy, double oz,
                            double dx, double dy, double dz, double size, String where) {
        double[] s = new double[3];
        DeCasteljau.evaluate(patch.copyNet(), 0, patch.degreeU(), patch.degreeV(), 3, hit.u, hit.v, s, 0,
                new double[DeCasteljau.SCRATCH_LENGTH]);
        double ex = ox + hit.t * dx - s[0], ey = oy + hit.t * dy - s[1], ez = oz + hit.t * dz - s[2];
        double err = Math.sqrt(ex * ex + ey * ey + ez * ez);
        assertTrue(err <= ON_SURFACE * size, "hit point off the surface by " + err + ": " + where);
    }

    /** Near-tangent rays: whatever is returned must be a genuine root, and nothing may be NaN. */
    @ParameterizedTest
    @EnumSource(Method.class)
    void grazingRaysReturnGenuineRootsOrMiss(Method method) {
        Random rnd = new Random(31);
        int hits = 0, rays = 0;
        for (int trial = 0; trial < 200; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, 2, 0.3);
            SceneIntersector si = SceneIntersector.build(new Scene(List.of(patch)), IntersectOptions.defaults().withMethod(method));
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            SurfacePoint sp = new SurfacePoint();
            double[] e = new double[9];
            for (int r = 0; r < 10; r++) {
                // a ray tangent to the surface at a random point, nudged off by up to 1e-6
                double us = rnd.nextDouble(), vs = rnd.nextDouble();
                DeCasteljau.evaluateWithDerivatives(patch.copyNet(), 0, n, m, us, vs, e, new double[DeCasteljau.SCRATCH_LENGTH]);
                double a = rnd.nextDouble() * 2 * Math.PI;
                double dx = Math.cos(a) * e[3] + Math.sin(a) * e[6], dy = Math.cos(a) * e[4] + Math.sin(a) * e[7],
                        dz = Math.cos(a) * e[5] + Math.sin(a) * e[8];
                double nudge = 1e-6 * (rnd.nextDouble() - 0.5);
                double ox = e[0] - 3 * dx, oy = e[1] - 3 * dy, oz = e[2] - 3 * dz + nudge;
                rays++;
                String where = method + " degree " + n + "x" + m + " tangent at (" + us + "," + vs + ") angle " + a;
                if (si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
                    hits++;
                    assertTrue(Double.isFinite(hit.t) && hit.t > 0, "t " + hit.t + ": " + where);
                    if (method != Method.SUBDIVISION) {
                        assertOnRay(patch, hit, ox, oy, oz, dx, dy, dz, 2 * 1e3, where);
                    }
                    si.surfacePoint(ctx, hit, sp);
                    assertTrue(Double.isFinite(sp.nx + sp.ny + sp.nz + sp.px + sp.py + sp.pz), "NaN surface point: " + where);
                }
                assertEquals(si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit),
                        si.occluded(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY), "occluded agrees: " + where);
            }
        }
        assertTrue(hits > rays / 10, method + " grazing rays hit " + hits + " of " + rays);
    }
}
