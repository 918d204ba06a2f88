package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * A shadow ray's Newton on the patch it leaves starts from the evaluation its hit was shaded with
 * ({@link RayPatchNewton}, {@code fromOrigin}): that evaluation is the patch's own at the start
 * (the point within the solver's extrapolation, the derivatives within a step's worth of
 * curvature), on random patches of degree 1..15; it is not used for a
 * piece of a free-form surface (whose shading derivatives are taken with respect to the
 * surface's parameters), nor at another point, nor for a ray that leaves no kept point.
 */
class OriginEvaluationTest {

    @Test
    void theFirstIterateIsThePatchsOwnEvaluationAtTheOrigin() {
        Random rnd = new Random(29);
        int seeded = 0;
        for (int trial = 0; trial < 60; trial++) {
            int n = 1 + rnd.nextInt(15), m = 1 + rnd.nextInt(15);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, 4, 0.3 + rnd.nextDouble());
            boolean piece = trial % 4 == 3;
            if (piece) {
                patch = new BezierPatch(n, m, patch.copyNet(), null, new PatchDomain(1, 1.5, -2, 2, null), null);
            }
            SceneIntersector si = SceneIntersector.build(new Scene(List.of(patch)), IntersectOptions.defaults());
            SubPatchTable tab = ((PatchLeaves) si.leaves).table;
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            SurfacePoint sp = new SurfacePoint();
            double ox = 4 * rnd.nextDouble() - 2, oy = 4 * rnd.nextDouble() - 2;
            if (!si.closestHit(ctx, ox, oy, 9, 0.1 * rnd.nextGaussian(), 0.1 * rnd.nextGaussian(), -1, 0,
                    Double.POSITIVE_INFINITY, hit)) {
                continue;
            }
            si.surfacePoint(ctx, hit, sp);
            double u = piece ? SurfaceParameters.s(tab.patchDomain, 0, hit.u) : hit.u;
            double v = piece ? SurfaceParameters.t(tab.patchDomain, 0, hit.v) : hit.v;
            double[] fresh = new double[9];
            tab.evaluatePatch(0, u, v, fresh, new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH]);
            // A shadow ray leaves the hit upward
            ctx.setRay(sp.px, sp.py, sp.pz + 1e-6, 0.3, 0.2, 1);
            ctx.leaving(hit.subPatch, hit.u, hit.v, sp, 0, 0, 1);
            firstIterate(ctx, tab, u, v);
            String where = "trial " + trial + " (degree " + n + "×" + m + (piece ? ", a piece" : "") + ")";
            for (int c = 0; c < 9; c++) {
                if (piece) {
                    assertEquals(fresh[c], ctx.eval[c], 0, where + ": a piece evaluates afresh");
                } else {
                    // The point within the extrapolation's error; the derivatives may be those of the
                    // iterate before an extrapolated last step (they move by at most M times the step)
                    double within = c < 3 ? 1e-9 : 1e-5;
                    assertEquals(fresh[c], ctx.eval[c], within * (1 + Math.abs(fresh[c])), where + ", component " + c);
                }
            }
            seeded += piece ? 0 : 1;
            // Elsewhere, or with no kept point, the patch is evaluated afresh: exactly
            double u2 = Math.min(1, u + 1e-3);
            tab.evaluatePatch(0, u2, v, fresh, new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH]);
            firstIterate(ctx, tab, u2, v);
            for (int c = 0; c < 9; c++) {
                assertEquals(fresh[c], ctx.eval[c], 0, where + ": another point");
            }
            ctx.leaving(hit.subPatch, hit.u, hit.v, sp.px + 1, sp.py, sp.pz, 0, 0, 1);   // no derivatives kept
            tab.evaluatePatch(0, u, v, fresh, new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH]);
            firstIterate(ctx, tab, u, v);
            for (int c = 0; c < 9; c++) {
                assertEquals(fresh[c], ctx.eval[c], 0, where + ": a point without derivatives");
            }
        }
        assertTrue(seeded > 20, seeded + " seeded starts");
    }

    @Test
    void aPieceWhoseParametersCoincideWithThePatchsIsStillEvaluatedAfresh() {
        // Domain [0,1]×[0,2]: at (0, 0) the surface's and the patch's parameters agree, but the
        // shading derivatives are taken along the surface's v, half the patch's
        Random rnd = new Random(31);
        BezierPatch net = RandomPatches.heightField(rnd, 3, 3, 4, 0.8);
        BezierPatch piece = new BezierPatch(3, 3, net.copyNet(), null, new PatchDomain(0, 1, 0, 2, null), null);
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(piece)), IntersectOptions.defaults());
        SubPatchTable tab = ((PatchLeaves) si.leaves).table;
        TraceContext ctx = si.newContext();
        double[] corner = new double[9];
        tab.evaluatePatch(0, 0, 0, corner, new double[org.beziertracer.geometry.DeCasteljau.SCRATCH_LENGTH]);
        SurfacePoint sp = new SurfacePoint();
        sp.px = corner[0]; sp.py = corner[1]; sp.pz = corner[2];
        sp.dpdux = corner[3]; sp.dpduy = corner[4]; sp.dpduz = corner[5];
        sp.dpdvx = corner[6] / 2; sp.dpdvy = corner[7] / 2; sp.dpdvz = corner[8] / 2;
        ctx.setRay(sp.px, sp.py, sp.pz + 1e-6, 0.3, 0.2, 1);
        ctx.leaving(tab.firstOf[0], 0, 0, sp, 0, 0, 1);
        firstIterate(ctx, tab, 0, 0);
        for (int c = 0; c < 9; c++) {
            assertEquals(corner[c], ctx.eval[c], 0, "component " + c);
        }
    }

    /** Newton's first iterate at (u, v) and no step: what it takes as the patch there. */
    private static void firstIterate(TraceContext ctx, SubPatchTable tab, double u, double v) {
        RayPatchNewton.solve(ctx, tab, 0, u, v, 0, 0, 1, 0, 1, 1e-9);
    }
}
