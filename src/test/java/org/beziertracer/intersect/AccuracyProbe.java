package org.beziertracer.intersect;

import java.util.List;
import java.util.Locale;
import java.util.Random;

import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.math.Aabb;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;

/** Temporary experiment harness: methods against the quadtree reference. */
public final class AccuracyProbe {

    public static void main(String[] args) {
        int rays = Integer.parseInt(args.length > 0 ? args[0] : "5000");
        String what = args.length > 1 ? args[1] : "teapot";
        Method[] methods = {Method.CLIPPING, Method.NEWTON};
        SplitOptions split = null;
        if (System.getProperty("methods") != null) {
            String[] names = System.getProperty("methods").split(",");
            methods = new Method[names.length];
            for (int i = 0; i < names.length; i++) methods[i] = Method.parse(names[i]);
        }
        if (what.equals("teapot")) {
            Scene scene = Models.load("teapot");
            for (Method m : methods) {
                run(scene, m, split, teapotRays(scene.controlBounds(), rays, 1), "teapot");
            }
        } else {
            for (int d = 1; d <= 15; d++) {
                Random rnd = new Random(100 + d);
                for (Method m : methods) {
                    long total = 0;
                    int[] c = new int[5];
                    for (int p = 0; p < 10; p++) {
                        boolean wild = what.equals("wild");
                        BezierPatch patch = wild ? RandomPatches.wild(new Random(1000 * d + p), d, d, 2)
                                : RandomPatches.heightField(new Random(1000 * d + p), d, d, 4, 0.8);
                        int[] r = run(new Scene(List.of(patch)), m, split, wild ? teapotRays(new Scene(List.of(patch)).controlBounds(), rays / 10, 77 + p) : patchRays(rnd, rays / 10), null);
                        for (int k = 0; k < 5; k++) c[k] += r[k];
                        total += rays / 10;
                    }
                    System.out.printf(Locale.ROOT, "degree %2d %-9s rays %d refHits %d hitMiss %d farther %d (robust %d) leaves/patch %d%n",
                            d, m.label(), total, c[0], c[1], c[2], c[3], c[4] / 10);
                }
            }
        }
    }

    static double[] teapotRays(Aabb box, int count, long seed) {
        Random rnd = new Random(seed);
        double[] out = new double[6 * count];
        double r = box.diagonal();
        double cx = box.center().x(), cy = box.center().y(), cz = box.center().z();
        for (int k = 0; k < count; k++) {
            double gx = rnd.nextGaussian(), gy = rnd.nextGaussian(), gz = rnd.nextGaussian();
            double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
            double ox = cx + r * gx / len, oy = cy + r * gy / len, oz = cz + r * gz / len;
            double tx = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX());
            double ty = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY());
            double tz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ());
            put(out, k, ox, oy, oz, tx - ox, ty - oy, tz - oz);
        }
        return out;
    }

    static double[] patchRays(Random rnd, int count) {
        double[] out = new double[6 * count];
        for (int k = 0; k < count; k++) {
            double ox = 6 * (rnd.nextDouble() - 0.5), oy = 6 * (rnd.nextDouble() - 0.5), oz = 3 + 3 * rnd.nextDouble();
            double tx = 3 * (rnd.nextDouble() - 0.5), ty = 3 * (rnd.nextDouble() - 0.5);
            put(out, k, ox, oy, oz, tx - ox, ty - oy, -oz);
        }
        return out;
    }

    static void put(double[] a, int k, double ox, double oy, double oz, double dx, double dy, double dz) {
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        a[6 * k] = ox; a[6 * k + 1] = oy; a[6 * k + 2] = oz;
        a[6 * k + 3] = dx / len; a[6 * k + 4] = dy / len; a[6 * k + 5] = dz / len;
    }

    /** Returns {refHits, hitMiss, farther, fartherRobust}. */
    static int[] run(Scene scene, Method method, SplitOptions split, double[] rays, String label) {
        SceneIntersector si = SceneIntersector.build(scene, split == null ? IntersectOptions.defaults().withMethod(method) : IntersectOptions.defaults().withMethod(method).withSplit(split));
        QuadtreeReference ref = new QuadtreeReference();
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double size = si.sceneSize();
        int count = rays.length / 6, refHits = 0, hitMiss = 0, farther = 0, robust = 0, missRobust = 0;
        double maxDt = 0;
        for (int k = 0; k < count; k++) {
            int o = 6 * k;
            double[] r = ref.nearest(scene, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], 0,
                    Double.POSITIVE_INFINITY);
            boolean h = si.closestHit(ctx, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], 0,
                    Double.POSITIVE_INFINITY, hit);
            if (r != null) {
                refHits++;
            }
            if ((r != null) != h) {
                hitMiss++;
                if (r != null && robust(ref, scene, rays, o, r[0], size)) {
                    missRobust++;
                }
                continue;
            }
            if (r != null) {
                double dt = hit.t - r[0];
                if (dt > 1e-6 * size) {
                    farther++;
                    if (robust(ref, scene, rays, o, r[0], size)) {
                        robust++;
                    }
                } else {
                    maxDt = Math.max(maxDt, Math.abs(dt));
                }
            }
        }
        if (label != null) {
            System.out.printf(Locale.ROOT, "%s %-9s rays %d refHits %d hitMiss %d (%.3f%%, robust misses %d) farther %d (robust %d) max|dt| %.2e subPatches %d%n",
                    label, method.label(), count, refHits, hitMiss, 100.0 * hitMiss / count, missRobust, farther, robust, maxDt,
                    si.subPatchCount());
        }
        return new int[] {refHits, hitMiss, farther, robust, si.subPatchCount()};
    }

    /** True when rays offset by 1e-6 of the scene in four directions all still meet a root near t. */
    static boolean robust(QuadtreeReference ref, Scene scene, double[] rays, int o, double t, double size) {
        double dx = rays[o + 3], dy = rays[o + 4], dz = rays[o + 5];
        // two unit vectors perpendicular to d
        double ax = Math.abs(dx) < 0.9 ? 1 : 0, ay = ax == 1 ? 0 : 1, az = 0;
        double p1x = dy * az - dz * ay, p1y = dz * ax - dx * az, p1z = dx * ay - dy * ax;
        double l = Math.sqrt(p1x * p1x + p1y * p1y + p1z * p1z);
        p1x /= l; p1y /= l; p1z /= l;
        double p2x = dy * p1z - dz * p1y, p2y = dz * p1x - dx * p1z, p2z = dx * p1y - dy * p1x;
        double eps = 1e-6 * size;
        for (int s = 0; s < 4; s++) {
            double sx = s < 2 ? p1x : p2x, sy = s < 2 ? p1y : p2y, sz = s < 2 ? p1z : p2z;
            double sign = (s & 1) == 0 ? eps : -eps;
            double[] r = ref.nearest(scene, rays[o] + sign * sx, rays[o + 1] + sign * sy, rays[o + 2] + sign * sz,
                    dx, dy, dz, 0, Double.POSITIVE_INFINITY);
            if (r == null || Math.abs(r[0] - t) > 1e-3 * size) {
                return false;
            }
        }
        return true;
    }
}
