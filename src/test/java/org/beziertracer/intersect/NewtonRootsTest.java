package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROOT_UV;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * The Newton kernels judged by what they return, not how they get there: the root a refined
 * solve ends on, its t along rays of any length, the evaluation kept with it, rational patches,
 * and the Newton method's nearest root, interval and misses through the scene.
 */
class NewtonRootsTest {

    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];

    /** t of the surface point S(u,v) of patch 0 projected on the ray: (S − o)·d / |d|². */
    private double tOf(SubPatchTable tab, TraceContext ctx, double u, double v) {
        double[] s = new double[3];
        DeCasteljau.evaluate(tab.patchNets, 0, tab.patchDegreeU[0], tab.patchDegreeV[0], 3, u, v, s, 0, scratch);
        double d2 = ctx.dx * ctx.dx + ctx.dy * ctx.dy + ctx.dz * ctx.dz;
        return ((s[0] - ctx.ox) * ctx.dx + (s[1] - ctx.oy) * ctx.dy + (s[2] - ctx.oz) * ctx.dz) / d2;
    }

    /**
     * From a root accepted at a loose residual (1e-6 of a patch of size 4), one refine step makes
     * it exact: Newton converges quadratically near a simple root. The refined (u,v) is the aimed
     * point, t is its t along a ray of any length, and the kept evaluation is the surface there.
     */
    @Test
    void refineTurnsALooseRootIntoAnExactOne() {
        Random rnd = new Random(1986);
        TraceContext ctx = new TraceContext();
        double[] s = new double[3], e = new double[9];
        int refined = 0;
        for (int trial = 0; trial < 400; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            SubPatchTable tab = SubPatchTable.build(List.of(RandomPatches.heightField(rnd, n, m, 4, 0.3)),
                    SplitOptions.wholePatches());
            double us = 0.1 + 0.8 * rnd.nextDouble(), vs = 0.1 + 0.8 * rnd.nextDouble();
            DeCasteljau.evaluate(tab.patchNets, 0, n, m, 3, us, vs, s, 0, scratch);
            double ox = s[0] + rnd.nextGaussian(), oy = s[1] + rnd.nextGaussian(), oz = 6;
            double k = Math.pow(10, rnd.nextInt(7) - 3);
            ctx.setRay(ox, oy, oz, k * (s[0] - ox), k * (s[1] - oy), k * (s[2] - oz)); // t* = 1/k
            if (RayPatchNewton.solve(ctx, tab, 0, us + 0.03, vs - 0.03, 12, 0, 1, 0, 1, 1e-6) != RayPatchNewton.CONVERGED) {
                continue;
            }
            double before = RayPatchNewtonTest.residual(ctx);
            if (before <= 1e-3 * 1e-12) {
                continue; // already exact: refine rightly does nothing
            }
            RayPatchNewton.refine(ctx, tab, 0, 0, 1, 0, 1, 1e-12);
            double after = RayPatchNewtonTest.residual(ctx);
            String where = "trial " + trial + " degree " + n + "x" + m + " residual " + before + " -> " + after;
            assertTrue(after <= Math.max(1e-3 * before, 1e-13), where);
            assertEquals(us, ctx.rootU, ROOT_UV, where);
            assertEquals(vs, ctx.rootV, ROOT_UV, where);
            assertEquals(1 / k, ctx.rootT, ROOT_T * 4 / k, where);
            assertEquals(tOf(tab, ctx, ctx.rootU, ctx.rootV), ctx.rootT, 1e-12 / k, "t of the refined point: " + where);
            DeCasteljau.evaluateWithDerivatives(tab.patchNets, 0, n, m, ctx.rootU, ctx.rootV, e, scratch);
            RayPatchNewtonTest.assertKeptEvaluation(e, ctx.eval, tab.patchCurvature[0], 1e-12,
                    "evaluation kept at the refined root: " + where);
            refined++;
        }
        assertTrue(refined > 250, "refined " + refined);
    }

    /** A refine whose step would leave the box keeps the root it was given. */
    @Test
    void refineStaysInItsBox() {
        SubPatchTable tab = SubPatchTable.build(List.of(ClippingStepsTest.trough()), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        ctx.setRay(-1, 0.5, 0.09, 1, 0, 0); // roots at u = 0.2 and 0.8
        assertEquals(RayPatchNewton.CONVERGED, RayPatchNewton.solve(ctx, tab, 0, 0.75, 0.5, 12, 0, 1, 0, 1, 1e-4));
        double u = ctx.rootU, t = ctx.rootT;
        assertTrue(Math.abs(u - 0.8) > 1e-9, "a loose root " + u);
        RayPatchNewton.refine(ctx, tab, 0, 0, Math.min(u, 0.8) - 1e-12, 0, 1, 1e-12);
        assertEquals(u, ctx.rootU, 0, "the step towards 0.8 leaves [0, u]");
        assertEquals(t, ctx.rootT, 0);
        RayPatchNewton.refine(ctx, tab, 0, 0, 1, 0, 1, 1e-12);
        assertTrue(Math.abs(ctx.rootU - 0.8) < 1e-3 * Math.abs(u - 0.8), "refined in [0, 1]: " + ctx.rootU);
        assertTrue(Math.abs(ctx.rootT - 1.8) < 1e-3 * Math.abs(t - 1.8), "refined t " + ctx.rootT);
    }

    /**
     * Newton on a rational patch (the arc of {@link ClippingStepsTest#arc()}: a cylinder piece)
     * converges to the exact circle hit, its t along the ray, from a start near it.
     */
    @Test
    void newtonOnARationalPatchFindsTheCircle() {
        Random rnd = new Random(1987);
        SubPatchTable tab = SubPatchTable.build(List.of(ClippingStepsTest.arc()), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        int converged = 0;
        for (int r = 0; r < 300; r++) {
            double phi = Math.PI * (0.3 + 0.4 * rnd.nextDouble()), z = 0.2 + 0.6 * rnd.nextDouble();
            double ox = 3 * Math.cos(phi) + rnd.nextGaussian(), oy = 3 * Math.sin(phi), oz = z + 0.3 * rnd.nextGaussian();
            double tx = Math.cos(phi), ty = Math.sin(phi);
            double k = 0.1 + 3 * rnd.nextDouble();
            double dx = k * (tx - ox), dy = k * (ty - oy), dz = k * (z - oz);
            ctx.setRay(ox, oy, oz, dx, dy, dz);
            double want = ClippingStepsTest.arcHit(ox, oy, oz, dx, dy, dz);
            // the arc's parameter of the aimed angle is near (3π/4 − φ)/(π/2); start a little off it
            double u0 = (0.75 * Math.PI - phi) / (0.5 * Math.PI) + 0.02 * rnd.nextGaussian();
            int result = RayPatchNewton.solve(ctx, tab, 0, Math.min(1, Math.max(0, u0)), 0.5, 12, 0, 1, 0, 1, 1e-12);
            if (result != RayPatchNewton.CONVERGED) {
                continue;
            }
            converged++;
            String where = "ray " + r + " phi " + phi;
            assertEquals(want, ctx.rootT, ROOT_T * 3 / k, where);
            assertEquals(z, ctx.oz + ctx.rootT * ctx.dz, ROOT_T * 3, "height " + where);
            assertEquals(z, ctx.rootV, ROOT_UV, "v is the height " + where);
        }
        assertTrue(converged > 200, "converged " + converged);
    }

    /**
     * The Newton method through the scene: the nearest of the trough's two roots, the farther one
     * when tMin cuts the nearer out, none between them or beyond, for rays of any length.
     */
    @Test
    void theNewtonMethodReturnsTheNearestRootInTheInterval() {
        SceneIntersector si = SceneIntersector.build(new Scene(List.of(ClippingStepsTest.trough())),
                IntersectOptions.defaults().withMethod(Method.NEWTON));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        for (double k : new double[] {1, 1e-3, 1e3}) {
            assertTrue(si.closestHit(ctx, -1, 0.5, 0.09, k, 0, 0, 0, Double.POSITIVE_INFINITY, hit));
            assertEquals(1.2 / k, hit.t, ROOT_T / k);
            assertEquals(0.2, hit.u, ROOT_UV);
            assertEquals(0.5, hit.v, ROOT_UV);
            assertTrue(si.closestHit(ctx, -1, 0.5, 0.09, k, 0, 0, 1.5 / k, Double.POSITIVE_INFINITY, hit));
            assertEquals(1.8 / k, hit.t, ROOT_T / k);
            assertEquals(0.8, hit.u, ROOT_UV);
            assertFalse(si.closestHit(ctx, -1, 0.5, 0.09, k, 0, 0, 1.3 / k, 1.7 / k, hit));
            assertFalse(si.closestHit(ctx, -1, 0.5, 0.09, k, 0, 0, 1.9 / k, Double.POSITIVE_INFINITY, hit));
            assertFalse(si.closestHit(ctx, -1, 0.5, 0.09, k, 0, 0, 0, 1.1 / k, hit));
            // from the other end the root at u = 0.8 is nearer
            assertTrue(si.closestHit(ctx, 2, 0.5, 0.09, -k, 0, 0, 0, Double.POSITIVE_INFINITY, hit));
            assertEquals(1.2 / k, hit.t, ROOT_T / k);
            assertEquals(0.8, hit.u, ROOT_UV);
            // beside the trough, above it, parallel to it: misses
            assertFalse(si.closestHit(ctx, -1, 1.5, 0.09, k, 0, 0, 0, Double.POSITIVE_INFINITY, hit));
            assertFalse(si.closestHit(ctx, -1, 0.5, 0.3, k, 0, 0, 0, Double.POSITIVE_INFINITY, hit));
            assertFalse(si.closestHit(ctx, 0.5, -1, 0.3, 0, k, 0, 0, Double.POSITIVE_INFINITY, hit));
        }
    }
}
