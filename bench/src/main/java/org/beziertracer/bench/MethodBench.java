package org.beziertracer.bench;

import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.Aabb;
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
 * The three ray–patch methods compared (docs/methods.md): {@code closestHit} per ray, each method
 * with its own default leaves ({@code IntersectOptions.defaults().withMethod(method)}).
 * <ul>
 *   <li>{@code scene = teapot}: the rays of {@code trace teapot --random} (seeded), as
 *       {@link SceneBench};</li>
 *   <li>{@code scene = 1 .. 15}: one wavy height field of that degree in u and v (as the intersect
 *       tests' {@code RandomPatches.heightField}, seed fixed per degree), rays as for the teapot:
 *       from a sphere of radius its box diagonal toward random points of its box, so that many
 *       hit, some at grazing angles.</li>
 * </ul>
 * Time is per ray.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class MethodBench {

    @Param({"CLIPPING", "NEWTON", "SUBDIVISION"})
    public Method method;

    @Param({"teapot", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15"})
    public String scene;

    SceneIntersector si;
    TraceContext ctx;
    Hit hit;
    double[] rays;

    @Setup
    public void setup() {
        Scene s;
        if (scene.equals("teapot")) {
            s = Fixtures.teapots(32);
            rays = Fixtures.randomRays(s.controlBounds(), Fixtures.RAYS, 1);
        } else {
            int degree = Integer.parseInt(scene);
            s = new Scene(List.of(Fixtures.heightField(new Random(4000 + degree), degree, degree, 2, 0.3)));
            Aabb box = s.controlBounds();
            rays = Fixtures.randomRays(box, Fixtures.RAYS, 7 + degree);
        }
        si = SceneIntersector.build(s, IntersectOptions.defaults().withMethod(method));
        ctx = si.newContext();
        hit = new Hit();
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void closestHit(Blackhole bh) {
        Fixtures.closestHits(si, ctx, hit, rays, bh);
    }
}
