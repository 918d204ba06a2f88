package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.NORMAL;
import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** The Utah teapot: collapsed lid top, the knob, and no cracks along patch borders. */
class TeapotIntersectionTest {

    static final Scene TEAPOT = Models.load("teapot");
    /** The diagonal of the teapot's control box, the scale of its tolerances. */
    static final double TEAPOT_SIZE = TEAPOT.controlBounds().diagonal();

    static void assertUnitNormal(SurfacePoint sp, String where) {
        double len = Math.sqrt(sp.nx * sp.nx + sp.ny * sp.ny + sp.nz * sp.nz);
        assertTrue(Double.isFinite(len) && Math.abs(len - 1) < ROUNDING, "normal " + sp.nx + "," + sp.ny + "," + sp.nz + " at " + where);
    }

    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "SUBDIVISION"})
    void raysThroughTheCollapsedLidTopHitWithFiniteNormals(Method method) {
        SceneIntersector si = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(method));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        Random rnd = new Random(120);
        for (int r = 0; r < 500; r++) {
            // from above, through (0,0,120) exactly, in a cone of directions
            double dx = 0.3 * rnd.nextGaussian(), dy = 0.3 * rnd.nextGaussian();
            double ox = -dx * 100, oy = -dy * 100, oz = 220;
            String where = "ray " + r + " o=(" + ox + "," + oy + "," + oz + ") d=(" + dx + "," + dy + ",-1)";
            assertTrue(si.closestHit(ctx, ox, oy, oz, dx, dy, -1, 0, Double.POSITIVE_INFINITY, hit), "missed the lid top: " + where);
            si.surfacePoint(ctx, hit, sp);
            assertUnitNormal(sp, where);
            if (method == Method.CLIPPING) {
                assertEquals(100, hit.t, ROOT_T * TEAPOT_SIZE, "the lid top is at t=100: " + where);
                assertEquals(1, Math.abs(sp.nz), NORMAL, "lid-top normal is vertical: " + where);
            }
        }
    }

    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "NEWTON"})
    void raysAtTheKnobAroundTheRingAtZ108HitWithFiniteNormals(Method method) {
        SceneIntersector si = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(method));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] s = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        Random rnd = new Random(108);
        int tested = 0;
        for (int k = 0; k < TEAPOT.patchCount(); k++) {
            BezierPatch p = TEAPOT.patches().get(k);
            if (p.controlBounds().minZ() > 108 + 1e-9 || p.controlBounds().maxZ() < 108 - 1e-9 || p.controlBounds().minZ() < 90) {
                continue; // the knob patches span z = 108
            }
            for (int r = 0; r < 200; r++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                DeCasteljau.evaluate(p.copyNet(), 0, 3, 3, 3, u, v, s, 0, scratch);
                // from above and outside, aimed at the surface point
                double ox = s[0] * 3, oy = s[1] * 3, oz = 200;
                String where = "patch " + k + " (u,v)=(" + u + "," + v + ")";
                tested++;
                if (!si.closestHit(ctx, ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz, 0, Double.POSITIVE_INFINITY, hit)) {
                    assertTrue(method == Method.NEWTON, "missed the knob: " + where);
                    continue;
                }
                si.surfacePoint(ctx, hit, sp);
                assertUnitNormal(sp, where);
            }
        }
        assertTrue(tested >= 400, "knob patches found: " + tested / 200);
    }

    /** Shoots a dense grid of rays at every patch border; none may fall through ({@link BorderRays}). */
    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "SUBDIVISION"})
    void raysAtPatchBordersNeverFallThrough(Method method) {
        BorderRays.assertNoneFallThrough(TEAPOT, method);
    }
}
