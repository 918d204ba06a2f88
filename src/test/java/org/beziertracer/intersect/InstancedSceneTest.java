package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.InstancedSplitTestAccess;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Placement;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * A scene that uses one model several times ({@link org.beziertracer.model.Instance}, split once)
 * is traced as the same patches given as the scene's own: the same hits (patch, t, u, v to
 * rounding) and the same shadows, for every method, on seeded random rays.
 */
class InstancedSceneTest {

    private static final Placement[] USES = InstancedSplitTestAccess.uses();

    @Test
    void anInstancedSceneHasTheHitsOfTheSamePatchesGivenOneByOne() {
        List<BezierPatch> teapot = Models.teapot().patches();
        Scene instanced = InstancedSplitTestAccess.scene(teapot, USES);
        Scene flat = Scene.builder().patches(instanced.patches()).build();
        assertEquals(USES.length, instanced.instances().size());
        double size = instanced.controlBounds().diagonal();
        for (Method method : Method.values()) {
            IntersectOptions options = IntersectOptions.defaults().withMethod(method);
            SceneIntersector a = SceneIntersector.build(instanced, options), b = SceneIntersector.build(flat, options);
            assertEquals(32, ((PatchLeaves) a.leaves).table.splitPatches, method + ": the model split once");
            assertEquals(32 * USES.length, ((PatchLeaves) b.leaves).table.splitPatches, method + ": every patch split");
            TraceContext ca = a.newContext(), cb = b.newContext();
            Hit ha = new Hit(), hb = new Hit();
            Random rnd = new Random(20261204L + method.ordinal());
            var box = instanced.controlBounds();
            int hits = 0, differ = 0;
            for (int r = 0; r < 3000; r++) {
                double ox = box.minX() - size + 3 * size * rnd.nextDouble(), oy = box.minY() - size + 3 * size * rnd.nextDouble();
                double oz = box.maxZ() + size;
                double tx = box.minX() + (box.maxX() - box.minX()) * rnd.nextDouble();
                double ty = box.minY() + (box.maxY() - box.minY()) * rnd.nextDouble();
                double tz = box.minZ() + (box.maxZ() - box.minZ()) * rnd.nextDouble();
                double dx = tx - ox, dy = ty - oy, dz = tz - oz;
                boolean hitA = a.closestHit(ca, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, ha);
                boolean hitB = b.closestHit(cb, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hb);
                boolean shadowA = a.occluded(ca, ox, oy, oz, dx, dy, dz, 0, 1);
                boolean shadowB = b.occluded(cb, ox, oy, oz, dx, dy, dz, 0, 1);
                if (hitA != hitB || shadowA != shadowB
                        || hitA && (ha.index != hb.index || Math.abs(ha.t - hb.t) > 1e-9 * (1 + hb.t))) {
                    differ++;
                    continue;
                }
                hits += hitA ? 1 : 0;
            }
            assertTrue(hits > 600, method + ": the rays meet the teapots: " + hits);
            // a ray grazing a silhouette may fall either side of it by rounding; no more than that
            assertTrue(differ <= 3, method + ": " + differ + " of 3000 rays differ");
        }
    }
}
