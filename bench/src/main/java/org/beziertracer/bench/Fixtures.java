package org.beziertracer.bench;

import org.openjdk.jmh.infra.Blackhole;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.intersect.SceneIntersector;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.PatchNormals;
import org.beziertracer.math.Aabb;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Placement;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;

/**
 * Seeded inputs shared by the benchmarks: scenes (teapot, 100 teapots, random height fields) and
 * ray sets stored flat, six doubles a ray ({@code ox, oy, oz, dx, dy, dz}). Setup-time only.
 */
public final class Fixtures {
    private Fixtures() {}

    /** Rays per benchmark invocation (the {@code @OperationsPerInvocation} of the ray loops). */
    public static final int RAYS = 1024;

    /**
     * Eight drag steps of {@code p}'s middle control point: moved along z by 2 % of the patch's
     * control-box diagonal times {@code sin(k π/4)}, k = 0..7 (up, back, down, back).
     */
    public static BezierPatch[] drags(BezierPatch p) {
        int i = p.degreeU() / 2, j = p.degreeV() / 2;
        double size = p.controlBounds().diagonal();
        BezierPatch[] drags = new BezierPatch[8];
        for (int k = 0; k < drags.length; k++) {
            double dz = 0.02 * size * Math.sin(k * Math.PI / 4);
            drags[k] = p.withPoint(i, j, p.get(i, j, 0), p.get(i, j, 1), p.get(i, j, 2) + dz);
        }
        return drags;
    }

    /**
     * The first {@code count} patches of the teapot, or {@code count/32} teapots on a grid: one
     * model used {@code count/32} times ({@link Scene.Builder#addInstance}), as a scene file that
     * lists the built-in teapot again with other transforms.
     */
    public static Scene teapots(int patchCount) {
        List<BezierPatch> teapot = Models.teapot().patches();
        if (patchCount <= teapot.size()) {
            return new Scene(teapot.subList(0, patchCount));
        }
        int copies = patchCount / teapot.size();
        int side = (int) Math.ceil(Math.sqrt(copies));
        Scene.Builder scene = Scene.builder();
        for (int c = 0; c < copies; c++) {
            Shift shift = new Shift(300.0 * (c % side), 200.0 * (c / side));
            List<BezierPatch> placed = new ArrayList<>();
            for (BezierPatch p : teapot) {
                double[] net = p.copyNet();
                shift.mapPoints(net, 0, net.length / 3);
                placed.add(new BezierPatch(p.degreeU(), p.degreeV(), net));
            }
            scene.addInstance(teapot, placed, shift, 0);
        }
        return scene.build();
    }

    /** A translation in x and y. */
    private record Shift(double tx, double ty) implements Placement {
        @Override
        public void mapPoints(double[] xyz, int offset, int count) {
            for (int i = offset; i < offset + 3 * count; i += 3) {
                xyz[i] += tx;
                xyz[i + 1] += ty;
            }
        }

        @Override
        public boolean similarity() { return true; }
    }

    /**
     * Random rays as {@code trace --random}: from a sphere of radius = box diagonal around the
     * scene's control box toward uniform points inside it.
     */
    public static double[] randomRays(Aabb box, int count, long seed) {
        Random rnd = new Random(seed);
        double[] rays = new double[6 * count];
        double r = box.diagonal();
        double cx = box.center().x(), cy = box.center().y(), cz = box.center().z();
        for (int k = 0; k < count; k++) {
            double gx = rnd.nextGaussian(), gy = rnd.nextGaussian(), gz = rnd.nextGaussian();
            double len = Math.sqrt(gx * gx + gy * gy + gz * gz);
            double ox = cx + r * gx / len, oy = cy + r * gy / len, oz = cz + r * gz / len;
            double tx = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX());
            double ty = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY());
            double tz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ());
            put(rays, k, ox, oy, oz, tx - ox, ty - oy, tz - oz);
        }
        return rays;
    }

    /**
     * A wavy height field over {@code [-size/2, size/2]²} as in the intersect tests'
     * {@code RandomPatches.heightField}: jittered grid in x and y, random heights up to
     * {@code relief·size}.
     */
    public static BezierPatch heightField(Random rnd, int n, int m, double size, double relief) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                net[k] = size * ((double) i / n - 0.5) + 0.1 * size / n * (rnd.nextDouble() - 0.5);
                net[k + 1] = size * ((double) j / m - 0.5) + 0.1 * size / m * (rnd.nextDouble() - 0.5);
                net[k + 2] = relief * size * (rnd.nextDouble() - 0.5);
            }
        }
        return new BezierPatch(n, m, net);
    }

    /** Point and unit normal of the patch at (u,v): {@code out[0..2]} and {@code out[3..5]}. */
    public static void pointAndNormal(BezierPatch p, double u, double v, double[] out) {
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        double[] net = p.copyNet();
        DeCasteljau.evaluate(net, 0, p.degreeU(), p.degreeV(), 3, u, v, out, 0, scratch);
        PatchNormals.unitNormal(net, 0, p.degreeU(), p.degreeV(), u, v, out, 3, scratch);
    }

    public static void put(double[] rays, int k, double ox, double oy, double oz, double dx, double dy, double dz) {
        rays[6 * k] = ox;
        rays[6 * k + 1] = oy;
        rays[6 * k + 2] = oz;
        rays[6 * k + 3] = dx;
        rays[6 * k + 4] = dy;
        rays[6 * k + 5] = dz;
    }

    /** Traces every ray of {@code rays} (6 doubles each) with closestHit, consuming t or -1. */
    static void closestHits(SceneIntersector si, TraceContext ctx, Hit hit, double[] rays, Blackhole bh) {
        for (int k = 0, count = rays.length / 6; k < count; k++) {
            int o = 6 * k;
            boolean found = si.closestHit(ctx, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5],
                    0, Double.POSITIVE_INFINITY, hit);
            bh.consume(found ? hit.t : -1);
        }
    }

    /** Traces every ray of {@code rays} (6 doubles each) with occluded, consuming the answer. */
    static void occludedAll(SceneIntersector si, TraceContext ctx, double[] rays, Blackhole bh) {
        for (int k = 0, count = rays.length / 6; k < count; k++) {
            int o = 6 * k;
            bh.consume(si.occluded(ctx, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5],
                    0, Double.POSITIVE_INFINITY));
        }
    }
}
