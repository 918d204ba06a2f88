package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** The leaf seam: the kind of leaves is chosen once per scene, and a context serves any scene. */
class LeavesTest {

    private static final Scene TEAPOT = Models.teapot();

    @Test
    void eachMethodGetsItsOwnPatchLeaves() {
        IntersectOptions o = IntersectOptions.defaults();
        assertInstanceOf(ClippingLeaves.class, SceneIntersector.build(TEAPOT, o).leaves);
        assertInstanceOf(NewtonLeaves.class, SceneIntersector.build(TEAPOT, o.withMethod(Method.NEWTON)).leaves);
        assertInstanceOf(SubdivisionLeaves.class,
                SceneIntersector.build(TEAPOT, o.withMethod(Method.SUBDIVISION)).leaves);
    }

    @Test
    void tessellatedModeGetsTriangleLeavesWhateverTheMethod() {
        for (Method m : Method.values()) {
            SceneIntersector si = SceneIntersector.build(TEAPOT,
                    IntersectOptions.defaults().withMethod(m).withTessellate(4));
            assertInstanceOf(TriangleLeaves.class, si.leaves, m.label());
            assertEquals(32 * 4 * 4 * 2, si.triangleCount(), m.label());
            assertEquals(si.triangleCount(), si.primitiveCount(), m.label());
            assertEquals(32, si.subPatchCount(), "whole patches, " + m.label());
        }
    }

    @Test
    void aSceneWithoutPatchesHasItsSpheresAsLeavesInEitherMode() {
        Scene sphereOnly = new Scene(List.of(), List.of(), List.of(new Sphere(new Vec3(0, 0, 0), 1)));
        for (int k : new int[] {0, 4}) {
            SceneIntersector si = SceneIntersector.build(sphereOnly, IntersectOptions.defaults().withTessellate(k));
            assertInstanceOf(SphereLeaves.class, si.leaves, "tessellate " + k);
            assertEquals(1, si.primitiveCount(), "tessellate " + k);
            assertEquals(0, si.triangleCount(), "tessellate " + k);
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            assertTrue(si.closestHit(ctx, 0, 0, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit), "tessellate " + k);
            assertEquals(Hit.SPHERE, hit.kind);
            assertEquals(4, hit.t, ROUNDING);
            assertFalse(si.closestHit(ctx, 3, 0, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit), "tessellate " + k);
        }
    }

    @Test
    void anEditKeepsTheKindOfLeaves() {
        for (int k : new int[] {0, 4}) {
            for (Method m : Method.values()) {
                IntersectOptions o = IntersectOptions.defaults().withMethod(m).withTessellate(k);
                SceneIntersector si = SceneIntersector.build(TEAPOT, o);
                SceneIntersector edited = si.withPatch(3, TEAPOT.patches().get(3).withPoint(1, 1, 0, 0, 100));
                assertSame(si.leaves.getClass(), edited.leaves.getClass(), m.label() + ", tessellate " + k);
            }
        }
    }

    /**
     * One context alternating between an exact and a tessellated scene (as a render thread does
     * across edits and mode switches) gives bit for bit the answers of a fresh context per scene:
     * the context holds no state that belongs to a scene.
     */
    @Test
    void oneContextServesScenesOfEveryKind() {
        SceneIntersector exact = SceneIntersector.build(TEAPOT, IntersectOptions.defaults());
        SceneIntersector tess = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withTessellate(6));
        SceneIntersector newton = SceneIntersector.build(TEAPOT, IntersectOptions.defaults().withMethod(Method.NEWTON));
        SceneIntersector[] scenes = {exact, tess, newton};
        TraceContext shared = exact.newContext();
        TraceContext[] own = {exact.newContext(), tess.newContext(), newton.newContext()};
        Hit a = new Hit(), b = new Hit();
        SurfacePoint pa = new SurfacePoint(), pb = new SurfacePoint();
        Random rnd = new Random(5);
        Aabb box = TEAPOT.controlBounds();
        double size = box.diagonal();
        int hits = 0;
        for (int r = 0; r < 3000; r++) {
            int k = rnd.nextInt(3);
            // from a cube twice the box's size toward a point in the box
            double ox = box.center().x() + 2 * size * (rnd.nextDouble() - 0.5);
            double oy = box.center().y() + 2 * size * (rnd.nextDouble() - 0.5);
            double oz = box.center().z() + 2 * size * (rnd.nextDouble() - 0.5);
            double dx = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX()) - ox;
            double dy = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY()) - oy;
            double dz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ()) - oz;
            boolean hitShared = scenes[k].closestHit(shared, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, a);
            boolean hitOwn = scenes[k].closestHit(own[k], ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, b);
            String where = "ray " + r + " on scene " + k;
            assertEquals(hitOwn, hitShared, where);
            if (hitOwn) {
                hits++;
                scenes[k].surfacePoint(shared, a, pa);
                scenes[k].surfacePoint(own[k], b, pb);
                assertEquals(b.t, a.t, 0, where);
                assertEquals(b.u, a.u, 0, where);
                assertEquals(b.v, a.v, 0, where);
                assertEquals(pb.nx, pa.nx, 0, where);
                assertEquals(pb.px, pa.px, 0, where);
            }
            assertEquals(scenes[k].occluded(own[k], ox, oy, oz, dx, dy, dz, 0, 0.9),
                    scenes[k].occluded(shared, ox, oy, oz, dx, dy, dz, 0, 0.9), where);
        }
        assertTrue(hits > 500, "hits " + hits);
    }
}
