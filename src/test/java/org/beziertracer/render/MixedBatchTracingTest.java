package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.accel.RayPacket;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.MixedScenes;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link SceneIntersector#closestHits} on a scene that mixes patches, triangle meshes and spheres in
 * one BVH: every ray's answer (hit, parameters, surface point) is the one
 * {@link SceneIntersector#closestHit} gives it alone, to the bit, and the work is the same.
 */
class MixedBatchTracingTest {

    private static final int W = 160, H = 120;

    @ParameterizedTest
    @ValueSource(ints = {0, 4})
    void aBatchOnAMixedSceneAnswersEveryRayAsItWouldAlone(int tessellate) {
        for (LaneKernel kernel : new LaneKernel[] {Kernels.scalar(), Kernels.named("simd")}) {
            sameAnswers(MixedScenes.teapotOnFloor(5, true), kernel, tessellate);
        }
    }

    private static void sameAnswers(Scene scene, LaneKernel kernel, int tessellate) {
        RenderJob job = RenderJob.prepare(scene, RenderSettings.defaults(),
                RenderOptions.defaults().withThreads(1).withTessellate(tessellate).withKernel(kernel));
        SceneIntersector si = job.intersector();
        TraceContext alone = si.newContext(), together = si.newContext();
        int side = RenderWorker.PACKET, n = side * side;
        double[] rays = new double[6 * n];
        Hit[] hits = new Hit[n];
        SurfacePoint[] points = new SurfacePoint[n];
        boolean[] found = new boolean[n];
        for (int i = 0; i < n; i++) {
            hits[i] = new Hit();
            points[i] = new SurfacePoint();
        }
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        RayPacket packet = new RayPacket();
        int gathered = 0;
        int[] kinds = new int[4];
        for (int y0 = 0; y0 < H; y0 += side) {
            for (int x0 = 0; x0 < W; x0 += side) {
                for (int i = 0; i < n; i++) {
                    job.camera().generateRay(x0 + i % side + 0.5, y0 + i / side + 0.5, W, H, rays, 6 * i);
                }
                boolean ok = si.gather(together, packet.of(rays, n), 0, Double.POSITIVE_INFINITY);
                gathered += ok ? 1 : 0;
                si.closestHits(together, ok ? packet : null, rays, n, 0, Double.POSITIVE_INFINITY, hits, found, points);
                for (int i = 0; i < n; i++) {
                    int o = 6 * i;
                    boolean any = si.closestHit(alone, ok ? packet : null, rays[o], rays[o + 1], rays[o + 2],
                            rays[o + 3], rays[o + 4], rays[o + 5], 0, Double.POSITIVE_INFINITY, hit);
                    String where = "tessellate " + tessellate + " (" + kernel.description() + "): ray " + i
                            + " of the packet at (" + x0 + ", " + y0 + ")";
                    assertEquals(any, found[i], where);
                    if (!any) {
                        continue;
                    }
                    kinds[hit.kind]++;
                    si.surfacePoint(alone, hit, sp);
                    assertEquals(hit.toString(), hits[i].toString(), where);
                    assertEquals(hit.subPatch, hits[i].subPatch, where);
                    assertEquals(hit.b1, hits[i].b1, 0, where);
                    assertEquals(hit.b2, hits[i].b2, 0, where);
                    double[] a = {sp.px, sp.py, sp.pz, sp.nx, sp.ny, sp.nz, sp.dpdux, sp.dpdvz};
                    double[] b = {points[i].px, points[i].py, points[i].pz, points[i].nx, points[i].ny, points[i].nz,
                            points[i].dpdux, points[i].dpdvz};
                    for (int c = 0; c < a.length; c++) {
                        assertEquals(a[c], b[c], 0, where + ", surface point component " + c);
                    }
                }
            }
        }
        String name = "tessellate " + tessellate + " (" + kernel.description() + ")";
        assertTrue(gathered > 0, name + ": no packet gathered");
        assertTrue(kinds[Hit.PATCH] > 100 && kinds[Hit.TRIANGLE] > 100 && kinds[Hit.SPHERE] > 10,
                name + ": hits by kind " + java.util.Arrays.toString(kinds));
        assertEquals(alone.solverCalls, together.solverCalls, name + ": leaf-solver calls");
        assertEquals(alone.evaluations, together.evaluations, name + ": evaluations");
    }
}
