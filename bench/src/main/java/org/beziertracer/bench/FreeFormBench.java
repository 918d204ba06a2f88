package org.beziertracer.bench;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
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
 * The cost per ray of rational and trimmed surfaces against their plain twins, with Bézier
 * clipping and the default sub-patch BVH ({@code closestHit} and {@code occluded}, seeded random
 * rays through the model's box):
 * <ul>
 *   <li>{@code polynomial} / {@code rational}: a 4×4 tiling of wavy bicubic patches, the second
 *       with the same control points and weights drawn log-uniformly from [0.7, 1.4] — another,
 *       wavier surface (issue 11: at most 1.3×);</li>
 *   <li>{@code reparametrized}: the polynomial tiles as rational patches with weights
 *       {@code α^i·β^j} ({@code α, β} per patch in [0.8, 1.25]): the very same surfaces in a rational
 *       parametrization (a Möbius reparametrization), so it measures what the rational machinery
 *       itself costs;</li>
 *   <li>{@code untrimmed} / {@code trimmed}: the built-in {@code trimmed-plate} without and with
 *       its trim loops (an outer loop of 8 curves and 3 holes; issue 11: at most 1.2×).</li>
 * </ul>
 * Run with {@code -prof gc}: every case must allocate ~0 B/op.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class FreeFormBench {

    @Param({"polynomial", "rational", "reparametrized", "untrimmed", "trimmed"})
    public String surface;

    SceneIntersector si;
    TraceContext ctx;
    Hit hit;
    double[] rays;

    @Setup
    public void setup() {
        Scene scene = switch (surface) {
            case "polynomial" -> tiles(false);
            case "rational" -> tiles(true);
            case "reparametrized" -> reparametrized(tiles(false));
            case "untrimmed" -> untrimmedPlate();
            case "trimmed" -> Models.load("trimmed-plate");
            default -> throw new IllegalArgumentException(surface);
        };
        si = SceneIntersector.build(scene, IntersectOptions.defaults());
        ctx = si.newContext();
        hit = new Hit();
        rays = Fixtures.randomRays(scene.controlBounds(), Fixtures.RAYS, 1);
    }

    /** 4×4 wavy bicubic patches side by side; with weights in [0.7, 1.4] when rational (same seed either way). */
    static Scene tiles(boolean rational) {
        Random rnd = new Random(11);
        List<BezierPatch> patches = new ArrayList<>();
        for (int b = 0; b < 4; b++) {
            for (int a = 0; a < 4; a++) {
                double[] net = Fixtures.heightField(rnd, 3, 3, 2, 0.3).copyNet();
                for (int k = 0; k < net.length; k += 3) {
                    net[k] += 2 * a;
                    net[k + 1] += 2 * b;
                }
                double[] w = new double[16];
                for (int k = 0; k < 16; k++) {
                    w[k] = 0.7 * Math.pow(2, rnd.nextDouble());
                }
                patches.add(new BezierPatch(3, 3, net, rational ? w : null, null, null));
            }
        }
        return new Scene(patches);
    }

    /**
     * Each patch with weights {@code α^i·β^j}: the same surface, rationally reparametrized
     * (Farin, <i>Curves and Surfaces for CAGD</i>, rational Bézier curves: standard form).
     */
    static Scene reparametrized(Scene polynomial) {
        Random rnd = new Random(12);
        List<BezierPatch> patches = new ArrayList<>();
        for (BezierPatch p : polynomial.patches()) {
            double alpha = 0.8 * Math.pow(1.5625, rnd.nextDouble()), beta = 0.8 * Math.pow(1.5625, rnd.nextDouble());
            double[] w = new double[p.pointCount()];
            for (int j = 0; j <= p.degreeV(); j++) {
                for (int i = 0; i <= p.degreeU(); i++) {
                    w[j * (p.degreeU() + 1) + i] = Math.pow(alpha, i) * Math.pow(beta, j);
                }
            }
            patches.add(new BezierPatch(p.degreeU(), p.degreeV(), p.copyNet(), w, null, null));
        }
        return new Scene(patches);
    }

    /** The trimmed plate's surface without its trim loops. */
    static Scene untrimmedPlate() {
        BezierPatch p = Models.load("trimmed-plate").patches().get(0);
        return new Scene(List.of(new BezierPatch(p.degreeU(), p.degreeV(), p.copyNet())));
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
