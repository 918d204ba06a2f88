package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
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
 * Whole-scene queries on the teapot with Bézier clipping: {@code closestHit} and {@code occluded}
 * for the rays of {@code trace teapot --random} (seeded), with the sub-patch BVH on (default split
 * and BVH options) or off (whole patches in a flat list). Time is per ray. Run with
 * {@code -prof gc}: both must allocate ~0 B/op.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class SceneBench {

    @Param({"true", "false"})
    public boolean bvh;

    /** Number of teapot patches: 32 = one teapot, 3200 = 100 teapots on a grid. */
    @Param({"32"})
    public int patchCount;

    SceneIntersector si;
    TraceContext ctx;
    Hit hit;
    double[] rays;

    @Setup
    public void setup() {
        Scene scene = Fixtures.teapots(patchCount);
        si = SceneIntersector.build(scene, IntersectOptions.defaults().withBvh(bvh));
        ctx = si.newContext();
        hit = new Hit();
        rays = Fixtures.randomRays(patchCount <= 32 ? scene.controlBounds() : Fixtures.teapots(32).controlBounds(),
                Fixtures.RAYS, 1);
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void closestHit(Blackhole bh) {
        Fixtures.closestHits(si, ctx, hit, rays, bh);
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void occluded(Blackhole bh) {
        Fixtures.occludedAll(si, ctx, rays, bh);
    }
}
