package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.DERIVED;
import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.geometry.Tessellator;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** The tessellated (triangle mesh) mode: convergence to the exact path, BVH against brute force, occlusion. */
class TessellatedModeTest {

    /** Worst differences between tessellated and exact hits over one ray set. */
    record Errors(double t, double uv, double normal, int compared) {}

    static Scene heightFields(Random rnd) {
        List<BezierPatch> list = new ArrayList<>();
        for (int k = 0; k < 4; k++) {
            BezierPatch p = RandomPatches.heightField(rnd, 3 + k % 2, 3, 4, 0.4);
            double[] net = p.copyNet();
            for (int i = 0; i < net.length; i += 3) {
                net[i] += 5 * k;
            }
            list.add(new BezierPatch(p.degreeU(), p.degreeV(), net));
        }
        return new Scene(list);
    }

    /**
     * Tessellated against exact hits for 400 steep rays from above toward the inner part of a
     * random patch (at least 0.5 from its border, where the chord error of any K ≥ 4 is far
     * smaller): every ray must hit in both modes, on the same patch; the worst differences are
     * returned for the caller to bound.
     */
    static Errors compare(Scene scene, int k, long seed) {
        SceneIntersector exact = SceneIntersector.build(scene, IntersectOptions.defaults());
        SceneIntersector tess = SceneIntersector.build(scene, IntersectOptions.defaults().withTessellate(k));
        TraceContext ce = exact.newContext(), ct = tess.newContext();
        Hit he = new Hit(), ht = new Hit();
        SurfacePoint se = new SurfacePoint(), st = new SurfacePoint();
        Random rnd = new Random(seed);
        double et = 0, euv = 0, en = 0;
        int compared = 0;
        for (int r = 0; r < 400; r++) {
            int patch = rnd.nextInt(4);
            double tx = 5 * patch + 3 * (rnd.nextDouble() - 0.5), ty = 3 * (rnd.nextDouble() - 0.5);
            double ox = tx + 2 * (rnd.nextDouble() - 0.5), oy = ty + 2 * (rnd.nextDouble() - 0.5), oz = 8;
            double dx = tx - ox, dy = ty - oy, dz = -oz;
            String where = "K=" + k + " ray " + r + " o=(" + ox + "," + oy + "," + oz + ") d=(" + dx + "," + dy + "," + dz + ")";
            assertTrue(exact.closestHit(ce, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, he), "exact missed: " + where);
            assertTrue(tess.closestHit(ct, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, ht), "tessellated missed: " + where);
            assertEquals(he.index, ht.index, "patch: " + where);
            exact.surfacePoint(ce, he, se);
            tess.surfacePoint(ct, ht, st);
            compared++;
            et = Math.max(et, Math.abs(he.t - ht.t));
            euv = Math.max(euv, Math.max(Math.abs(he.u - ht.u), Math.abs(he.v - ht.v)));
            en = Math.max(en, Math.sqrt(sq(se.nx - st.nx) + sq(se.ny - st.ny) + sq(se.nz - st.nz)));
        }
        return new Errors(et, euv, en, compared);
    }

    private static double sq(double x) { return x * x; }

    @Test
    void tessellatedHitsConvergeToTheExactHitsAsKGrows() {
        Scene scene = heightFields(new Random(21));
        Errors coarse = compare(scene, 4, 9), fine = compare(scene, 64, 9);
        assertEquals(400, coarse.compared(), "every ray compared");
        assertEquals(400, fine.compared(), "every ray compared");
        // Chord error falls as 1/K²: 16x finer cells should be ~256x closer; ask for 50x
        assertTrue(fine.t() < coarse.t() / 50, "t error K=4 " + coarse.t() + ", K=64 " + fine.t());
        assertTrue(fine.uv() < coarse.uv() / 10, "uv error K=4 " + coarse.uv() + ", K=64 " + fine.uv());
        assertTrue(fine.normal() < coarse.normal() / 10, "normal error K=4 " + coarse.normal() + ", K=64 " + fine.normal());
        assertTrue(fine.t() < 1e-3, "t error at K=64: " + fine.t());
        assertTrue(fine.normal() < 1e-2, "normal error at K=64: " + fine.normal());
    }

    @Test
    void closestHitEqualsBruteForceOverTheTriangles() {
        Random rnd = new Random(17);
        Scene scene = SceneIntersectorTest.wildScene(rnd, 25, 4);
        int k = 6;
        Mesh mesh = Tessellator.tessellate(scene.patches(), k);
        for (boolean bvh : new boolean[] {true, false}) {
            SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withTessellate(k).withBvh(bvh));
            assertEquals(mesh.triangleCount(), si.triangleCount());
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            SurfacePoint sp = new SurfacePoint();
            int hits = 0;
            for (int r = 0; r < 2000; r++) {
                double[] ray = SceneIntersectorTest.randomRay(rnd);
                double[] ref = bruteForce(mesh, ray);
                boolean found = si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0,
                        Double.POSITIVE_INFINITY, hit);
                String where = "bvh " + bvh + " ray " + r + " " + Arrays.toString(ray);
                assertEquals(ref != null, found, "hit/miss differs from brute force: " + where);
                if (!found) {
                    continue;
                }
                hits++;
                assertEquals(ref[0], hit.t, DERIVED, "t: " + where);
                assertEquals(mesh.patchOfTriangle((int) ref[1]), hit.index, "patch: " + where);
                si.surfacePoint(ctx, hit, sp);
                // The point lies on the ray and on the triangle; the normal is unit length
                assertEquals(ray[0] + hit.t * ray[3], sp.px, DERIVED, "x on the ray: " + where);
                assertEquals(ray[1] + hit.t * ray[4], sp.py, DERIVED, "y on the ray: " + where);
                assertEquals(ray[2] + hit.t * ray[5], sp.pz, DERIVED, "z on the ray: " + where);
                assertEquals(1, Math.sqrt(sp.nx * sp.nx + sp.ny * sp.ny + sp.nz * sp.nz), ROUNDING, "unit normal: " + where);
                assertTrue(hit.u >= -ROUNDING && hit.u <= 1 + ROUNDING && hit.v >= -ROUNDING && hit.v <= 1 + ROUNDING,
                        "uv inside the patch: " + where);
            }
            assertTrue(hits > 300, "rays should hit often, hit " + hits);
        }
    }

    /** Nearest Möller–Trumbore hit over every triangle: {t, triangle} or null (an independent test path). */
    static double[] bruteForce(Mesh mesh, double[] ray) {
        double[] best = null;
        for (int t = 0; t < mesh.triangleCount(); t++) {
            int a = mesh.triangleVertex(t, 0), b = mesh.triangleVertex(t, 1), c = mesh.triangleVertex(t, 2);
            double[] p0 = {mesh.position(a, 0), mesh.position(a, 1), mesh.position(a, 2)};
            double[] e1 = {mesh.position(b, 0) - p0[0], mesh.position(b, 1) - p0[1], mesh.position(b, 2) - p0[2]};
            double[] e2 = {mesh.position(c, 0) - p0[0], mesh.position(c, 1) - p0[1], mesh.position(c, 2) - p0[2]};
            double[] d = {ray[3], ray[4], ray[5]};
            double[] pv = cross(d, e2);
            double det = dot(e1, pv);
            if (Math.abs(det) < 1e-300) {
                continue;
            }
            double[] tv = {ray[0] - p0[0], ray[1] - p0[1], ray[2] - p0[2]};
            double u = dot(tv, pv) / det;
            double[] qv = cross(tv, e1);
            double v = dot(d, qv) / det;
            double th = dot(e2, qv) / det;
            if (u >= 0 && v >= 0 && u + v <= 1 && th > 0 && (best == null || th < best[0])) {
                best = new double[] {th, t};
            }
        }
        return best;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    @Test
    void occludedAgreesWithClosestHitInTessellatedMode() {
        Random rnd = new Random(23);
        Scene scene = SceneIntersectorTest.wildScene(rnd, 20, 5);
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withTessellate(8));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        for (int r = 0; r < 2000; r++) {
            double[] ray = SceneIntersectorTest.randomRay(rnd);
            double tMax = rnd.nextDouble() * 1.5;
            boolean closest = si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax, hit);
            boolean occluded = si.occluded(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax);
            assertEquals(closest, occluded, "ray " + Arrays.toString(ray) + " tMax " + tMax);
        }
    }

    @Test
    void raysThroughTheTeapotTessellationDoNotFallThroughSharedVertices() {
        // Rays aimed exactly at interior grid vertices of each patch's tessellation (shared by six
        // triangles); border vertices are left out: the teapot has open borders (spout, handle)
        Scene teapot = Models.teapot();
        int k = 8;
        Mesh mesh = Tessellator.tessellate(teapot.patches(), k);
        SceneIntersector si = SceneIntersector.build(teapot, IntersectOptions.defaults().withTessellate(k));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(5);
        int misses = 0, tried = 0;
        for (int vert = 0; vert < mesh.vertexCount(); vert += 3) {
            int a = vert % ((k + 1) * (k + 1)) % (k + 1), b = vert % ((k + 1) * (k + 1)) / (k + 1);
            if (a == 0 || a == k || b == 0 || b == k) {
                continue;
            }
            double px = mesh.position(vert, 0), py = mesh.position(vert, 1), pz = mesh.position(vert, 2);
            double nx = mesh.normal(vert, 0), ny = mesh.normal(vert, 1), nz = mesh.normal(vert, 2);
            // From outside along the normal, slightly tilted
            double ox = px + 300 * nx + rnd.nextDouble(), oy = py + 300 * ny + rnd.nextDouble(), oz = pz + 300 * nz;
            tried++;
            if (!si.closestHit(ctx, ox, oy, oz, px - ox, py - oy, pz - oz, 0, 1 + 1e-9, hit)) {
                misses++;
            }
        }
        assertEquals(0, misses, "rays at mesh vertices that fell through, of " + tried);
    }

    @Test
    void optionsRejectANegativeTessellation() {
        UserMessages.of(IllegalArgumentException.class, () -> IntersectOptions.defaults().withTessellate(-1));
        assertFalse(IntersectOptions.defaults().tessellated());
        assertTrue(IntersectOptions.defaults().withTessellate(3).tessellated());
    }
}
