package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.accel.BvhOptions;
import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.junit.jupiter.api.Test;

/**
 * Patches, triangle meshes and spheres in one BVH ({@link MixedLeaves}): every ray gets the nearest
 * hit of the scene's parts, each traced alone by a linear loop over its primitives (the BVH off),
 * and the same any-hit answer; the BVH on and off agree; an edit keeps the mesh and sphere leaves.
 */
class MixedLeavesTest {

    private static final long SEED = 20261204L;
    private static final int RAYS = 3000;

    @Test
    void aSceneOfPatchesOnlyKeepsItsPatchLeavesAndAMixedSceneGetsTheComposite() {
        Scene mixed = MixedScenes.teapotOnFloor(4, false);
        Scene patches = Scene.builder().patches(mixed.patches()).build();
        assertInstanceOf(ClippingLeaves.class, SceneIntersector.build(patches, IntersectOptions.defaults()).leaves);
        SceneIntersector si = SceneIntersector.build(mixed, IntersectOptions.defaults());
        assertInstanceOf(MixedLeaves.class, si.leaves);
        assertTrue(si.spheresInLeaves);
        assertEquals(0, si.shapes.sphereCount, "the spheres are leaves, not tested apart");
        int triangles = 2 * 4 * 4 + 6;
        assertEquals(triangles, si.triangleCount());
        assertEquals(si.subPatchCount() + triangles + 2, si.primitiveCount());
        Scene meshOnly = Scene.builder().addMesh(MixedScenes.pyramid(0, 0, 0, 1), 0).build();
        assertInstanceOf(MeshLeaves.class, SceneIntersector.build(meshOnly, IntersectOptions.defaults()).leaves);
    }

    @Test
    void everyRayMeetsTheNearestOfThePartsClipping() {
        nearestOfParts(MixedScenes.teapotOnFloor(6, true), IntersectOptions.defaults(), "clipping");
    }

    @Test
    void everyRayMeetsTheNearestOfThePartsNewtonAndTessellated() {
        Scene scene = MixedScenes.teapotOnFloor(3, false);
        nearestOfParts(scene, IntersectOptions.defaults().withMethod(Method.NEWTON), "newton");
        nearestOfParts(scene, IntersectOptions.defaults().withTessellate(5), "tessellated 5");
    }

    /**
     * Random rays from around the scene into its box: the mixed BVH's hit is the nearest of the
     * parts' hits (patches, meshes and spheres each in a scene of their own, without a BVH), of the
     * same kind and index unless two parts are within 1e-9 of each other; occlusion agrees; the
     * BVH off gives the same answers.
     */
    private static void nearestOfParts(Scene scene, IntersectOptions options, String name) {
        SceneIntersector mixed = SceneIntersector.build(scene, options);
        SceneIntersector flat = SceneIntersector.build(scene, options.withBvh(false));
        List<SceneIntersector> parts = MixedScenes.parts(scene).stream()
                .map(s -> SceneIntersector.build(s, options.withBvh(false))).toList();
        TraceContext ctx = mixed.newContext(), flatCtx = flat.newContext(), partCtx = parts.get(0).newContext();
        Hit hit = new Hit(), flatHit = new Hit(), partHit = new Hit();
        Aabb box = scene.bounds();
        double size = box.diagonal();
        Random random = new Random(SEED);
        int[] kinds = new int[4];
        for (int r = 0; r < RAYS; r++) {
            double[] ray = ray(random, box, size);
            double tMax = random.nextInt(4) == 0 ? 0.5 + random.nextDouble() : Double.POSITIVE_INFINITY;
            String where = name + ", ray " + r + " " + java.util.Arrays.toString(ray) + " tMax " + tMax + " (seed " + SEED
                    + ")";
            boolean found = mixed.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax, hit);
            boolean flatFound = flat.closestHit(flatCtx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax, flatHit);
            double best = Double.POSITIVE_INFINITY, second = Double.POSITIVE_INFINITY;
            int bestKind = -1, bestIndex = -1;
            boolean occludedByPart = false;
            for (SceneIntersector part : parts) {
                if (part.closestHit(partCtx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax, partHit)) {
                    if (partHit.t < best) {
                        second = best;
                        best = partHit.t;
                        bestKind = partHit.kind;
                        bestIndex = partHit.index;
                    } else {
                        second = Math.min(second, partHit.t);
                    }
                }
                occludedByPart |= part.occluded(partCtx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax);
            }
            assertEquals(best < Double.POSITIVE_INFINITY, found, where + ": found");
            assertEquals(found, flatFound, where + ": the BVH off");
            assertEquals(occludedByPart, mixed.occluded(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, tMax),
                    where + ": occluded");
            if (!found) {
                continue;
            }
            assertEquals(best, hit.t, 1e-9 * Math.max(1, best), where + ": t");
            assertEquals(hit.t, flatHit.t, 1e-9 * Math.max(1, best), where + ": t, the BVH off");
            if (second - best > 1e-9 * Math.max(1, best)) {
                assertEquals(bestKind, hit.kind, where + ": kind");
                if (hit.kind != Hit.PATCH) { // neighbouring patches share their borders
                    assertEquals(bestIndex, hit.index, where + ": index");
                }
                assertEquals(hit.kind, flatHit.kind, where + ": kind, the BVH off");
            }
            kinds[hit.kind]++;
            SurfacePoint sp = new SurfacePoint();
            mixed.surfacePoint(ctx, hit, sp);
            double px = ray[0] + hit.t * ray[3], py = ray[1] + hit.t * ray[4], pz = ray[2] + hit.t * ray[5];
            assertEquals(0, Math.hypot(Math.hypot(sp.px - px, sp.py - py), sp.pz - pz), 1e-6 * size,
                    where + ": the surface point is on the ray");
            assertEquals(1, Math.sqrt(sp.nx * sp.nx + sp.ny * sp.ny + sp.nz * sp.nz), 1e-9, where + ": unit normal");
        }
        assertTrue(kinds[Hit.PATCH] > RAYS / 50 && kinds[Hit.TRIANGLE] > RAYS / 50 && kinds[Hit.SPHERE] > RAYS / 200,
                name + ": hits by kind " + java.util.Arrays.toString(kinds));
    }

    /** A ray from a random point around the box toward a random point in it; direction not unit. */
    private static double[] ray(Random random, Aabb box, double size) {
        Vec3 c = box.center();
        double theta = Math.acos(2 * random.nextDouble() - 1), phi = 2 * Math.PI * random.nextDouble();
        double d = 1.5 * size;
        double ox = c.x() + d * Math.sin(theta) * Math.cos(phi), oy = c.y() + d * Math.sin(theta) * Math.sin(phi),
                oz = c.z() + d * Math.cos(theta);
        double tx = box.minX() + random.nextDouble() * (box.maxX() - box.minX());
        double ty = box.minY() + random.nextDouble() * (box.maxY() - box.minY());
        double tz = box.minZ() + random.nextDouble() * (box.maxZ() - box.minZ());
        return new double[] {ox, oy, oz, tx - ox, ty - oy, tz - oz};
    }

    @Test
    void aBigMeshWithoutPatchesBuildsItsOneTreeAndIsHit() {
        // 2·190² = 72,200 triangles: past BvhOptions.GROUPED_PRIMS, where a scene of patches is built
        // in two levels; a mesh alone has no patches to group by (its render failed before)
        Scene scene = Scene.builder().addMesh(MixedScenes.grid(190, 0, 19, 0, 19, 0), 0).build();
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        assertTrue(si.leaves.count() >= BvhOptions.GROUPED_PRIMS);
        Hit hit = new Hit();
        assertTrue(si.closestHit(si.newContext(), 7.05, 11.02, 2, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.TRIANGLE, hit.kind);
        assertEquals(2, hit.t, 1e-12);
        Scene withSphere = scene.toBuilder().addSphere(new Sphere(new Vec3(30, 30, 0), 1)).build();
        SceneIntersector both = SceneIntersector.build(withSphere, IntersectOptions.defaults());
        assertTrue(both.closestHit(both.newContext(), 30, 30, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.SPHERE, hit.kind);
    }

    @Test
    void aTriangleHitReportsTheMeshItsBarycentricsUvsAndNormal() {
        Scene scene = Scene.builder().addMesh(MixedScenes.grid(2, 0, 2, 0, 2, 0), 0)
                .addMesh(MixedScenes.pyramid(5, 5, 0, 1), 0).addSphere(new Sphere(new Vec3(-5, -5, 0), 1)).build();
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        assertTrue(si.closestHit(ctx, 0.5, 1.5, 3, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.TRIANGLE, hit.kind);
        assertEquals(0, hit.index);
        assertEquals(3, hit.t, 1e-12);
        assertEquals(0.25, hit.u, 1e-12, "u from the mesh's uvs");
        assertEquals(0.75, hit.v, 1e-12, "v from the mesh's uvs");
        si.surfacePoint(ctx, hit, sp);
        assertEquals(1, sp.nz, 1e-12);
        assertEquals(0.5, sp.px, 1e-12);
        // the pyramid has no normals: the face normal, pointing out of its side x = 5.5 .. 6 facing -y
        assertTrue(si.closestHit(ctx, 5.5, -3, 0.25, 0, 1, 0, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.TRIANGLE, hit.kind);
        assertEquals(1, hit.index);
        si.surfacePoint(ctx, hit, sp);
        assertTrue(sp.ny < -0.5, "face normal " + sp.nx + " " + sp.ny + " " + sp.nz);
        assertEquals(hit.b1, hit.u, 0, "without uvs (u,v) are the barycentrics");
        // the sphere, a leaf of the same BVH
        assertTrue(si.closestHit(ctx, -5, -5, 3, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit));
        assertEquals(Hit.SPHERE, hit.kind);
        assertEquals(2, hit.t, 1e-12);
        assertEquals(0, hit.v, 1e-9, "the north pole: v = colatitude / pi");
    }

    @Test
    void anEditReSplitsThePatchesAndKeepsTheMeshAndSphereLeaves() {
        Scene scene = MixedScenes.teapotOnFloor(4, false);
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
        BezierPatch p = scene.patches().get(5);
        double[] net = p.copyNet();
        for (int k = 2; k < net.length; k += 3) {
            net[k] += 0.01;
        }
        Scene edited = scene.withPatch(5, p.withNet(net));
        SceneIntersector after = si.withPatches(edited, new int[] {5});
        MixedLeaves before = (MixedLeaves) si.leaves, now = (MixedLeaves) after.leaves;
        assertSame(partOf(before, MeshLeaves.class), partOf(now, MeshLeaves.class), "mesh leaves kept");
        assertSame(partOf(before, SphereLeaves.class), partOf(now, SphereLeaves.class), "sphere leaves kept");
        assertEquals(2, edited.meshes().size(), "the meshes are in the edited scene");
        SceneIntersector fresh = SceneIntersector.build(edited, IntersectOptions.defaults());
        TraceContext a = after.newContext(), b = fresh.newContext();
        Hit ha = new Hit(), hb = new Hit();
        Aabb box = edited.bounds();
        Random random = new Random(SEED + 1);
        for (int r = 0; r < 1000; r++) {
            double[] ray = ray(random, box, box.diagonal());
            String where = "ray " + r + " " + java.util.Arrays.toString(ray);
            boolean fa = after.closestHit(a, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, ha);
            boolean fb = fresh.closestHit(b, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, hb);
            assertEquals(fb, fa, where);
            if (fa) {
                assertEquals(hb.t, ha.t, 1e-9 * Math.max(1, hb.t), where);
                assertEquals(hb.kind, ha.kind, where);
            }
        }
    }

    private static Leaves partOf(MixedLeaves leaves, Class<?> type) {
        try {
            var f = MixedLeaves.class.getDeclaredField("parts");
            f.setAccessible(true);
            for (Leaves l : (Leaves[]) f.get(leaves)) {
                if (type.isInstance(l)) {
                    return l;
                }
            }
        } catch (ReflectiveOperationException e) {
            throw new AssertionError(e);
        }
        throw new AssertionError("no " + type.getSimpleName());
    }

    @Test
    void aMeshWithoutNormalsOrUvsIsAccepted() {
        Mesh m = MixedScenes.pyramid(0, 0, 0, 1);
        assertTrue(!m.hasNormals() && !m.hasUvs());
        assertEquals(6, m.triangleCount());
    }
}
