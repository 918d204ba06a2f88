package org.beziertracer.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.beziertracer.app.WeldIndex;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;

/**
 * What an edit of a big model costs off the event thread, on a grid of bicubic patches that share
 * their borders: finding the welded points ({@link WeldIndex#build}, after every edit that lands),
 * and the render snapshot after a welded corner moved in four patches — one pass for the four
 * ({@link SceneIntersector#withPatches}) against one {@link SceneIntersector#withPatch} per patch.
 * Time per operation, in ms.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class EditBench {

    @Param({"10000", "100000"})
    public int patchCount;

    Scene scene;
    Scene moved;
    int[] corner;
    SceneIntersector snapshot;

    @Setup(Level.Trial)
    public void setup() {
        scene = Scene.builder().patches(grid(patchCount)).build();
        int side = (int) Math.ceil(Math.sqrt(patchCount));
        int k = (side / 2) * side + side / 2;
        corner = new int[] {k, k + 1, k + side, k + side + 1};
        // The corner P33 of patch k is P03 of k+1, P30 of k+side and P00 of k+side+1: move all four
        List<BezierPatch> patches = new ArrayList<>(scene.patches());
        int[][] ij = {{3, 3}, {0, 3}, {3, 0}, {0, 0}};
        for (int c = 0; c < 4; c++) {
            BezierPatch p = patches.get(corner[c]);
            patches.set(corner[c], p.withPoint(ij[c][0], ij[c][1], p.get(ij[c][0], ij[c][1], 0),
                    p.get(ij[c][0], ij[c][1], 1), 0.5));
        }
        moved = scene.toBuilder().patches(patches).build();
        snapshot = SceneIntersector.build(scene, IntersectOptions.defaults());
    }

    /** {@code count} unit-square bicubic patches in rows, borders shared, gently waved. */
    static List<BezierPatch> grid(int count) {
        int side = (int) Math.ceil(Math.sqrt(count));
        List<BezierPatch> out = new ArrayList<>(count);
        for (int k = 0; k < count; k++) {
            double[] net = new double[48];
            for (int j = 0; j < 4; j++) {
                for (int i = 0; i < 4; i++) {
                    double x = k % side + i / 3.0, y = k / side + j / 3.0;
                    net[3 * (4 * j + i)] = x;
                    net[3 * (4 * j + i) + 1] = y;
                    net[3 * (4 * j + i) + 2] = 0.1 * Math.sin(x) * Math.cos(y);
                }
            }
            out.add(new BezierPatch(3, 3, net));
        }
        return out;
    }

    @Benchmark
    public WeldIndex welds() {
        return WeldIndex.build(scene);
    }

    @Benchmark
    public SceneIntersector snapshotOnePass() {
        return snapshot.withPatches(moved, corner);
    }

    @Benchmark
    public SceneIntersector snapshotPerPatch() {
        SceneIntersector s = snapshot;
        for (int k : corner) {
            s = s.withPatch(k, moved.patches().get(k));
        }
        return s;
    }
}
