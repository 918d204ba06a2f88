package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.accel.BvhOptions;
import org.beziertracer.geometry.SplitOptions;
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
 * Tuning sweep for the exact path on the teapot: the pre-split's flatness tolerance and depth cap
 * ({@link SplitOptions}) and the BVH leaf size ({@link BvhOptions}), closest hit with Bézier
 * clipping, same rays as {@link SceneBench}. The full grid is large: restrict it with {@code -p},
 * e.g. {@code -p leafSize=4} first, then sweep the leaf size at the chosen split.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class SplitTuningBench {

    @Param({"0.4", "0.2", "0.1", "0.05", "0.02"})
    public double flatness;

    @Param({"3", "5", "8"})
    public int maxDepth;

    @Param({"1", "2", "4", "8"})
    public int leafSize;

    SceneIntersector si;
    TraceContext ctx;
    Hit hit;
    double[] rays;

    @Setup
    public void setup() {
        Scene scene = Fixtures.teapots(32);
        si = SceneIntersector.build(scene, IntersectOptions.defaults()
                .withSplit(new SplitOptions(true, flatness, maxDepth))
                .withBvhOptions(new BvhOptions(leafSize, 16)));
        ctx = si.newContext();
        hit = new Hit();
        rays = Fixtures.randomRays(scene.controlBounds(), Fixtures.RAYS, 1);
        System.out.println("# sub-patches " + si.subPatchCount() + ", BVH nodes " + si.nodeCount()
                + ", depth " + si.depth());
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void closestHit(Blackhole bh) {
        Fixtures.closestHits(si, ctx, hit, rays, bh);
    }
}
