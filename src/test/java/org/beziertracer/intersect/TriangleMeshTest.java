package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.junit.jupiter.api.Test;

/**
 * {@link TriangleMesh} on its own: the watertight test reports rays exactly through edges and
 * vertices (on the patch border and inside, seen from either side, for either winding), never a
 * zero-area triangle, only {@code tMin < t < tMax}, and rays along every axis; the surface point
 * of a triangle has derivatives that reproduce its edges, the interpolated vertex normal or, where
 * that cancels, the triangle's own normal; {@code bytes()} counts the arrays it holds.
 */
class TriangleMeshTest {

    /** The bilinear patch with corners {@code o, o+a, o+b, o+a+b} (a flat parallelogram). */
    private static BezierPatch parallelogram(Vec3 o, Vec3 a, Vec3 b) {
        Vec3 c = o.add(a).add(b), p10 = o.add(a), p01 = o.add(b);
        return new BezierPatch(1, 1, new double[] {o.x(), o.y(), o.z(), p10.x(), p10.y(), p10.z(),
                p01.x(), p01.y(), p01.z(), c.x(), c.y(), c.z()});
    }

    private static Vec3 random(Random rnd, double scale) {
        return new Vec3(scale * (2 * rnd.nextDouble() - 1), scale * (2 * rnd.nextDouble() - 1),
                scale * (2 * rnd.nextDouble() - 1));
    }

    private static Vec3 corner(TriangleMesh tm, int t, int corner) {
        int vert = tm.mesh.triangleVertex(t, corner);
        return new Vec3(tm.mesh.position(vert, 0), tm.mesh.position(vert, 1), tm.mesh.position(vert, 2));
    }

    private static boolean hit(TriangleMesh tm, TraceContext c, double[] o, double[] d, double tMin, double tMax) {
        c.setRay(o[0], o[1], o[2], d[0], d[1], d[2]);
        TriangleMesh.setRay(c);
        boolean any = false;
        for (int t = 0; t < tm.count; t++) {
            if (tm.intersect(c, t, tMin, tMax)) {
                any = true;
                tMax = c.rootT;
            }
        }
        return any;
    }

    /**
     * The unit square in z = 0 cut into 2×2 cells (both windings): rays along ±z exactly through
     * the midpoints of its border edges (each edge of one triangle only, one for each of the three
     * edge functions), its inner edges (horizontal, vertical, diagonal) and its vertices all hit at
     * t = 1 with barycentric weights that give the point back.
     */
    @Test
    void raysExactlyThroughEdgesAndVerticesHitFromEitherSideForEitherWinding() {
        double[][] points = {
            {0.25, 0}, {0.75, 0}, {1, 0.25}, {1, 0.75}, {0.25, 1}, {0.75, 1}, {0, 0.25}, {0, 0.75}, // border
            {0.5, 0.25}, {0.5, 0.75}, {0.25, 0.5}, {0.75, 0.5}, {0.25, 0.25}, {0.75, 0.75},           // inner edges
            {0.5, 0.5}, {0.5, 0}, {1, 0.5}, {0, 0}, {1, 1}, {0, 1}, {0.5, 1}, {1, 0}, {0.3, 0.6}       // vertices, inside
        };
        BezierPatch[] windings = {parallelogram(Vec3.ZERO, Vec3.X, Vec3.Y), parallelogram(Vec3.ZERO, Vec3.Y, Vec3.X)};
        TraceContext c = new TraceContext();
        for (BezierPatch patch : windings) {
            TriangleMesh tm = TriangleMesh.build(List.of(patch), 2);
            for (double side : new double[] {1, -1}) {
                for (double[] p : points) {
                    String where = "point (" + p[0] + ", " + p[1] + ") from z = " + side + ", net " + patch;
                    assertTrue(hit(tm, c, new double[] {p[0], p[1], side}, new double[] {0, 0, -side}, 0, 2), where);
                    assertEquals(1, c.rootT, 0, where);
                    int t = -1;
                    for (int k = 0; k < tm.count && t < 0; k++) {
                        t = tm.intersect(c, k, 0, 2) ? k : -1;
                    }
                    SurfacePoint sp = new SurfacePoint();
                    tm.surfacePoint(t, c.rootB1, c.rootB2, sp);
                    assertEquals(p[0], sp.px, ROUNDING, where);
                    assertEquals(p[1], sp.py, ROUNDING, where);
                    assertEquals(0, sp.pz, 0, where);
                }
                // just outside the square: a miss
                assertFalse(hit(tm, c, new double[] {1.001, 0.5, side}, new double[] {0, 0, -side}, 0, 2));
                assertFalse(hit(tm, c, new double[] {0.5, -0.001, side}, new double[] {0, 0, -side}, 0, 2));
            }
        }
    }

    @Test
    void onlyHitsStrictlyInsideTheIntervalCount() {
        TriangleMesh tm = TriangleMesh.build(List.of(parallelogram(Vec3.ZERO, Vec3.X, Vec3.Y)), 1);
        TraceContext c = new TraceContext();
        double[] o = {0.3, 0.6, 1}, d = {0, 0, -1};
        assertTrue(hit(tm, c, o, d, 0, Math.nextUp(1.0)));
        assertFalse(hit(tm, c, o, d, 0, 1), "t = tMax is outside");
        assertFalse(hit(tm, c, o, d, 1, 2), "t = tMin is outside");
        assertTrue(hit(tm, c, o, d, Math.nextDown(1.0), 2));
        assertFalse(hit(tm, c, o, new double[] {0, 0, 1}, 0, 100), "behind the origin");
    }

    /** A triangle facing each axis, met by a ray along that axis (both ways) and by oblique rays. */
    @Test
    void raysAlongEveryAxisAndObliqueRaysHitAtTheRightPoint() {
        Random rnd = new Random(41);
        TraceContext c = new TraceContext();
        Vec3[] axes = {Vec3.X, Vec3.Y, Vec3.Z};
        for (int axis = 0; axis < 3; axis++) {
            Vec3 a = axes[(axis + 1) % 3].scale(2), b = axes[(axis + 2) % 3].scale(3);
            Vec3 o = axes[axis].scale(-0.5);
            TriangleMesh tm = TriangleMesh.build(List.of(parallelogram(o, a, b)), 1);
            for (int trial = 0; trial < 200; trial++) {
                // a point inside the parallelogram, a ray toward it from distance 1..3 on either side
                double s = 0.05 + 0.9 * rnd.nextDouble(), r = 0.05 + 0.9 * rnd.nextDouble();
                Vec3 target = o.add(a.scale(s)).add(b.scale(r));
                double side = rnd.nextBoolean() ? 1 : -1, dist = 1 + 2 * rnd.nextDouble();
                Vec3 dir = trial % 2 == 0 ? axes[axis].scale(-side)
                        : axes[axis].scale(-side).add(random(rnd, 0.4)).scale(0.5 + rnd.nextDouble());
                Vec3 origin = target.sub(dir.scale(dist));
                String where = "axis " + axis + " trial " + trial;
                assertTrue(hit(tm, c, new double[] {origin.x(), origin.y(), origin.z()},
                        new double[] {dir.x(), dir.y(), dir.z()}, 0, 10), where);
                assertEquals(dist, c.rootT, 1e-12 * dist, where);
            }
        }
    }

    /** A patch with a collapsed edge: its zero-area triangle is never reported, the real one is. */
    @Test
    void aZeroAreaTriangleIsNeverReported() {
        // P00 = P10: the edge v = 0 is one point (the apex)
        BezierPatch fan = new BezierPatch(1, 1, new double[] {0, 0, 0, 0, 0, 0, -1, 1, 0, 1, 1, 0});
        TriangleMesh tm = TriangleMesh.build(List.of(fan), 1);
        TraceContext c = new TraceContext();
        // triangle 0 = (v00, v10, v11) has two corners at the apex; triangle 1 = (v00, v11, v01) is real
        assertEquals(0, corner(tm, 0, 0).sub(corner(tm, 0, 1)).length(), 0);
        for (double[] p : new double[][] {{0, 0}, {0.5, 0.5}, {0.25, 0.25}}) {
            c.setRay(p[0], p[1], 1, 0, 0, -1);
            TriangleMesh.setRay(c);
            assertFalse(tm.intersect(c, 0, 0, 10), "zero-area triangle at (" + p[0] + ", " + p[1] + ")");
            assertTrue(tm.intersect(c, 1, 0, 10), "its neighbour at (" + p[0] + ", " + p[1] + ")");
            assertEquals(1, c.rootT, 0);
        }
    }

    /**
     * Any patch, any triangle of a 4×4 tessellation: the point is the barycentric combination of
     * the corners, the derivatives reproduce the triangle's edges from its vertices' (u,v)
     * ({@code e = dp/du·Δu + dp/dv·Δv}), and the normal is the unit interpolant of the vertex normals.
     */
    @Test
    void theSurfacePointOfATriangleInterpolatesItsCornersAndItsDerivativesReproduceItsEdges() {
        Random rnd = new Random(42);
        SurfacePoint sp = new SurfacePoint();
        for (int trial = 0; trial < 20; trial++) {
            BezierPatch patch = RandomPatches.wild(rnd, 1 + rnd.nextInt(4), 1 + rnd.nextInt(4), 4);
            TriangleMesh tm = TriangleMesh.build(List.of(patch), 4);
            Mesh m = tm.mesh;
            for (int t = 0; t < tm.count; t++) {
                double b1 = rnd.nextDouble(), b2 = (1 - b1) * rnd.nextDouble(), b0 = 1 - b1 - b2;
                tm.surfacePoint(t, b1, b2, sp);
                Vec3 p0 = corner(tm, t, 0), p1 = corner(tm, t, 1), p2 = corner(tm, t, 2);
                Vec3 p = p0.scale(b0).add(p1.scale(b1)).add(p2.scale(b2));
                String where = "trial " + trial + " triangle " + t;
                assertEquals(p.x(), sp.px, 4 * ROUNDING, where);
                assertEquals(p.y(), sp.py, 4 * ROUNDING, where);
                assertEquals(p.z(), sp.pz, 4 * ROUNDING, where);
                int i0 = m.triangleVertex(t, 0), i1 = m.triangleVertex(t, 1), i2 = m.triangleVertex(t, 2);
                double du1 = m.uv(i1, 0) - m.uv(i0, 0), dv1 = m.uv(i1, 1) - m.uv(i0, 1);
                double du2 = m.uv(i2, 0) - m.uv(i0, 0), dv2 = m.uv(i2, 1) - m.uv(i0, 1);
                Vec3 dpdu = new Vec3(sp.dpdux, sp.dpduy, sp.dpduz), dpdv = new Vec3(sp.dpdvx, sp.dpdvy, sp.dpdvz);
                Vec3 e1 = dpdu.scale(du1).add(dpdv.scale(dv1)).sub(p1.sub(p0));
                Vec3 e2 = dpdu.scale(du2).add(dpdv.scale(dv2)).sub(p2.sub(p0));
                assertEquals(0, e1.length(), 16 * ROUNDING, "edge 1 from dp/du, dp/dv: " + where);
                assertEquals(0, e2.length(), 16 * ROUNDING, "edge 2 from dp/du, dp/dv: " + where);
                Vec3 n = new Vec3(0, 0, 0);
                double[] w = {b0, b1, b2};
                for (int k = 0; k < 3; k++) {
                    int v = m.triangleVertex(t, k);
                    n = n.add(new Vec3(m.normal(v, 0), m.normal(v, 1), m.normal(v, 2)).scale(w[k]));
                }
                n = n.normalize();
                assertEquals(n.x(), sp.nx, ROUNDING, where);
                assertEquals(n.y(), sp.ny, ROUNDING, where);
                assertEquals(n.z(), sp.nz, ROUNDING, where);
            }
        }
    }

    /** A flat parallelogram: every triangle's derivatives are the patch's own edges, whatever the cell. */
    @Test
    void aFlatParallelogramsTrianglesHaveThePatchsDerivatives() {
        Random rnd = new Random(43);
        SurfacePoint sp = new SurfacePoint();
        for (int trial = 0; trial < 20; trial++) {
            Vec3 o = random(rnd, 5), a = random(rnd, 2), b = random(rnd, 2);
            TriangleMesh tm = TriangleMesh.build(List.of(parallelogram(o, a, b)), 3);
            Vec3 n = a.cross(b).normalize();
            for (int t = 0; t < tm.count; t++) {
                tm.surfacePoint(t, 0.2, 0.3, sp);
                String where = "trial " + trial + " triangle " + t;
                double tol = 8 * ROUNDING * (1 + o.length());
                assertEquals(a.x(), sp.dpdux, tol, where);
                assertEquals(a.y(), sp.dpduy, tol, where);
                assertEquals(a.z(), sp.dpduz, tol, where);
                assertEquals(b.x(), sp.dpdvx, tol, where);
                assertEquals(b.y(), sp.dpdvy, tol, where);
                assertEquals(b.z(), sp.dpdvz, tol, where);
                assertEquals(1, n.dot(new Vec3(sp.nx, sp.ny, sp.nz)), ROUNDING, where);
                // the point is the patch at the interpolated (u,v)
                double u = tm.uv(t, 0.2, 0.3, 0), v = tm.uv(t, 0.2, 0.3, 1);
                Vec3 p = o.add(a.scale(u)).add(b.scale(v));
                assertEquals(p.x(), sp.px, tol, where);
                assertEquals(p.y(), sp.py, tol, where);
                assertEquals(p.z(), sp.pz, tol, where);
            }
        }
    }

    /**
     * A U-shaped cubic strip, obliquely placed (dyadic coordinates, so everything below is exact):
     * its u-derivatives at the two ends are exact opposites, so are the vertex normals there, and
     * halfway between them the interpolated normal vanishes: the triangle's own unit normal is used.
     */
    @Test
    void whereTheVertexNormalsCancelTheTrianglesOwnNormalIsUsed() {
        Vec3 d = new Vec3(1, 0.5, 0.25), p3 = new Vec3(0.125, 0.75, 1), extrude = new Vec3(0.25, 1, -0.5);
        Vec3[] curve = {Vec3.ZERO, d, p3.add(d), p3}; // P1 - P0 = d = -(P3 - P2)
        double[] net = new double[4 * 2 * 3];
        for (int j = 0; j <= 1; j++) {
            for (int i = 0; i <= 3; i++) {
                Vec3 p = curve[i].add(extrude.scale(j));
                System.arraycopy(new double[] {p.x(), p.y(), p.z()}, 0, net, 3 * (j * 4 + i), 3);
            }
        }
        TriangleMesh tm = TriangleMesh.build(List.of(new BezierPatch(3, 1, net)), 1);
        Mesh m = tm.mesh;
        int i0 = m.triangleVertex(0, 0), i1 = m.triangleVertex(0, 1), i2 = m.triangleVertex(0, 2);
        for (int c = 0; c < 3; c++) {
            assertEquals(-m.normal(i0, c), m.normal(i1, c), 0, "opposite normals at u = 0 and u = 1");
            assertEquals(m.normal(i1, c), m.normal(i2, c), 0);
        }
        SurfacePoint sp = new SurfacePoint();
        tm.surfacePoint(0, 0.25, 0.25, sp);
        Vec3 p0 = corner(tm, 0, 0), n = corner(tm, 0, 1).sub(p0).cross(corner(tm, 0, 2).sub(p0)).normalize();
        assertEquals(n.x(), sp.nx, ROUNDING);
        assertEquals(n.y(), sp.ny, ROUNDING);
        assertEquals(n.z(), sp.nz, ROUNDING);
        // just beside the cancelling point the interpolant wins again, pointing either way
        tm.surfacePoint(0, 0.2, 0.25, sp);
        assertEquals(m.normal(i0, 2), sp.nz, ROUNDING);
        tm.surfacePoint(0, 0.3, 0.25, sp);
        assertEquals(m.normal(i1, 2), sp.nz, ROUNDING);
    }

    @Test
    void bytesCountTheMeshAndTheTriangleArraysWithTheirHeaders() {
        Random rnd = new Random(44);
        for (int k : new int[] {1, 3, 7}) {
            List<BezierPatch> patches = List.of(RandomPatches.wild(rnd, 3, 2, 1), RandomPatches.wild(rnd, 1, 4, 1));
            TriangleMesh tm = TriangleMesh.build(patches, k);
            long v = tm.mesh.vertexCount(), t = tm.count;
            // positions, normals, uvs, triangle indices and patch tags; corners, boxes, patch of each triangle
            long elements = 8 * (3 + 3 + 2) * v + 4 * (3 + 1) * t + 8 * (9 + 6) * t + 4 * t;
            long bytes = tm.bytes();
            assertTrue(bytes >= elements + 8 * 16 && bytes <= elements + 8 * 24, "K = " + k + ": " + bytes + " for " + elements);
        }
    }
}
