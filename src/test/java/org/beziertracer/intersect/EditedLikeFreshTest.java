package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.GeneratedModels;
import org.junit.jupiter.api.Test;

/**
 * After a drag (edits that keep the patch's old halvings, {@link SceneIntersector#withPatches}),
 * every method finds the hits a fresh build of the same scene finds: the exact methods to
 * rounding, their roots being the patch's whatever the leaves; subdivision bit for bit, its hits
 * being its leaves' control meshes, because an edit splits its patch afresh ({@link Method#exact()}).
 * A soak once saw one pixel of a subdivision picture differ from a fresh render after a drag.
 */
class EditedLikeFreshTest {

    @Test
    void aDraggedPatchIsTracedAsAFreshBuildOfItWouldBeForEveryMethod() {
        for (Method method : Method.values()) {
            IntersectOptions options = IntersectOptions.defaults().withMethod(method);
            Scene scene = GeneratedModels.wavy(6);
            SceneIntersector si = SceneIntersector.build(scene, options);
            Random rnd = new Random(36 + method.ordinal());
            for (int drag = 0; drag < 12; drag++) {
                BezierPatch p = scene.patches().get(0);
                double[] net = p.copyNet();
                int point = 3 * (7 + rnd.nextInt(21));
                net[point + 2] += 0.08 * (rnd.nextDouble() - 0.5);
                scene = scene.withPatch(0, p.withNet(net));
                si = si.withPatch(0, scene.patches().get(0));
            }
            SceneIntersector fresh = SceneIntersector.build(scene, options);
            TraceContext a = si.newContext(), b = fresh.newContext();
            Hit ha = new Hit(), hb = new Hit();
            int hits = 0;
            for (int r = 0; r < 4000; r++) {
                double x = 3 * rnd.nextDouble() - 1.5, y = 3 * rnd.nextDouble() - 1.5;
                double dx = 0.2 * (rnd.nextDouble() - 0.5), dy = 0.2 * (rnd.nextDouble() - 0.5);
                boolean fa = si.closestHit(a, x, y, 5, dx, dy, -1, 0, Double.POSITIVE_INFINITY, ha);
                boolean fb = fresh.closestHit(b, x, y, 5, dx, dy, -1, 0, Double.POSITIVE_INFINITY, hb);
                String what = method + ", ray " + r;
                assertEquals(fb, fa, what + ": hit or miss");
                if (fa) {
                    hits++;
                    // exact methods: the same root to rounding (other leaves, other last steps);
                    // subdivision: the same leaves, so the same bits
                    double tol = method.exact() ? 1e-12 : 0;
                    assertEquals(hb.t, ha.t, tol * hb.t, what + ": t");
                    assertEquals(hb.u, ha.u, tol, what + ": u");
                    assertEquals(hb.v, ha.v, tol, what + ": v");
                }
            }
            assertTrue(hits > 1000, method + ": the rays meet the patch: " + hits);
        }
    }
}
