package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.accel.RayPacket;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;
import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link SceneIntersector#closestHits} (a packet's rays as one ray batch, the leaves solving the
 * lanes that reach them together, Newton's evaluations in SIMD registers) gives every ray the answer
 * {@link SceneIntersector#closestHit} gives it alone, to the bit — hit, parameters and surface point
 * — and does the same work (solver calls, clip steps, evaluations), with the scalar and the SIMD
 * kernel; on the frames: polynomial patches of degree 3 to 9, the teapot, rational, trimmed
 * and tessellated surfaces.
 */
class BatchTracingTest {

    private static final int W = 160, H = 120;

    @ParameterizedTest
    @ValueSource(strings = {"wavy10", "wavy6", "curved", "teapot", "patch", "sphere", "trimmed-plate", "teapot-room"})
    void aBatchAnswersEveryRayAsItWouldAlone(String model) {
        for (LaneKernel kernel : new LaneKernel[] {Kernels.scalar(), Kernels.named("simd")}) {
            sameAnswers(model, kernel, 0);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"curved", "teapot"})
    void aTessellatedBatchAnswersEveryRayAsItWouldAlone(String model) {
        sameAnswers(model, Kernels.named("simd"), 6);
    }

    @ParameterizedTest
    @ValueSource(strings = {"curved:-2,-4,5", "teapot:-200,-350,450", "wavy10:-8,0,1", "wavy6:-8,0.5,1.2",
            "teapot-room:0,0,0"})
    void aBatchOfShadowRaysAnswersEachAsItWouldAlone(String modelAndLight) {
        String model = modelAndLight.substring(0, modelAndLight.indexOf(':'));
        String[] l = modelAndLight.substring(modelAndLight.indexOf(':') + 1).split(",");
        for (LaneKernel kernel : new LaneKernel[] {Kernels.scalar(), Kernels.named("simd")}) {
            sameShadows(model, new double[] {Double.parseDouble(l[0]), Double.parseDouble(l[1]), Double.parseDouble(l[2])},
                    kernel);
        }
    }

    /**
     * The shadow rays of a packet's first hits toward {@code light} (the scene's first light when it
     * is the origin), made as the renderer makes them, answered as one batch and one by one.
     */
    private static void sameShadows(String model, double[] light, LaneKernel kernel) {
        SceneDocument doc = SceneFiles.load(model);
        RenderJob job = RenderJob.prepare(doc.scene(), doc.settings(),
                RenderOptions.defaults().withThreads(1).withKernel(kernel));
        if (light[0] == 0 && light[1] == 0 && light[2] == 0) {
            var p = doc.scene().lights().get(0).position();
            light = new double[] {p.x(), p.y(), p.z()};
        }
        SceneIntersector si = job.intersector();
        TraceContext camera = si.newContext(), ctx = si.newContext(), alone = si.newContext(), plain = si.newContext();
        int side = RenderWorker.PACKET, n = side * side;
        double[] rays = new double[6 * n], shadowRays = new double[6 * n], normals = new double[3 * n];
        Hit[] hits = new Hit[n], from = new Hit[n];
        SurfacePoint[] points = new SurfacePoint[n], at = new SurfacePoint[n];
        boolean[] found = new boolean[n], blocked = new boolean[n];
        for (int i = 0; i < n; i++) {
            hits[i] = new Hit();
            points[i] = new SurfacePoint();
        }
        RayPacket packet = new RayPacket(), shadows = new RayPacket();
        double eps = 1e-7 * si.sceneSize();
        int shadowCount = 0, blockedCount = 0;
        long laneEvaluations = 0;
        for (int y0 = 0; y0 < H; y0 += side) {
            for (int x0 = 0; x0 < W; x0 += side) {
                for (int i = 0; i < n; i++) {
                    job.camera().generateRay(x0 + i % side + 0.5, y0 + i / side + 0.5, W, H, rays, 6 * i);
                }
                boolean ok = si.gather(camera, packet.of(rays, n), 0, Double.POSITIVE_INFINITY);
                si.closestHits(camera, ok ? packet : null, rays, n, 0, Double.POSITIVE_INFINITY, hits, found, points);
                int count = 0;
                shadows.clear();
                for (int i = 0; i < n; i++) {
                    if (!found[i]) {
                        continue;
                    }
                    SurfacePoint sp = points[i];
                    // the normal on the eye's side, the origin lifted off the surface along it
                    double sgn = sp.nx * rays[6 * i + 3] + sp.ny * rays[6 * i + 4] + sp.nz * rays[6 * i + 5] > 0 ? -1 : 1;
                    double nx = sgn * sp.nx, ny = sgn * sp.ny, nz = sgn * sp.nz;
                    double px = sp.px + eps * nx, py = sp.py + eps * ny, pz = sp.pz + eps * nz;
                    double dx = light[0] - px, dy = light[1] - py, dz = light[2] - pz;
                    if (dx * nx + dy * ny + dz * nz <= 0) {
                        continue;
                    }
                    int q = 6 * count;
                    shadowRays[q] = px; shadowRays[q + 1] = py; shadowRays[q + 2] = pz;
                    shadowRays[q + 3] = dx; shadowRays[q + 4] = dy; shadowRays[q + 5] = dz;
                    normals[3 * count] = nx; normals[3 * count + 1] = ny; normals[3 * count + 2] = nz;
                    from[count] = hits[i];
                    at[count] = points[i];
                    shadows.add(px, py, pz, dx, dy, dz);
                    count++;
                }
                boolean together = count > 1 && si.gather(ctx, shadows, 0, 1 - 1e-9);
                long before = ctx.laneEvaluations;
                si.occludedLeaving(ctx, together ? shadows : null, shadowRays, count, 0, 1 - 1e-9, from, at, normals,
                        blocked);
                laneEvaluations += ctx.laneEvaluations - before;
                for (int j = 0; j < count; j++) {
                    int q = 6 * j;
                    boolean one = si.occludedLeaving(alone, together ? shadows : null, from[j], at[j], normals[3 * j],
                            normals[3 * j + 1], normals[3 * j + 2], shadowRays[q], shadowRays[q + 1], shadowRays[q + 2],
                            shadowRays[q + 3], shadowRays[q + 4], shadowRays[q + 5], 0, 1 - 1e-9);
                    assertEquals(one, blocked[j], model + " (" + kernel.description() + "): shadow ray " + j
                            + " of the packet at (" + x0 + ", " + y0 + ")");
                    // and as its own traversal answers it, its own leaf met in near-first order (a batch
                    // puts that leaf off until the others had their say, RayBatch.putOff)
                    boolean ownTraversal = si.occludedLeaving(plain, null, from[j], at[j], normals[3 * j],
                            normals[3 * j + 1], normals[3 * j + 2], shadowRays[q], shadowRays[q + 1],
                            shadowRays[q + 2], shadowRays[q + 3], shadowRays[q + 4], shadowRays[q + 5], 0, 1 - 1e-9);
                    assertEquals(ownTraversal, blocked[j], model + " (" + kernel.description() + "): shadow ray " + j
                            + " of the packet at (" + x0 + ", " + y0 + ") by its own traversal");
                    shadowCount++;
                    blockedCount += one ? 1 : 0;
                }
            }
        }
        String name = model + " (" + kernel.description() + ")";
        // the same work too (OriginLeaf's per-thread memory of failed proofs could make it differ by
        // the order in which the leaves see the rays; on these frames it does not)
        assertEquals(alone.solverCalls, ctx.solverCalls, name + ": leaf-solver calls");
        assertEquals(alone.clipIterations, ctx.clipIterations, name + ": clip steps");
        assertEquals(alone.evaluations, ctx.evaluations, name + ": evaluations");
        assertTrue(shadowCount > W * H / 20, name + ": only " + shadowCount + " shadow rays");
        assertTrue(blockedCount > 0 && blockedCount < shadowCount, name + ": " + blockedCount + " of " + shadowCount
                + " blocked: the light casts no shadow here, or everything is in shadow");
        assertTrue(laneEvaluations > 0, name + ": no shadow ray was solved in lanes");
    }

    private static void sameAnswers(String model, LaneKernel kernel, int tessellate) {
        SceneDocument doc = SceneFiles.load(model);
        RenderJob job = RenderJob.prepare(doc.scene(), doc.settings(),
                RenderOptions.defaults().withThreads(1).withTessellate(tessellate).withKernel(kernel));
        SceneIntersector si = job.intersector();
        assertEquals(kernel, si.options().kernel());
        TraceContext alone = si.newContext(), together = si.newContext(), traversal = si.newContext();
        int side = RenderWorker.PACKET, n = side * side;
        double[] rays = new double[6 * n];
        Hit[] hits = new Hit[n];
        SurfacePoint[] points = new SurfacePoint[n];
        boolean[] found = new boolean[n];
        for (int i = 0; i < n; i++) {
            hits[i] = new Hit();
            points[i] = new SurfacePoint();
        }
        Hit hit = new Hit(), own = new Hit();
        SurfacePoint sp = new SurfacePoint();
        RayPacket packet = new RayPacket();
        int gathered = 0, hitCount = 0;
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
                    // alone: from the same packet's leaves, as the renderer traced a packet's rays before
                    // batches (the same leaves in the same order, so the same work too)
                    boolean any = si.closestHit(alone, ok ? packet : null, rays[o], rays[o + 1], rays[o + 2], rays[o + 3],
                            rays[o + 4], rays[o + 5], 0, Double.POSITIVE_INFINITY, hit);
                    boolean traversed = si.closestHit(traversal, rays[o], rays[o + 1], rays[o + 2], rays[o + 3],
                            rays[o + 4], rays[o + 5], 0, Double.POSITIVE_INFINITY, own);
                    String where = model + " (" + kernel.description() + ", tessellate " + tessellate
                            + "): ray " + i + " of the packet at (" + x0 + ", " + y0 + ")";
                    assertEquals(any, found[i], where);
                    assertEquals(traversed, found[i], where + ": a traversal of its own");
                    if (traversed) {
                        assertEquals(own.toString(), hits[i].toString(), where + ": a traversal of its own");
                    }
                    if (!any) {
                        continue;
                    }
                    hitCount++;
                    si.surfacePoint(alone, hit, sp);
                    assertEquals(hit.toString(), hits[i].toString(), where);
                    assertEquals(hit.subPatch, hits[i].subPatch, where);
                    assertEquals(hit.b1, hits[i].b1, 0, where);
                    double[] a = {sp.px, sp.py, sp.pz, sp.nx, sp.ny, sp.nz, sp.dpdux, sp.dpdvz};
                    double[] b = {points[i].px, points[i].py, points[i].pz, points[i].nx, points[i].ny, points[i].nz,
                            points[i].dpdux, points[i].dpdvz};
                    for (int c = 0; c < a.length; c++) {
                        assertEquals(a[c], b[c], 0, where + ", surface point component " + c);
                    }
                }
            }
        }
        String name = model + " (" + kernel.description() + ", tessellate " + tessellate + ")";
        int packets = (W / side) * (H / side);
        assertTrue(gathered > packets / 2, name + ": " + gathered + " of " + packets + " packets gathered");
        assertTrue(hitCount > W * H / 20, name + ": only " + hitCount + " rays hit, the model is not in view");
        assertEquals(alone.solverCalls, together.solverCalls, name + ": leaf-solver calls");
        assertEquals(alone.clipIterations, together.clipIterations, name + ": clip steps");
        assertEquals(alone.evaluations, together.evaluations, name + ": evaluations");
        // a packet's ray alone is a batch of one: the same stages, the same lane evaluations
        assertEquals(alone.laneEvaluations, together.laneEvaluations, name + ": evaluations in lanes");
        assertEquals(0, traversal.laneEvaluations, name + ": a ray of no packet traverses alone");
        if (tessellate == 0 && !model.equals("sphere") && !model.equals("trimmed-plate")) {
            // the polynomial patches' single-root leaves were solved several lanes at a time
            assertTrue(together.laneEvaluations > together.evaluations / 3,
                    name + ": " + together.laneEvaluations + " of " + together.evaluations + " evaluations in lanes");
        } else {
            // rational patches have no power form; trimmed leaves solve each lane alone (the trim
            // test may send a lane's search on past its first root)
            assertEquals(0, together.laneEvaluations, name + ": no lanes");
        }
    }
}
