package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.Scene;

/**
 * The crack test: dense rays at every border two patches of a model share, none of which may fall
 * through. {@link TeapotIntersectionTest} runs it on the teapot; editing tests run it on edited
 * models (a welded point dragged must leave no crack).
 */
public final class BorderRays {
    private BorderRays() {}

    /**
     * Shoots a dense grid of rays at every border {@code scene}'s patches share (39 points a border, 3
     * rays each, from outside along the normal tilted at random); none may fall through, none may
     * hit beyond the border point aimed at, and most must reach it.
     */
    public static void assertNoneFallThrough(Scene scene, Method method) {
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(method));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH], nrm = new double[3];
        Random rnd = new Random(4);
        int rays = 0, misses = 0, onBorder = 0, shared = 0;
        StringBuilder firstMiss = new StringBuilder();
        for (int k = 0; k < scene.patchCount(); k++) {
            double[] net = scene.patches().get(k).copyNet();
            for (int border = 0; border < 4; border++) {
                if (!isShared(scene, k, border)) {
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
    static boolean isShared(Scene scene, int k, int b) {
        org.beziertracer.math.Vec3 mid = borderPoint(scene, k, b, 0.5), q1 = borderPoint(scene, k, b, 0.25);
        for (int k2 = 0; k2 < scene.patchCount(); k2++) {
            for (int b2 = 0; b2 < 4 && k2 != k; b2++) {
                for (double s : new double[] {0.5}) {
                    if (borderPoint(scene, k2, b2, s).sub(mid).length() < 1e-6) {
                        // same border if the quarter point also lies on it (either direction)
                        if (borderPoint(scene, k2, b2, 0.25).sub(q1).length() < 1e-6 || borderPoint(scene, k2, b2, 0.75).sub(q1).length() < 1e-6) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    }

    static org.beziertracer.math.Vec3 borderPoint(Scene scene, int k, int b, double s) {
        double u = b == 0 ? 0 : b == 1 ? 1 : s, v = b == 2 ? 0 : b == 3 ? 1 : s;
        return org.beziertracer.geometry.Patches.evaluate(scene.patches().get(k), u, v);
    }
}
