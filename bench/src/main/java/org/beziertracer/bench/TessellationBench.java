package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.model.Scene;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.Blackhole;

/**
 * Exact (tessellate = 0, Bézier clipping over the sub-patch BVH) against the tessellated mode
 * (K×K cells per patch, watertight triangles in the same BVH) on the teapot, same rays as
 * {@link SceneBench}. {@code closestHitShaded} adds the surface-point evaluation of the final hit,
 * which a renderer always needs. Time is per ray.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class TessellationBench {

    @Param({"0", "4", "8", "16", "32", "64"})
    public int tessellate;

    SceneIntersector si;
    TraceContext ctx;
    Hit hit;
    SurfacePoint sp;
    double[] rays;

    @Setup
    public void setup() {
        Scene scene = Fixtures.teapots(32);
        si = SceneIntersector.build(scene, IntersectOptions.defaults().withTessellate(tessellate));
        ctx = si.newContext();
        hit = new Hit();
        sp = new SurfacePoint();
        rays = Fixtures.randomRays(scene.controlBounds(), Fixtures.RAYS, 1);
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void closestHit(Blackhole bh) {
        Fixtures.closestHits(si, ctx, hit, rays, bh);
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void closestHitShaded(Blackhole bh) {
        double[] r = rays;
        for (int k = 0; k < Fixtures.RAYS; k++) {
            int o = 6 * k;
            if (si.closestHit(ctx, r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5],
                    0, Double.POSITIVE_INFINITY, hit)) {
                si.surfacePoint(ctx, hit, sp);
                bh.consume(sp.nx);
            }
        }
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void occluded(Blackhole bh) {
        Fixtures.occludedAll(si, ctx, rays, bh);
    }
}
