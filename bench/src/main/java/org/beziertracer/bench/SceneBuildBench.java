package org.beziertracer.bench;

import java.util.List;
import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
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
 * Scene preparation as the app and the CLI pay it: {@link SceneIntersector#build} (pre-split into
 * the sub-patch table, then the BVH, both parallel on the common pool) for the scale cases of
 * issue [1 of 5] and the big models of issue [6]; and {@link SceneIntersector#withPatch} after a
 * drag (one patch re-split, BVH refitted, or rebuilt when its leaf count changed) on the 10×10-point
 * grid (one degree 9×9 patch). Time per operation in milliseconds; quote the median.
 *
 * <p>{@code model}: {@code teapots3200} (100 teapots), {@code teapots32000} (1,000 teapots),
 * {@code body100000} / {@code soup100000} ({@link BigModels}), {@code grid10} (the degree-9 grid).
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class SceneBuildBench {

    @Param({"teapots3200", "teapots32000", "body100000", "soup100000", "grid10"})
    public String model;

    Scene scene;
    SceneIntersector built;
    BezierPatch[] drags;
    int drag;

    @Setup
    public void setup() {
        scene = scene(model);
        built = SceneIntersector.build(scene, IntersectOptions.defaults());
        // A drag: the middle control point of patch 0 moved a little, back and forth
        drags = Fixtures.drags(scene.patches().get(0));
    }

    /** The scene of {@code name} (see the class comment). */
    static Scene scene(String name) {
        if (name.startsWith("teapots")) {
            return Fixtures.teapots(Integer.parseInt(name.substring(7)));
        }
        if (name.equals("grid10")) {
            return new Scene(List.of(wavyGrid(10)));
        }
        String kind = name.startsWith("body") ? "body" : "soup";
        return Scene.builder().patches(BigModels.of(kind, Integer.parseInt(name.substring(4)), 1)).build();
    }

    /**
     * The wavy grid of issue [1 of 5]: {@code flatGrid(points, points)} lifted to
     * {@code z = 0.5 sin(2.6x + 1.2y) cos(1.7y − 0.9x) + 0.25 sin(2xy)} (the perf branch's
     * {@code wavy10} built-in).
     */
    static BezierPatch wavyGrid(int points) {
        double[] net = Models.flatGrid(points, points).copyNet();
        for (int k = 0; k < net.length; k += 3) {
            double x = net[k], y = net[k + 1];
            net[k + 2] = 0.5 * Math.sin(2.6 * x + 1.2 * y) * Math.cos(1.7 * y - 0.9 * x) + 0.25 * Math.sin(2.0 * x * y);
        }
        return new BezierPatch(points - 1, points - 1, net);
    }

    /** Split + BVH of the whole scene. */
    @Benchmark
    public void build(Blackhole bh) {
        bh.consume(SceneIntersector.build(scene, IntersectOptions.defaults()));
    }

    /** One drag step on patch 0: re-split it and refit (or rebuild) the BVH. */
    @Benchmark
    public void edit(Blackhole bh) {
        bh.consume(built.withPatch(0, drags[drag++ & 7]));
    }
}
