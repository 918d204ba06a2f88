package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.NORMAL;
import static org.beziertracer.Tolerances.ON_SURFACE;
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
    @EnumSource(Method.class)
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
            if (method != Method.SUBDIVISION) { // the exact methods
                assertEquals(100, hit.t, ROOT_T * TEAPOT_SIZE, "the lid top is at t=100: " + where);
                assertEquals(1, Math.abs(sp.nz), NORMAL, "lid-top normal is vertical: " + where);
            }
        }
    }

    /**
     * Rays from above and outside at random points of the knob patches (around the ring at
     * z = 108, where the knob's profile turns sharply): every hit has a unit normal and lies on
     * the surface; clipping hits the aimed point unless the surface is nearer; Newton hits what
     * clipping hits, never missing or passing a nearer root (before issue #10: 33 of 800).
     */
    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "NEWTON"})
    void raysAtTheKnobAroundTheRingAtZ108HitTheSurface(Method method) {
        SceneIntersector si = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(method));
        SceneIntersector exact = SceneIntersector.build(TEAPOT, IntersectOptions.defaults());
        TraceContext ctx = si.newContext(), ce = exact.newContext();
        Hit hit = new Hit(), ref = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] s = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        Random rnd = new Random(108);
        int tested = 0, nearer = 0, missed = 0, farther = 0;
        for (int k = 0; k < TEAPOT.patchCount(); k++) {
            BezierPatch p = TEAPOT.patches().get(k);
            if (p.controlBounds().minZ() > 108 + 1e-9 || p.controlBounds().maxZ() < 108 - 1e-9 || p.controlBounds().minZ() < 90) {
                continue; // the knob patches span z = 108
            }
            for (int r = 0; r < 200; r++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                DeCasteljau.evaluate(p.copyNet(), 0, 3, 3, 3, u, v, s, 0, scratch);
                // from above and outside, aimed at the surface point: t = 1 there
                double ox = s[0] * 3, oy = s[1] * 3, oz = 200, dx = s[0] - ox, dy = s[1] - oy, dz = s[2] - oz;
                String where = method.label() + " patch " + k + " (u,v)=(" + u + "," + v + ")";
                double tTol = ROOT_T * TEAPOT_SIZE / Math.sqrt(dx * dx + dy * dy + dz * dz);
                tested++;
                assertTrue(exact.closestHit(ce, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, ref),
                        "clipping missed the knob: " + where);
                assertTrue(ref.t <= 1 + tTol, "clipping hit beyond the aimed point, t=" + ref.t + ": " + where);
                if (ref.t < 1 - tTol) {
                    nearer++; // the surface is in front of the aimed point
                }
                if (!si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
                    missed++;
                    continue;
                }
                si.surfacePoint(ctx, hit, sp);
                assertUnitNormal(sp, where);
                double ex = ox + hit.t * dx - sp.px, ey = oy + hit.t * dy - sp.py, ez = oz + hit.t * dz - sp.pz;
                assertTrue(Math.sqrt(ex * ex + ey * ey + ez * ez) <= ON_SURFACE * TEAPOT_SIZE,
                        "hit point off the surface: " + where);
                if (Math.abs(hit.t - ref.t) > tTol) {
                    assertTrue(hit.t > ref.t, "nearer than clipping's nearest root, t=" + hit.t + " vs " + ref.t + ": " + where);
                    farther++;
                }
            }
        }
        assertTrue(tested >= 400, "knob patches found: " + tested / 200);
        assertTrue(nearer > 0, "some aimed points lie behind nearer surface");
        assertEquals(0, missed + farther, method + " missed " + missed + " and returned a farther root " + farther
                + " times of " + tested);
    }
}
