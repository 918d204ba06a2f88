package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.Plane;
import org.beziertracer.model.Sphere;
import org.junit.jupiter.api.Test;

/**
 * {@link AnalyticShapes} on its own, seeded random planes, spheres and rays (directions of any
 * length): roots lie on the surface and are the nearest in {@code (tMin, tMax)}, misses are NaN,
 * the surface frames are orthonormal where they should be, and the texture coordinates map back
 * to the hit point.
 */
class AnalyticShapesTest {

    private static Vec3 random(Random rnd, double scale) {
        return new Vec3(scale * (2 * rnd.nextDouble() - 1), scale * (2 * rnd.nextDouble() - 1),
                scale * (2 * rnd.nextDouble() - 1));
    }

    private static double dot(double ax, double ay, double az, double bx, double by, double bz) {
        return ax * bx + ay * by + az * bz;
    }

    @Test
    void sphereRootsAreOnTheSphereAndTheNearestInsideTheInterval() {
        Random rnd = new Random(91);
        TraceContext c = new TraceContext();
        int hits = 0, fromInside = 0;
        for (int trial = 0; trial < 4000; trial++) {
            Vec3 centre = random(rnd, 10);
            double r = 0.1 + 5 * rnd.nextDouble();
            AnalyticShapes s = new AnalyticShapes(List.of(), List.of(new Sphere(centre, r, 0)));
            // aimed near the sphere (most hit, some miss, some start inside), of any length
            Vec3 o = rnd.nextInt(5) == 0 ? centre.add(random(rnd, 0.5 * r)) : random(rnd, 12);
            Vec3 d = centre.add(random(rnd, 1.5 * r)).add(o.scale(-1)).scale(0.1 + 3 * rnd.nextDouble());
            c.setRay(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            // the two roots, independently, from |o + t d - c|² = r² in plain form
            double fx = o.x() - centre.x(), fy = o.y() - centre.y(), fz = o.z() - centre.z();
            double a = dot(d.x(), d.y(), d.z(), d.x(), d.y(), d.z()), b = 2 * dot(fx, fy, fz, d.x(), d.y(), d.z());
            double cc = dot(fx, fy, fz, fx, fy, fz) - r * r, disc = b * b - 4 * a * cc;
            double tMin = rnd.nextBoolean() ? 0 : -2 + 4 * rnd.nextDouble(), tMax = rnd.nextInt(4) == 0 ? 1 : 1e30;
            double t = s.sphereT(0, c, tMin, tMax);
            String where = "trial " + trial;
            if (disc < -1e-9 * a * r * r) {
                assertTrue(Double.isNaN(t), "the line misses: " + where);
                continue;
            }
            if (disc <= 1e-9 * a * r * r) {
                continue; // tangent within rounding: either answer is right
            }
            double t0 = (-b - Math.sqrt(disc)) / (2 * a), t1 = (-b + Math.sqrt(disc)) / (2 * a);
            double tol = 1e-9 * (1 + Math.abs(t0) + Math.abs(t1));
            double expected = t0 > tMin + tol && t0 < tMax - tol ? t0 : t1 > tMin + tol && t1 < tMax - tol ? t1 : Double.NaN;
            if (Double.isNaN(expected)) {
                boolean nearEdge = Math.abs(t0 - tMin) <= tol || Math.abs(t1 - tMin) <= tol
                        || Math.abs(t0 - tMax) <= tol || Math.abs(t1 - tMax) <= tol;
                assertTrue(nearEdge || Double.isNaN(t), "no root inside (" + tMin + ", " + tMax + "): " + where + " got " + t);
                continue;
            }
            assertEquals(expected, t, tol, where);
            assertTrue(t > tMin && t < tMax, where);
            double px = o.x() + t * d.x() - centre.x(), py = o.y() + t * d.y() - centre.y(), pz = o.z() + t * d.z() - centre.z();
            assertEquals(r, Math.sqrt(px * px + py * py + pz * pz), 1e-9 * (r + Math.abs(t) * Math.sqrt(a)), where);
            hits++;
            if (cc < 0 && tMin == 0) {
                fromInside++;
                assertEquals(t1, t, tol, "from inside, the exit: " + where);
            }
        }
        assertTrue(hits > 1500 && fromInside > 200, hits + " hits, " + fromInside + " from inside");
    }

    @Test
    void aSpherePointHasTheOutwardUnitNormalATangentFrameAndUvThatMapBack() {
        Random rnd = new Random(92);
        TraceContext c = new TraceContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        for (int trial = 0; trial < 1000; trial++) {
            Vec3 centre = random(rnd, 5);
            double r = 0.5 + 3 * rnd.nextDouble();
            AnalyticShapes s = new AnalyticShapes(List.of(), List.of(new Sphere(centre, r, 0)));
            // aim at a random point of the sphere from outside
            double theta = Math.acos(2 * rnd.nextDouble() - 1), phi = 2 * Math.PI * rnd.nextDouble();
            Vec3 n = new Vec3(Math.sin(theta) * Math.cos(phi), Math.sin(theta) * Math.sin(phi), Math.cos(theta));
            Vec3 target = centre.add(n.scale(r)), o = target.add(n.scale(3 * r));
            c.setRay(o.x(), o.y(), o.z(), target.x() - o.x(), target.y() - o.y(), target.z() - o.z());
            hit.t = s.sphereT(0, c, 0, Double.POSITIVE_INFINITY);
            assertEquals(1, hit.t, 1e-9, "trial " + trial);
            s.spherePoint(0, hit, c, sp);
            assertEquals(target.x(), sp.px, 1e-9 * r);
            assertEquals(target.y(), sp.py, 1e-9 * r);
            assertEquals(target.z(), sp.pz, 1e-9 * r);
            assertEquals(1, Math.sqrt(dot(sp.nx, sp.ny, sp.nz, sp.nx, sp.ny, sp.nz)), 1e-12);
            assertEquals(1, dot(sp.nx, sp.ny, sp.nz, n.x(), n.y(), n.z()), 1e-9, "outward normal");
            assertEquals(0, dot(sp.dpdux, sp.dpduy, sp.dpduz, sp.nx, sp.ny, sp.nz), 1e-9 * r, "dp/du is tangent");
            assertEquals(0, dot(sp.dpdvx, sp.dpdvy, sp.dpdvz, sp.nx, sp.ny, sp.nz), 1e-9 * r, "dp/dv is tangent");
            double rho = Math.hypot(n.x(), n.y());
            assertEquals(2 * Math.PI * r * rho, Math.sqrt(dot(sp.dpdux, sp.dpduy, sp.dpduz, sp.dpdux, sp.dpduy, sp.dpduz)),
                    1e-9 * r, "|dp/du| = 2π r sin θ");
            assertEquals(Math.PI * r, Math.sqrt(dot(sp.dpdvx, sp.dpdvy, sp.dpdvz, sp.dpdvx, sp.dpdvy, sp.dpdvz)), 1e-9 * r,
                    "|dp/dv| = π r");
            s.sphereUv(0, sp.px, sp.py, sp.pz, hit);
            assertTrue(hit.u >= 0 && hit.u < 1 && hit.v >= 0 && hit.v <= 1, hit.u + ", " + hit.v);
            double t2 = Math.PI * hit.v, p2 = 2 * Math.PI * hit.u;
            assertEquals(n.x(), Math.sin(t2) * Math.cos(p2), 1e-9);
            assertEquals(n.y(), Math.sin(t2) * Math.sin(p2), 1e-9);
            assertEquals(n.z(), Math.cos(t2), 1e-9);
        }
    }

    @Test
    void planeRootsLieOnThePlaneParallelRaysMissAndTheFrameAndUvAreThePlanes() {
        Random rnd = new Random(93);
        TraceContext c = new TraceContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        for (int trial = 0; trial < 3000; trial++) {
            Vec3 point = random(rnd, 10);
            // normals along each axis too (the in-plane axes are picked from the smallest component)
            Vec3 normal = trial % 4 == 0 ? new Vec3(0, 0, 1) : trial % 4 == 1 ? new Vec3(0, -2, 0)
                    : trial % 4 == 2 ? new Vec3(3, 0, 0) : random(rnd, 1);
            if (normal.length() < 1e-3) {
                continue;
            }
            double scale = 0.25 + 4 * rnd.nextDouble();
            Plane plane = new Plane(point, normal, 0, scale);
            Vec3 n = plane.normal();
            AnalyticShapes s = new AnalyticShapes(List.of(plane), List.of());
            Vec3 o = random(rnd, 12), d = random(rnd, 3);
            c.setRay(o.x(), o.y(), o.z(), d.x(), d.y(), d.z());
            double t = s.planeT(0, c);
            double px = o.x() + t * d.x(), py = o.y() + t * d.y(), pz = o.z() + t * d.z();
            String where = "trial " + trial;
            assertEquals(0, dot(px - point.x(), py - point.y(), pz - point.z(), n.x(), n.y(), n.z()),
                    1e-9 * (1 + Math.abs(t) * d.length() + point.length()), where);
            hit.t = t;
            s.planePoint(0, hit, c, sp);
            assertEquals(px, sp.px, 0);
            assertEquals(1, dot(sp.nx, sp.ny, sp.nz, n.x(), n.y(), n.z()), 1e-12, "the plane's normal");
            double[] a = {sp.dpdux, sp.dpduy, sp.dpduz}, b = {sp.dpdvx, sp.dpdvy, sp.dpdvz};
            assertEquals(1, dot(a[0], a[1], a[2], a[0], a[1], a[2]), 1e-12, "unit dp/du");
            assertEquals(1, dot(b[0], b[1], b[2], b[0], b[1], b[2]), 1e-12, "unit dp/dv");
            assertEquals(0, dot(a[0], a[1], a[2], b[0], b[1], b[2]), 1e-12, "dp/du ⟂ dp/dv");
            assertEquals(0, dot(a[0], a[1], a[2], n.x(), n.y(), n.z()), 1e-12, "dp/du in the plane");
            assertEquals(0, dot(b[0], b[1], b[2], n.x(), n.y(), n.z()), 1e-12, "dp/dv in the plane");
            // right-handed: dp/du × dp/dv = n
            assertEquals(n.z(), a[0] * b[1] - a[1] * b[0], 1e-12, "right-handed frame");
            s.planeUv(0, px, py, pz, hit);
            double mx = point.x() + scale * (hit.u * a[0] + hit.v * b[0]);
            double my = point.y() + scale * (hit.u * a[1] + hit.v * b[1]);
            double mz = point.z() + scale * (hit.u * a[2] + hit.v * b[2]);
            double tol = 1e-9 * (1 + Math.abs(t) * d.length() + point.length());
            assertEquals(px, mx, tol, "uv map back, " + where);
            assertEquals(py, my, tol, where);
            assertEquals(pz, mz, tol, where);
            // a ray parallel to the plane (direction along dp/du) never meets it
            c.setRay(o.x(), o.y(), o.z(), a[0], a[1], a[2]);
            double parallel = s.planeT(0, c);
            assertTrue(Double.isNaN(parallel) || Math.abs(parallel) > 1e9, "parallel: " + parallel + ", " + where);
        }
    }
    /**
     * Exact cases with round numbers: a root exactly at tMin or tMax does not count (a ray leaving
     * the sphere's surface finds the far side, not its own origin); a tangent ray touches at its
     * double root; at the poles the frame is the φ = 0 limit; on the seam u is 0, never 1.
     */
    @Test
    void rootsAtTheIntervalsEndsTangentsPolesAndTheSeam() {
        AnalyticShapes s = new AnalyticShapes(List.of(), List.of(new Sphere(new Vec3(0, 0, 0), 2, 0)));
        TraceContext c = new TraceContext();
        c.setRay(2, 0, 0, -1, 0, 0); // from the surface inward: roots 0 and 4
        assertEquals(4, s.sphereT(0, c, 0, 10), 0);
        assertEquals(0, s.sphereT(0, c, -1, 10), 0);
        assertTrue(Double.isNaN(s.sphereT(0, c, -1, 0)), "root 0 at tMax");
        assertTrue(Double.isNaN(s.sphereT(0, c, 0, 4)), "roots at tMin and at tMax");
        assertTrue(Double.isNaN(s.sphereT(0, c, 4, 10)), "root 4 at tMin");
        assertEquals(4, s.sphereT(0, c, 0, Math.nextUp(4.0)), 0);
        c.setRay(-5, 2, 0, 1, 0, 0); // tangent at (0, 2, 0)
        assertEquals(5, s.sphereT(0, c, 0, 10), 0);
        c.setRay(-5, Math.nextUp(2.0), 0, 1, 0, 0);
        assertTrue(Double.isNaN(s.sphereT(0, c, 0, 10)), "just past the tangent");

        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        for (double z : new double[] {1, -1}) {
            c.setRay(0, 0, 5 * z, 0, 0, -z);
            hit.t = s.sphereT(0, c, 0, 10);
            assertEquals(3, hit.t, 0);
            s.spherePoint(0, hit, c, sp);
            assertEquals(z, sp.nz, 0, "pole normal");
            assertEquals(0, Math.hypot(sp.dpdux, sp.dpduy), 0, "dp/du vanishes at the pole");
            assertEquals(z * 2 * Math.PI, sp.dpdvx, 1e-12, "dp/dv at the pole: the φ = 0 meridian");
            assertEquals(0, sp.dpdvy, 0);
            assertEquals(0, sp.dpdvz, 1e-12);
            s.sphereUv(0, sp.px, sp.py, sp.pz, hit);
            assertEquals(z > 0 ? 0 : 1, hit.v, 0);
        }
        c.setRay(5, 0, 0, -1, 0, 0);
        hit.t = s.sphereT(0, c, 0, 10);
        s.spherePoint(0, hit, c, sp);
        s.sphereUv(0, sp.px, sp.py, sp.pz, hit);
        assertEquals(0, hit.u, 0, "on the seam φ = 0: u = 0");
        assertEquals(0.5, hit.v, 0);
        assertEquals(4 * Math.PI, sp.dpduy, 1e-12, "dp/du = 2π r along +y at φ = 0");
        assertEquals(-2 * Math.PI, sp.dpdvz, 1e-12, "dp/dv = π r along -z on the equator");
    }

    /** Planes: a hit exactly at the plane's own point, a ray in the plane, and an exact parallel ray. */
    @Test
    void planeRootsWithRoundNumbers() {
        AnalyticShapes s = new AnalyticShapes(List.of(new Plane(new Vec3(1, 2, 3), new Vec3(0, 2, 0), 0, 0.5)), List.of());
        TraceContext c = new TraceContext();
        c.setRay(1, 7, 3, 0, -2, 0);
        assertEquals(2.5, s.planeT(0, c), 0);
        c.setRay(4, 7, -1, 1, -1, 2); // meets y = 2 at t = 5, point (9, 2, 9)
        assertEquals(5, s.planeT(0, c), 0);
        Hit hit = new Hit();
        s.planeUv(0, 9, 2, 9, hit);
        assertEquals(Math.hypot(8, 6) * 2, Math.hypot(hit.u, hit.v), 1e-12, "distance / uvScale");
        c.setRay(0, 5, 0, 1, 0, 1);
        assertTrue(Double.isNaN(s.planeT(0, c)), "parallel");
    }
    /**
     * The texture axes of axis-aligned planes (floors and walls) are fixed: dp/du and dp/dv of
     * each of the six axis normals, right-handed, from the smallest normal component.
     */
    @Test
    void axisAlignedPlanesHaveFixedTextureAxes() {
        double[][] expected = { // normal, dp/du, dp/dv
            {1, 0, 0, 0, 0, 1, 0, -1, 0}, {-1, 0, 0, 0, 0, -1, 0, -1, 0},
            {0, 1, 0, 0, 0, 1, 1, 0, 0}, {0, -1, 0, 0, 0, -1, 1, 0, 0},
            {0, 0, 1, 0, -1, 0, 1, 0, 0}, {0, 0, -1, 0, 1, 0, 1, 0, 0}};
        TraceContext c = new TraceContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        for (double[] e : expected) {
            Plane plane = new Plane(new Vec3(1, 2, 3), new Vec3(e[0], e[1], e[2]).scale(2), 0, 1);
            AnalyticShapes s = new AnalyticShapes(List.of(plane), List.of());
            c.setRay(5 * e[0] + 0.5, 5 * e[1] + 0.5, 5 * e[2] + 0.5, -e[0], -e[1], -e[2]);
            hit.t = s.planeT(0, c);
            s.planePoint(0, hit, c, sp);
            double[] actual = {sp.nx, sp.ny, sp.nz, sp.dpdux, sp.dpduy, sp.dpduz, sp.dpdvx, sp.dpdvy, sp.dpdvz};
            for (int k = 0; k < 9; k++) {
                assertEquals(e[k], actual[k], 0, "normal (" + e[0] + ", " + e[1] + ", " + e[2] + "), value " + k);
            }
        }
    }
}
