package org.beziertracer.bench.report;

import java.util.Locale;

import org.beziertracer.accel.BvhOptions;
import org.beziertracer.bench.Fixtures;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.model.Scene;

/**
 * Work counters behind the split-tuning numbers (not a timing tool: timings come from JMH's
 * {@code SplitTuningBench}): for each {@code flatness:maxDepth[:leafSize]} argument, the number of
 * sub-patches, BVH nodes and depth, and per ray the solver calls (BVH leaf primitives visited)
 * and clip iterations, over the {@code SceneBench} rays on the teapot. {@code whole} = BVH off.
 * <pre>java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.SplitStats whole 0.05:8 0.2:5:2</pre>
 */
public final class SplitStats {
    private SplitStats() {}

    public static void main(String[] args) {
        Scene scene = Fixtures.teapots(32);
        double[] rays = Fixtures.randomRays(scene.controlBounds(), 20_000, 1);
        for (String arg : args) {
            IntersectOptions opts = IntersectOptions.defaults();
            if (arg.equals("whole")) {
                opts = opts.withBvh(false);
            } else {
                String[] f = arg.split(":");
                opts = opts.withSplit(new SplitOptions(true, Double.parseDouble(f[0]), Integer.parseInt(f[1])));
                if (f.length > 2) {
                    opts = opts.withBvhOptions(new BvhOptions(Integer.parseInt(f[2]), 16));
                }
            }
            SceneIntersector si = SceneIntersector.build(scene, opts);
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            int count = rays.length / 6, hits = 0;
            for (int k = 0; k < count; k++) {
                int o = 6 * k;
                if (si.closestHit(ctx, rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5],
                        0, Double.POSITIVE_INFINITY, hit)) {
                    hits++;
                }
            }
            System.out.printf(Locale.ROOT, "%-10s sub-patches %5d nodes %5d depth %2d | per ray: solver calls %.2f, "
                            + "clip iterations %.2f | hits %d/%d%n", arg, si.subPatchCount(), si.nodeCount(), si.depth(),
                    (double) ctx.solverCalls / count, (double) ctx.clipIterations / count, hits, count);
        }
    }
}
