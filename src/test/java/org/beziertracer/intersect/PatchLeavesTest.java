package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.NORMAL;
import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * What every patch solver shares ({@link PatchLeaves}): a piece of a free-form surface (a domain
 * other than [0,1]²) is met where the same net with the plain domain is, and reports the surface's
 * (u,v) with derivatives taken with respect to them; the solver's last evaluation is kept for the
 * hit when it was at the root; solver calls are counted; an edit remakes the leaves of the same
 * solver.
 */
class PatchLeavesTest {

    private static BezierPatch withDomain(BezierPatch p, PatchDomain d) {
        return new BezierPatch(p.degreeU(), p.degreeV(), p.copyNet(), null, d, null);
    }

    @Test
    void aPieceOfASurfaceIsMetLikeItsNetAndReportsTheSurfacesParametersAndDerivatives() {
        Random rnd = new Random(51);
        PatchDomain domain = new PatchDomain(2, 2.5, -3, 1, null); // widths 1/2 and 4
        for (Method method : Method.values()) {
            int hits = 0;
            for (int trial = 0; trial < 6; trial++) {
                BezierPatch plain = RandomPatches.heightField(rnd, 2 + rnd.nextInt(3), 2 + rnd.nextInt(3), 4, 0.5);
                IntersectOptions io = IntersectOptions.defaults().withMethod(method);
                SceneIntersector a = SceneIntersector.build(new Scene(List.of(plain)), io);
                SceneIntersector b = SceneIntersector.build(new Scene(List.of(withDomain(plain, domain))), io);
                TraceContext ca = a.newContext(), cb = b.newContext();
                Hit ha = new Hit(), hb = new Hit();
                SurfacePoint pa = new SurfacePoint(), pb = new SurfacePoint();
                for (int r = 0; r < 40; r++) {
                    double ox = 3 * (rnd.nextDouble() - 0.5), oy = 3 * (rnd.nextDouble() - 0.5);
                    double dx = 0.3 * rnd.nextGaussian(), dy = 0.3 * rnd.nextGaussian();
                    boolean hitA = a.closestHit(ca, ox, oy, 5, dx, dy, -1, 0, Double.POSITIVE_INFINITY, ha);
                    boolean hitB = b.closestHit(cb, ox, oy, 5, dx, dy, -1, 0, Double.POSITIVE_INFINITY, hb);
                    String where = method + " trial " + trial + " ray " + r;
                    assertEquals(hitA, hitB, where);
                    if (!hitA) {
                        continue;
                    }
                    hits++;
                    assertEquals(ha.t, hb.t, 0, where);
                    assertEquals(2 + 0.5 * ha.u, hb.u, ROUNDING, where);
                    assertEquals(-3 + 4 * ha.v, hb.v, ROUNDING, where);
                    a.surfacePoint(ca, ha, pa);
                    b.surfacePoint(cb, hb, pb);
                    assertEquals(pa.px, pb.px, ROUNDING, where);
                    assertEquals(pa.py, pb.py, ROUNDING, where);
                    assertEquals(pa.pz, pb.pz, ROUNDING, where);
                    // The derivatives may come from an evaluation next to the hit (a last Newton
                    // step taken unevaluated, RayPatchNewton.extrapolate), on either side: within
                    // twice that step's bound on how far they move, in each surface's parameters
                    double moved = 2 * Math.sqrt(2 * ((PatchLeaves) a.leaves).table.patchCurvature[0]
                            * RayPatchNewton.EXTRAPOLATED * PatchLeaves.RELATIVE_TOLERANCE * a.sceneSize()) + ROUNDING;
                    assertEquals(pa.dpdux / 0.5, pb.dpdux, moved / 0.5, where);
                    assertEquals(pa.dpduy / 0.5, pb.dpduy, moved / 0.5, where);
                    assertEquals(pa.dpduz / 0.5, pb.dpduz, moved / 0.5, where);
                    assertEquals(pa.dpdvx / 4, pb.dpdvx, moved / 4, where);
                    assertEquals(pa.dpdvy / 4, pb.dpdvy, moved / 4, where);
                    assertEquals(pa.dpdvz / 4, pb.dpdvz, moved / 4, where);
                    assertEquals(pa.nx, pb.nx, NORMAL, where);
                    assertEquals(pa.ny, pb.ny, NORMAL, where);
                    assertEquals(pa.nz, pb.nz, NORMAL, where);
                }
            }
            assertTrue(hits > 100, method + ": " + hits + " hits");
        }
    }

    /**
     * When Newton's last evaluation is at its root, it is kept for the hit and is bit for bit the
     * surface's evaluation at the hit (which the surface point then reuses).
     */
    @Test
    void theSolversEvaluationAtTheRootIsKeptForTheHit() {
        Random rnd = new Random(52);
        BezierPatch patch = RandomPatches.heightField(rnd, 3, 3, 4, 0.5);
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(patch)),
                IntersectOptions.defaults().withMethod(Method.NEWTON));
        PatchLeaves leaves = (PatchLeaves) si.leaves;
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        double[] fresh = new double[9];
        int hits = 0, kept = 0;
        for (int r = 0; r < 300; r++) {
            double ox = 3 * (rnd.nextDouble() - 0.5), oy = 3 * (rnd.nextDouble() - 0.5);
            if (!si.closestHit(ctx, ox, oy, 5, 0.2 * rnd.nextGaussian(), 0.2 * rnd.nextGaussian(), -1, 0, 100, hit)) {
                continue;
            }
            hits++;
            // (an earlier, farther hit on the same patch may have left its evaluation: then u, v differ)
            if (ctx.hitEvalPatch == hit.index && ctx.hitEvalU == hit.u && ctx.hitEvalV == hit.v) {
                kept++;
                leaves.table.evaluatePatch(0, hit.u, hit.v, fresh, ctx.scratch); // the solver's own kernel
                assertArrayEquals(fresh, ctx.hitEval, "ray " + r);
            }
        }
        // 117 of 231 on 2026-12-02: Newton often stops on a step it did not evaluate again
        assertTrue(hits > 100 && kept > 0.3 * hits, kept + " of " + hits + " hits kept the solver's evaluation");
    }

    /** Every leaf the traversal hands to the solver is one solver call, in both queries. */
    @Test
    void solverCallsAreCounted() {
        BezierPatch flat = new BezierPatch(1, 1, new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(flat, flat.withPoint(0, 0, 0, 0, 0.5))),
                IntersectOptions.defaults().withBvh(false));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        assertTrue(si.closestHit(ctx, 0.6, 0.3, 1, 0, 0, -1, 0, 10, hit));
        assertEquals(2, ctx.solverCalls, "both whole-patch boxes are on the ray");
        assertTrue(si.occluded(ctx, 0.6, 0.3, 1, 0, 0, -1, 0, 10));
        assertTrue(ctx.solverCalls == 3 || ctx.solverCalls == 4, "one or two more: " + ctx.solverCalls);
        long before = ctx.solverCalls;
        assertTrue(!si.closestHit(ctx, 5, 5, 1, 0, 0, -1, 0, 10, hit));
        assertEquals(before, ctx.solverCalls, "no box on the ray, no call");
    }

    /**
     * Editing through the leaves themselves (one patch, or several) gives the same solver over the
     * table re-split for that patch along its old halvings (which keeps its scene-relative split
     * size and its leaves where they still fit, so it need not match a fresh build's leaves), with
     * the tolerance of the edited scene's size.
     */
    @Test
    void anEditRemakesTheLeavesOfTheSameSolverAsAFreshBuild() {
        Random rnd = new Random(53);
        Scene scene = SceneIntersectorTest.wildScene(rnd, 6, 4);
        for (Method method : Method.values()) {
            IntersectOptions io = IntersectOptions.defaults().withMethod(method);
            SceneIntersector si = SceneIntersector.build(scene, io);
            PatchLeaves leaves = (PatchLeaves) si.leaves;
            Scene edited = scene.withPatch(2, scene.patches().get(2).withPoint(1, 1, 9, 9, 9));
            double size = SceneIntersector.build(edited, io).sceneSize();
            PatchLeaves fresh = method.leaves.create(leaves.table.withPatches(new int[] {2}, List.of(edited.patches().get(2)), true),
                    PatchLeaves.RELATIVE_TOLERANCE * size);
            for (Leaves remade : List.of(leaves.withPatch(edited, 2, size), leaves.withPatches(edited, new int[] {2}, size, true))) {
                assertSame(leaves.getClass(), remade.getClass(), method.label());
                assertEquals(fresh.count(), remade.count(), method.label());
                assertArrayEquals(fresh.bounds(0, fresh.count()), remade.bounds(0, remade.count()), method.label());
                assertEquals(fresh.bytes(), remade.bytes(), method.label());
                assertEquals(fresh.tolerance, ((PatchLeaves) remade).tolerance, 0, method.label());
                assertEquals(fresh.firstLeaf(3), remade.firstLeaf(3));
                assertEquals(fresh.leafCount(2), remade.leafCount(2));
            }
        }
    }
}
