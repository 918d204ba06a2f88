package org.beziertracer.intersect;

import java.util.Locale;
import java.util.Random;

import org.beziertracer.math.Aabb;
import org.beziertracer.model.Scene;

/**
 * One method's answers on a seeded ray set against the slow reference ({@link QuadtreeReference}):
 * how often hit or miss disagree, how far the agreeing hits' t lies from the reference's, and how
 * often a farther root is returned — split by whether the reference's nearest root is more than
 * {@link #SILHOUETTE_MARGIN} of the scene size from a silhouette (then it is a plain error) or
 * not. Directions are unit, so t is a distance.
 */
final class MethodAccuracy {

    /** A root is "away from a silhouette" when rays moved this fraction of the scene size sideways still meet it. */
    static final double SILHOUETTE_MARGIN = 1e-6;
    /** A hit farther than the reference's by more than this fraction of the scene size returned "a farther root". */
    static final double FARTHER = 1e-6;

    int rays, referenceHits, hitMiss, hitMissAwayFromSilhouette, agreeing;
    int fartherAway, fartherNearSilhouette, nearer;
    double maxError, sumError;
    /** Largest |t − t_ref| over every ray both hit (farther and nearer roots included). */
    double maxBothHitError;

    /** Mean |t − t_ref| over the agreeing hits, as a fraction of the scene size. */
    double meanError(double size) { return agreeing == 0 ? 0 : sumError / agreeing / size; }

    /** Compares {@code method} (its default leaves) with the reference on {@code rays} (6 doubles each, unit d). */
    static MethodAccuracy measure(Scene scene, Method method, double[] rays) {
        SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(method));
        return measure(scene, si, rays, references(scene, rays));
    }

    /** As {@link #measure(Scene, Method, double[])} with the reference's roots already known. */
    static MethodAccuracy measure(Scene scene, SceneIntersector si, double[] rays, double[][] reference) {
        QuadtreeReference ref = new QuadtreeReference();
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double size = si.sceneSize();
        MethodAccuracy a = new MethodAccuracy();
        for (int k = 0, o = 0; k < rays.length / 6; k++, o += 6) {
            double[] r = reference[k];
            boolean found = si.closestHit(ctx, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5],
                    0, Double.POSITIVE_INFINITY, hit);
            a.rays++;
            if (r != null) {
                a.referenceHits++;
            }
            if (r != null && found) {
                a.maxBothHitError = Math.max(a.maxBothHitError, Math.abs(hit.t - r[0]));
            }
            if ((r != null) != found) {
                a.hitMiss++;
                if (r != null && awayFromSilhouette(ref, scene, rays, o, r[0], size)) {
                    a.hitMissAwayFromSilhouette++;
                }
            } else if (r != null && hit.t - r[0] > FARTHER * size) {
                if (awayFromSilhouette(ref, scene, rays, o, r[0], size)) {
                    a.fartherAway++;
                } else {
                    a.fartherNearSilhouette++;
                }
            } else if (r != null && r[0] - hit.t > FARTHER * size) {
                a.nearer++; // a root the reference missed
            } else if (r != null) {
                double error = Math.abs(hit.t - r[0]);
                a.agreeing++;
                a.sumError += error;
                a.maxError = Math.max(a.maxError, error);
            }
        }
        return a;
    }

    /** The reference's nearest root {t, u, v, patch} (or null) for every ray. */
    static double[][] references(Scene scene, double[] rays) {
        QuadtreeReference ref = new QuadtreeReference();
        double[][] out = new double[rays.length / 6][];
        for (int k = 0, o = 0; k < out.length; k++, o += 6) {
            out[k] = ref.nearest(scene, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], 0,
                    Double.POSITIVE_INFINITY);
        }
        return out;
    }

    /**
     * True when rays moved by {@link #SILHOUETTE_MARGIN} of the scene size in four directions
     * across the ray all still meet a root within 1e-3 of the scene size of {@code t}: the nearest
     * root is not within that margin of a silhouette (where it would vanish or jump).
     */
    static boolean awayFromSilhouette(QuadtreeReference ref, Scene scene, double[] rays, int o, double t, double size) {
        double dx = rays[o + 3], dy = rays[o + 4], dz = rays[o + 5];
        double ax = Math.abs(dx) < 0.9 ? 1 : 0, ay = 1 - ax;
        double p1x = -dz * ay, p1y = dz * ax, p1z = dx * ay - dy * ax;
        double l = Math.sqrt(p1x * p1x + p1y * p1y + p1z * p1z);
        p1x /= l;
        p1y /= l;
        p1z /= l;
        double p2x = dy * p1z - dz * p1y, p2y = dz * p1x - dx * p1z, p2z = dx * p1y - dy * p1x;
        double eps = SILHOUETTE_MARGIN * size;
        for (int s = 0; s < 4; s++) {
            double sx = s < 2 ? p1x : p2x, sy = s < 2 ? p1y : p2y, sz = s < 2 ? p1z : p2z, sign = (s & 1) == 0 ? eps : -eps;
            double[] r = ref.nearest(scene, rays[o] + sign * sx, rays[o + 1] + sign * sy, rays[o + 2] + sign * sz, dx, dy, dz,
                    0, Double.POSITIVE_INFINITY);
            if (r == null || Math.abs(r[0] - t) > 1e-3 * size) {
                return false;
            }
        }
        return true;
    }

    /** Rays as {@code trace --random}: from a sphere of radius the box diagonal toward uniform points of the box; unit d. */
    static double[] randomRays(Aabb box, int count, long seed) {
        Random rnd = new Random(seed);
        double[] out = new double[6 * count];
        double r = box.diagonal();
        double cx = box.center().x(), cy = box.center().y(), cz = box.center().z();
        for (int k = 0; k < count; k++) {
            double gx = rnd.nextGaussian(), gy = rnd.nextGaussian(), gz = rnd.nextGaussian();
            double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
            double ox = cx + r * gx / len, oy = cy + r * gy / len, oz = cz + r * gz / len;
            double dx = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX()) - ox;
            double dy = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY()) - oy;
            double dz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ()) - oz;
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            int o = 6 * k;
            out[o] = ox; out[o + 1] = oy; out[o + 2] = oz;
            out[o + 3] = dx / d; out[o + 4] = dy / d; out[o + 5] = dz / d;
        }
        return out;
    }

    /**
     * Rays at a height field over {@code [-2,2]²} (as {@link RandomPatches#heightField} with size 4):
     * from random points 3 to 6 above, toward random points of the middle {@code [-1.5,1.5]²}; unit d.
     */
    static double[] rainRays(Random rnd, int count) {
        double[] out = new double[6 * count];
        for (int k = 0; k < count; k++) {
            double ox = 6 * (rnd.nextDouble() - 0.5), oy = 6 * (rnd.nextDouble() - 0.5), oz = 3 + 3 * rnd.nextDouble();
            double dx = 3 * (rnd.nextDouble() - 0.5) - ox, dy = 3 * (rnd.nextDouble() - 0.5) - oy, dz = -oz;
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            int o = 6 * k;
            out[o] = ox; out[o + 1] = oy; out[o + 2] = oz;
            out[o + 3] = dx / d; out[o + 4] = dy / d; out[o + 5] = dz / d;
        }
        return out;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%d rays, %d reference hits: hit/miss differ %d (%d away from a silhouette), "
                        + "farther root %d (+%d near a silhouette), nearer %d, agreeing %d with max |dt| %.2e",
                rays, referenceHits, hitMiss, hitMissAwayFromSilhouette, fartherAway, fartherNearSilhouette, nearer,
                agreeing, maxError);
    }
}
