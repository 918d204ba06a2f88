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
    /**
     * Rays of the knob test that Newton misses or answers with a farther root, of 800: today 0
     * misses and 33 farther roots (its leaf-centre start converges to the far side of the knob's
     * ring). Issue #10 is to bring this down; lower it then, never raise it.
     */
    static final int NEWTON_KNOB_WRONG = 33;
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

    /**
     * Rays from above and outside at random points of the knob patches (around the ring at
     * z = 108, where the knob's profile turns sharply): every hit has a unit normal and lies on
     * the surface; clipping hits the aimed point unless the surface is nearer; Newton (from its
     * leaf-centre starts) hits what clipping hits, missing or passing a nearer root on at most
     * the share measured today (issue #10 will lower it).
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
        int wrong = missed + farther;
        if (method == Method.CLIPPING) {
            assertEquals(0, wrong, "clipping missed " + missed + ", returned a farther root " + farther + " times");
        } else {
            assertTrue(wrong <= NEWTON_KNOB_WRONG, "Newton missed " + missed + " and returned a farther root " + farther
                    + " times of " + tested + " (bound " + NEWTON_KNOB_WRONG + ")");
        }
    }

    /** Shoots a dense grid of rays at every patch border; none may fall through. */
    @ParameterizedTest
    @EnumSource(value = Method.class, names = {"CLIPPING", "SUBDIVISION"})
    void raysAtPatchBordersNeverFallThrough(Method method) {
        SceneIntersector si = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(method));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH], nrm = new double[3];
        Random rnd = new Random(4);
        int rays = 0, misses = 0, onBorder = 0, shared = 0;
        StringBuilder firstMiss = new StringBuilder();
        for (int k = 0; k < TEAPOT.patchCount(); k++) {
            double[] net = TEAPOT.patches().get(k).copyNet();
            for (int border = 0; border < 4; border++) {
                if (!isShared(k, border)) {
                    continue; // an open edge (the bottom rim, the spout tip): a ray exactly at it may graze past
                }
                shared++;
                for (int a = 1; a < 40; a++) { // corners may lie on an open edge
                    double s = a / 40.0;
                    double u = border == 0 ? 0 : border == 1 ? 1 : s;
                    double v = border == 2 ? 0 : border == 3 ? 1 : s;
                    DeCasteljau.evaluateWithDerivatives(net, 0, 3, 3, u, v, e, scratch);
                    org.beziertracer.geometry.PatchNormals.unitNormal(net, 0, 3, 3, u, v, nrm, 0, scratch);
                    for (int r = 0; r < 3; r++) {
                        // from the outside (normals point into the pot), tilted at random
                        double dx = nrm[0] + 0.4 * rnd.nextGaussian(), dy = nrm[1] + 0.4 * rnd.nextGaussian(),
                                dz = nrm[2] + 0.4 * rnd.nextGaussian();
                        double ox = e[0] - 300 * dx, oy = e[1] - 300 * dy, oz = e[2] - 300 * dz;
                        rays++;
                        if (!si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
                            if (misses++ == 0) {
                                firstMiss.append("patch ").append(k).append(" (u,v)=(").append(u).append(',').append(v)
                                        .append(") o=(").append(ox).append(',').append(oy).append(',').append(oz)
                                        .append(") d=(").append(dx).append(',').append(dy).append(',').append(dz).append(')');
                            }
                            continue;
                        }
                        assertTrue(hit.t <= 300 + 1e-3, "hit beyond the aimed border point: t=" + hit.t + " patch " + k
                                + " (u,v)=(" + u + "," + v + ") P=(" + e[0] + "," + e[1] + "," + e[2] + ") d=(" + dx + "," + dy + "," + dz + ") hit patch " + hit.index + " uv " + hit.u + "," + hit.v);
                        if (Math.abs(hit.t - 300) < 1e-3) {
                            onBorder++;
                        }
                    }
                }
            }
        }
        assertTrue(shared >= 100, "shared borders found: " + shared);
        assertEquals(0, misses, misses + " of " + rays + " rays fell through a border; first: " + firstMiss);
        assertTrue(onBorder > rays / 2, "most rays should reach the border point itself: " + onBorder + " of " + rays);
    }

    /** Whether border {@code b} (u=0, u=1, v=0, v=1) of patch {@code k} coincides with a border of another patch. */
    static boolean isShared(int k, int b) {
        org.beziertracer.math.Vec3 mid = borderPoint(k, b, 0.5), q1 = borderPoint(k, b, 0.25);
        for (int k2 = 0; k2 < TEAPOT.patchCount(); k2++) {
            for (int b2 = 0; b2 < 4 && k2 != k; b2++) {
                for (double s : new double[] {0.5}) {
                    if (borderPoint(k2, b2, s).sub(mid).length() < 1e-6) {
                        // same border if the quarter point also lies on it (either direction)
                        if (borderPoint(k2, b2, 0.25).sub(q1).length() < 1e-6 || borderPoint(k2, b2, 0.75).sub(q1).length() < 1e-6) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    static org.beziertracer.math.Vec3 borderPoint(int k, int b, double s) {
        double u = b == 0 ? 0 : b == 1 ? 1 : s, v = b == 2 ? 0 : b == 3 ? 1 : s;
        return org.beziertracer.geometry.Patches.evaluate(TEAPOT.patches().get(k), u, v);
    }
}
