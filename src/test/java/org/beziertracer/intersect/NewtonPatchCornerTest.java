package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.intersect.TeapotIntersectionTest.TEAPOT;
import static org.beziertracer.intersect.TeapotIntersectionTest.TEAPOT_SIZE;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Newton where teapot patches 0, 2 and 15 meet: pixel (131, 191) of the app's home view of the
 * teapot at 400×300 ({@code OrbitView.fit(controlBounds, 40°).camera(4/3)}, the ray copied here as
 * literals since the app layer lies above this one). The ray crosses patch 0 at (u,v) ≈ (0.046,
 * 0.015) at 78° to the normal; its start on the corner leaf leads to a root of the patch's
 * extension beyond u = 0, and the quarter start that reaches the real root first steps to v ≈ −5e-4,
 * just beyond the patch's border (before the fix Newton returned patch 15's root, 0.51 farther).
 */
class NewtonPatchCornerTest {

    private static final double OX = -184.9494386275178, OY = -474.6629223811145, OZ = 478.8202256303952;
    private static final double DX = 0.15987674329744658, DY = 0.7122549347194231, DZ = -0.6834708003422184;

    private final SceneIntersector newton = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(Method.NEWTON));
    private final SceneIntersector clipping = SceneIntersector.build(TEAPOT, IntersectOptions.defaults());
    private final TraceContext cn = newton.newContext(), cc = clipping.newContext();
    private final Hit hn = new Hit(), hc = new Hit();

    /** Both methods on one ray: clipping's hit. */
    private Hit assertSameHit(double dx, double dy, double dz, String where) {
        assertTrue(clipping.closestHit(cc, OX, OY, OZ, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hc), "clipping missed: " + where);
        assertTrue(newton.closestHit(cn, OX, OY, OZ, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hn), "Newton missed: " + where);
        double length = Math.sqrt(dx * dx + dy * dy + dz * dz);
        assertEquals(hc.t, hn.t, ROOT_T * TEAPOT_SIZE / length,
                "Newton's t (patch " + hn.index + ") vs clipping's (patch " + hc.index + "): " + where);
        return hc;
    }

    @Test
    void newtonHitsPatchZeroNearItsCornerAsClippingDoes() {
        Hit hit = assertSameHit(DX, DY, DZ, "pixel (131, 191)");
        assertEquals(0, hit.index, "the nearest root is patch 0's");
        assertEquals(0.0457, hit.u, 1e-3);
        assertEquals(0.0155, hit.v, 1e-3);
    }

    /** A 41×41 grid of directions within ±2 pixels (±3.5e-3 rad) of the pixel's ray. */
    @Test
    void newtonAgreesWithClippingOnADenseNeighbourhoodOfTheRay() {
        // two unit vectors perpendicular to the ray
        double ax = DY, ay = -DX, az = 0, al = Math.hypot(ax, ay);
        ax /= al;
        ay /= al;
        double bx = DY * az - DZ * ay, by = DZ * ax - DX * az, bz = DX * ay - DY * ax;
        java.util.Set<Integer> patches = new java.util.TreeSet<>();
        for (int i = -20; i <= 20; i++) {
            for (int j = -20; j <= 20; j++) {
                double e = 1.75e-4 * i, f = 1.75e-4 * j;
                Hit hit = assertSameHit(DX + e * ax + f * bx, DY + e * ay + f * by, DZ + e * az + f * bz,
                        "offset (" + i + ", " + j + ")");
                patches.add(hit.index);
            }
        }
        assertTrue(patches.size() >= 3 && patches.contains(0), "the neighbourhood spans the corner: " + patches);
    }
}
