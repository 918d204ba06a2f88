package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.accel.Bvh;
import org.beziertracer.accel.BvhOptions;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.Scene;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.Blackhole;

/**
 * Building and refitting the BVH over sub-patch boxes (default split), and the pre-split itself,
 * for 1 patch, the 32-patch teapot and 100 teapots on a grid (3,200 patches).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MICROSECONDS)
public class BvhBench {

    @Param({"1", "32", "3200"})
    public int patchCount;

    /** Split settings (defaults of {@link SplitOptions}); sweep with {@code -p flatness=..,.. -p maxDepth=..}. */
    @Param({"default"})
    public String flatness;

    @Param({"default"})
    public String maxDepth;

    Scene scene;
    SubPatchTable table;
    double[] bounds;
    Bvh bvh;
    BvhOptions options;
    SplitOptions split;

    @Setup
    public void setup() {
        scene = Fixtures.teapots(patchCount);
        SplitOptions d = SplitOptions.defaults();
        split = new SplitOptions(true, flatness.equals("default") ? d.flatnessTolerance() : Double.parseDouble(flatness),
                maxDepth.equals("default") ? d.maxDepth() : Integer.parseInt(maxDepth));
        table = SubPatchTable.build(scene.patches(), split);
        bounds = table.bounds(0, table.count);
        options = BvhOptions.defaults();
        bvh = Bvh.build(bounds, table.count, options);
    }

    @Benchmark
    public void build(Blackhole bh) {
        bh.consume(Bvh.build(bounds, table.count, options));
    }

    @Benchmark
    public void refit(Blackhole bh) {
        bh.consume(bvh.refit(bounds));
    }

    /** The de Casteljau pre-split of every patch into the sub-patch table. */
    @Benchmark
    public void split(Blackhole bh) {
        bh.consume(SubPatchTable.build(scene.patches(), split));
    }
}
