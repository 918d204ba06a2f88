package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.PatchNormals;
import org.beziertracer.geometry.Patches;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The dense border ("crack") test of any model: rays aimed at points of every border two patches
 * share, along the normal tilted at random, from twice the model's size away (so from the side
 * the normal points away from: the outside of the teapot, whose normals point inward). A ray may hit something nearer; it must not fall through, and it must not hit beyond
 * the border point it was aimed at. {@link BorderCrackTest} runs it for every method; editing
 * tests run {@link #assertNoneFallThrough} on edited models (a welded point dragged must leave no
 * crack).
 */
public final class BorderRays {

    /** Counts of one run, and the first failure for the message. */
    static final class Result {
        int sharedBorders, rays, misses, beyond, onBorder;
        final StringBuilder first = new StringBuilder();

        @Override
        public String toString() {
            return misses + " of " + rays + " rays fell through and " + beyond + " hit beyond the border, at "
                    + sharedBorders + " shared borders" + (first.length() > 0 ? "; first: " + first : "");
        }
    }

    private BorderRays() {}

    /**
     * Three rays at each of 39 points of every border {@code scene}'s patches share: none may fall
     * through or hit beyond the border point aimed at, and most must reach it.
     */
    public static void assertNoneFallThrough(Scene scene, Method method) {
        Result r = shoot(scene, IntersectOptions.defaults().withMethod(method), 3, 4);
        assertTrue(r.sharedBorders > 0, "no shared borders found");
        assertEquals(0, r.misses + r.beyond, method + ": " + r);
        assertTrue(r.onBorder > r.rays / 2, "most rays should reach the border point itself: " + r.onBorder + " of " + r.rays);
    }

    /** Shoots {@code perPoint} rays at each of 39 points of every shared border of {@code scene}. */
    static Result shoot(Scene scene, IntersectOptions options, int perPoint, long seed) {
        SceneIntersector si = SceneIntersector.build(scene, options);
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH], nrm = new double[3];
        double distance = 2 * scene.controlBounds().diagonal(), slack = 1e-6 * distance;
        Random rnd = new Random(seed);
        Result r = new Result();
        for (int k = 0; k < scene.patchCount(); k++) {
            BezierPatch p = scene.patches().get(k);
            double[] net = p.copyNet();
            for (int border = 0; border < 4; border++) {
                if (!isShared(scene, k, border)) {
                    continue; // an open edge: a ray exactly at it may graze past
                }
                r.sharedBorders++;
                for (int a = 1; a < 40; a++) { // corners may lie on an open edge
                    double u = border == 0 ? 0 : border == 1 ? 1 : a / 40.0, v = border == 2 ? 0 : border == 3 ? 1 : a / 40.0;
                    DeCasteljau.evaluateWithDerivatives(net, 0, p.degreeU(), p.degreeV(), u, v, e, scratch);
                    PatchNormals.unitNormal(net, 0, p.degreeU(), p.degreeV(), u, v, nrm, 0, scratch);
                    for (int i = 0; i < perPoint; i++) {
                        double dx = nrm[0] + 0.4 * rnd.nextGaussian(), dy = nrm[1] + 0.4 * rnd.nextGaussian();
                        double dz = nrm[2] + 0.4 * rnd.nextGaussian();
                        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                        dx /= len;
                        dy /= len;
                        dz /= len;
                        double ox = e[0] - distance * dx, oy = e[1] - distance * dy, oz = e[2] - distance * dz;
                        r.rays++;
                        boolean found = si.closestHit(ctx, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit);
                        if (found && Math.abs(hit.t - distance) <= slack) {
                            r.onBorder++;
                        } else if (!found || hit.t > distance + slack) {
                            if (found) {
                                r.beyond++;
                            } else {
                                r.misses++;
                            }
                            if (r.first.length() == 0) {
                                r.first.append(found ? "hit at t=" + hit.t + " beyond " + distance : "miss").append(" at patch ")
                                        .append(k).append(" (u,v)=(").append(u).append(',').append(v).append(") o=(")
                                        .append(ox).append(',').append(oy).append(',').append(oz).append(") d=(").append(dx)
                                        .append(',').append(dy).append(',').append(dz).append(')');
                            }
                        }
                    }
                }
            }
        }
        return r;
    }

    /** Whether border {@code b} (u=0, u=1, v=0, v=1) of patch {@code k} coincides with a border of another patch. */
    static boolean isShared(Scene scene, int k, int b) {
        double eps = 1e-9 * scene.controlBounds().diagonal();
        Vec3 mid = borderPoint(scene, k, b, 0.5), quarter = borderPoint(scene, k, b, 0.25);
        for (int k2 = 0; k2 < scene.patchCount(); k2++) {
            for (int b2 = 0; b2 < 4 && k2 != k; b2++) {
                // the same border if the middle and the quarter point lie on it (either direction)
                if (borderPoint(scene, k2, b2, 0.5).sub(mid).length() < eps
                        && (borderPoint(scene, k2, b2, 0.25).sub(quarter).length() < eps
                            || borderPoint(scene, k2, b2, 0.75).sub(quarter).length() < eps)) {
                    return true;
                }
            }
        }
        return false;
    }

    static Vec3 borderPoint(Scene scene, int k, int b, double s) {
        double u = b == 0 ? 0 : b == 1 ? 1 : s, v = b == 2 ? 0 : b == 3 ? 1 : s;
        return Patches.evaluate(scene.patches().get(k), u, v);
    }
}
