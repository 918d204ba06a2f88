package org.beziertracer.bench;

import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.model.BezierPatch;
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
 * One ray against one patch: a random height field of degree 3 or 6 (as in the intersect
 * tests), pre-split with the default options and a sub-patch BVH (the product configuration), so
 * the three solvers start where they would in a scene. Ray sets:
 * <ul>
 *   <li>{@code hit}: from random points above the patch toward {@code S(u*,v*)};</li>
 *   <li>{@code miss}: from above toward points just outside the patch footprint, kept only when
 *       the clipping solver reports a miss (they still enter the control boxes near the edge);</li>
 *   <li>{@code grazing}: through {@code S(u*,v*)} almost along the tangent plane (2° off).</li>
 * </ul>
 * Time is per ray.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class RayPatchBench {

    @Param({"3", "6"})
    public int degree;

    @Param({"CLIPPING", "NEWTON", "SUBDIVISION"})
    public Method method;

    @Param({"hit", "miss", "grazing"})
    public String rays;

    SceneIntersector si;
    TraceContext ctx;
    Hit hit;
    double[] set;

    @Setup
    public void setup() {
        Random rnd = new Random(1234 + degree);
        BezierPatch patch = Fixtures.heightField(rnd, degree, degree, 2, 0.3);
        Scene scene = new Scene(List.of(patch));
        si = SceneIntersector.build(scene, IntersectOptions.defaults().withMethod(method));
        SceneIntersector reference = SceneIntersector.build(scene, IntersectOptions.defaults());
        ctx = si.newContext();
        hit = new Hit();
        set = new double[6 * Fixtures.RAYS];
        double[] pn = new double[6];
        TraceContext rc = reference.newContext();
        int k = 0;
        while (k < Fixtures.RAYS) {
            double u = 0.02 + 0.96 * rnd.nextDouble(), v = 0.02 + 0.96 * rnd.nextDouble();
            Fixtures.pointAndNormal(patch, u, v, pn);
            double ox = 3 * (rnd.nextDouble() - 0.5), oy = 3 * (rnd.nextDouble() - 0.5), oz = 2 + rnd.nextDouble();
            switch (rays) {
                case "hit" -> Fixtures.put(set, k++, ox, oy, oz, pn[0] - ox, pn[1] - oy, pn[2] - oz);
                case "miss" -> {
                    double side = rnd.nextBoolean() ? 1 : -1;
                    double tx = side * (1.02 + 0.15 * rnd.nextDouble()), ty = 2 * (rnd.nextDouble() - 0.5);
                    if (rnd.nextBoolean()) {
                        double s = tx;
                        tx = ty;
                        ty = s;
                    }
                    double tz = 0.3 * (rnd.nextDouble() - 0.5);
                    double dx = tx - ox, dy = ty - oy, dz = tz - oz;
                    if (!reference.closestHit(rc, ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit)) {
                        Fixtures.put(set, k++, ox, oy, oz, dx, dy, dz);
                    }
                }
                default -> {
                    // A tangent direction tilted 2 degrees toward the normal, through the point
                    double a = 2 * Math.PI * rnd.nextDouble();
                    double tx = Math.cos(a), ty = Math.sin(a), tz = 0;
                    double dot = tx * pn[3] + ty * pn[4] + tz * pn[5];
                    tx -= dot * pn[3];
                    ty -= dot * pn[4];
                    tz -= dot * pn[5];
                    double len = Math.sqrt(tx * tx + ty * ty + tz * tz);
                    double tilt = Math.toRadians(2);
                    double dx = Math.cos(tilt) * tx / len - Math.sin(tilt) * pn[3];
                    double dy = Math.cos(tilt) * ty / len - Math.sin(tilt) * pn[4];
                    double dz = Math.cos(tilt) * tz / len - Math.sin(tilt) * pn[5];
                    Fixtures.put(set, k++, pn[0] - 3 * dx, pn[1] - 3 * dy, pn[2] - 3 * dz, dx, dy, dz);
                }
            }
        }
    }

    @Benchmark
    @OperationsPerInvocation(Fixtures.RAYS)
    public void closestHit(Blackhole bh) {
        double[] r = set;
        for (int k = 0; k < Fixtures.RAYS; k++) {
            int o = 6 * k;
            boolean found = si.closestHit(ctx, r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5],
                    0, Double.POSITIVE_INFINITY, hit);
            bh.consume(found ? hit.t : -1);
        }
    }
}
