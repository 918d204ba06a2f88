package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROOT_T;
import static org.beziertracer.Tolerances.ROOT_UV;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link RayPatchNewton}: from a start near a simple root it converges to that root; the
 * outcome codes mean what they say; the context's evaluation is the surface at the returned
 * point; {@link RayPatchNewton#refine} never makes a root worse.
 */
class RayPatchNewtonTest {

    static final double TOLERANCE = 1e-12; // residual tolerance for a patch of size ~4, as the solvers use

    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];

    /** The ray-space residual max(|F1|, |F2|) at the context's last evaluation. */
    static double residual(TraceContext ctx) {
        double qx = ctx.eval[0] - ctx.ox, qy = ctx.eval[1] - ctx.oy, qz = ctx.eval[2] - ctx.oz;
        return Math.max(Math.abs(ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz),
                Math.abs(ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz));
    }

    @Test
    void fromNearARootItConvergesToThatRoot() {
        Random rnd = new Random(1985);
        TraceContext ctx = new TraceContext();
        double[] s = new double[3], e = new double[9];
        int converged = 0, tried = 0;
        for (int trial = 0; trial < 300; trial++) {
            int n = 1 + rnd.nextInt(9), m = 1 + rnd.nextInt(9);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, 4, 0.3);
            SubPatchTable tab = SubPatchTable.build(List.of(patch), SplitOptions.wholePatches());
            for (int r = 0; r < 5; r++) {
                double us = 0.1 + 0.8 * rnd.nextDouble(), vs = 0.1 + 0.8 * rnd.nextDouble();
                DeCasteljau.evaluate(tab.patchNets, 0, n, m, 3, us, vs, s, 0, scratch);
                double ox = s[0] + rnd.nextGaussian(), oy = s[1] + rnd.nextGaussian(), oz = 6;
                ctx.setRay(ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz); // t* = 1
                double u = us + 0.02 * (rnd.nextDouble() - 0.5), v = vs + 0.02 * (rnd.nextDouble() - 0.5);
                int result = RayPatchNewton.solve(ctx, tab, 0, u, v, 12, 0, 1, 0, 1, TOLERANCE);
                String where = "degree " + n + "x" + m + " (u*,v*)=(" + us + "," + vs + ") start (" + u + "," + v + ")";
                tried++;
                if (result != RayPatchNewton.CONVERGED) {
                    continue;
                }
                converged++;
                assertTrue(residual(ctx) <= TOLERANCE, "residual " + residual(ctx) + ": " + where);
                assertEquals(1, ctx.rootT, ROOT_T * 4, "t: " + where);
                assertEquals(us, ctx.rootU, ROOT_UV, "u: " + where);
                assertEquals(vs, ctx.rootV, ROOT_UV, "v: " + where);
                // ctx.eval is the surface and its derivatives at the returned point (bit for bit,
                // or within the bound of a last step taken unevaluated)
                assertEquals(0, ctx.evalPatch, where);
                assertEquals(ctx.rootU, ctx.evalU, 0, where);
                assertEquals(ctx.rootV, ctx.evalV, 0, where);
                DeCasteljau.evaluateWithDerivatives(tab.patchNets, 0, n, m, ctx.rootU, ctx.rootV, e, scratch);
                assertKeptEvaluation(e, ctx.eval, tab.patchCurvature[0], TOLERANCE, where);
            }
        }
        assertTrue(converged > 0.98 * tried, "converged from close starts: " + converged + " of " + tried);
    }

    @Test
    void aRootOutsideTheBoxIsNotReturned() {
        BezierPatch patch = Models.flatGrid(4, 4);
        SubPatchTable tab = SubPatchTable.build(List.of(patch), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        double[] s = new double[3];
        DeCasteljau.evaluate(tab.patchNets, 0, 3, 3, 3, 0.8, 0.5, s, 0, scratch);
        ctx.setRay(s[0] + 0.3, s[1], s[2] + 5, -0.3, 0, -5);
        assertEquals(RayPatchNewton.CONVERGED, RayPatchNewton.solve(ctx, tab, 0, 0.3, 0.5, 12, 0, 1, 0, 1, TOLERANCE));
        assertEquals(0.8, ctx.rootU, ROOT_UV);
        assertEquals(RayPatchNewton.DIVERGED, RayPatchNewton.solve(ctx, tab, 0, 0.3, 0.5, 12, 0, 0.6, 0, 1, TOLERANCE),
                "the iterate must stay in [0,0.6] x [0,1]");
    }

    @Test
    void aRayInThePlaneOfAFlatPatchIsSingular() {
        // Every derivative of the flat grid lies in its plane; a ray parallel to the plane, off it,
        // makes the Jacobian [n1·Su n1·Sv; n2·Su n2·Sv] singular and the residual non-zero
        SubPatchTable tab = SubPatchTable.build(List.of(Models.flatGrid(4, 4)), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        double z = tab.patchNets[2];
        ctx.setRay(-5, 0.1, z + 1, 1, 0, 0);
        assertEquals(RayPatchNewton.SINGULAR, RayPatchNewton.solve(ctx, tab, 0, 0.5, 0.5, 12, 0, 1, 0, 1, TOLERANCE));
    }

    @Test
    void zeroStepsOnlyEvaluateTheStart() {
        SubPatchTable tab = SubPatchTable.build(List.of(Models.flatGrid(4, 4)), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        double[] s = new double[3];
        DeCasteljau.evaluate(tab.patchNets, 0, 3, 3, 3, 0.25, 0.75, s, 0, scratch);
        ctx.setRay(s[0], s[1], s[2] + 2, 0, 0, -1);
        assertEquals(RayPatchNewton.DIVERGED, RayPatchNewton.solve(ctx, tab, 0, 0.25, 0.75, 0, 0, 1, 0, 1, TOLERANCE),
                "no step, so no convergence is claimed");
        assertEquals(0.25, ctx.rootU, 0);
        assertEquals(0.75, ctx.rootV, 0);
        assertEquals(2, ctx.rootT, ROOT_T, "t of the start point's projection on the ray");
    }

    /**
     * From a converged loose solve (residual 1e-6) or from an arbitrary point (a zero-step solve),
     * with a box around or beside the point: refine keeps the point unless one Newton step stays
     * in the box and does not increase the residual.
     */
    @Test
    void refineNeverIncreasesTheResidualNorLeavesTheBox() {
        Random rnd = new Random(77);
        TraceContext ctx = new TraceContext();
        double[] s = new double[3];
        int improved = 0, kept = 0;
        for (int trial = 0; trial < 800; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            SubPatchTable tab = SubPatchTable.build(List.of(RandomPatches.heightField(rnd, n, m, 4, 0.4)),
                    SplitOptions.wholePatches());
            double us = rnd.nextDouble(), vs = rnd.nextDouble();
            DeCasteljau.evaluate(tab.patchNets, 0, n, m, 3, us, vs, s, 0, scratch);
            double ox = s[0] + rnd.nextGaussian(), oy = s[1] + rnd.nextGaussian(), oz = 6;
            ctx.setRay(ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz);
            boolean far = trial % 2 == 1;
            int steps = far ? 0 : 12;
            double su = far ? rnd.nextDouble() : us + 0.01, sv = far ? rnd.nextDouble() : vs - 0.01;
            int r = RayPatchNewton.solve(ctx, tab, 0, su, sv, steps, 0, 1, 0, 1, 1e-6);
            if (!far && r != RayPatchNewton.CONVERGED) {
                continue;
            }
            double[] root = {ctx.rootU, ctx.rootV, ctx.rootT};
            boolean beside = rnd.nextBoolean();
            double u0 = beside ? root[0] : Math.max(0, root[0] - 0.05), u1 = Math.min(1, root[0] + 0.05);
            double v0 = beside ? root[1] : Math.max(0, root[1] - 0.05), v1 = Math.min(1, root[1] + 0.05);
            double before = residual(ctx);
            RayPatchNewton.refine(ctx, tab, 0, u0, u1, v0, v1, TOLERANCE);
            String where = "trial " + trial + " from " + Arrays.toString(root) + (beside ? " box beside" : " box around");
            assertTrue(residual(ctx) <= before, "residual " + before + " -> " + residual(ctx) + ": " + where);
            if (ctx.rootU == root[0] && ctx.rootV == root[1]) {
                kept++;
                continue;
            }
            improved++;
            assertTrue(ctx.rootU >= u0 && ctx.rootU <= u1 && ctx.rootV >= v0 && ctx.rootV <= v1,
                    "left the box: (" + ctx.rootU + ", " + ctx.rootV + "): " + where);
            assertEquals(ctx.rootU, ctx.evalU, 0, "eval follows the refined root: " + where);
            assertEquals(ctx.rootV, ctx.evalV, 0, "eval follows the refined root: " + where);
        }
        assertTrue(improved > 150 && kept > 150, "refine improved " + improved + ", kept " + kept);
    }

    /**
     * {@code kept} is the evaluation a solve left at its root, {@code fresh} the surface's own
     * there: equal, or within what a last step taken without evaluation
     * ({@link RayPatchNewton#extrapolate}) allows — the point within
     * {@link RayPatchNewton#EXTRAPOLATED}{@code ·tolerance}, the derivatives within
     * {@code M·(|du|+|dv|) ≤ √(2·M·EXTRAPOLATED·tolerance)} ({@code M} the patch's curvature bound).
     */
    static void assertKeptEvaluation(double[] fresh, double[] kept, double curvature, double tolerance, String where) {
        double point = RayPatchNewton.EXTRAPOLATED * tolerance, slope = Math.sqrt(2 * curvature * point);
        for (int c = 0; c < 9; c++) {
            double allowed = (c < 3 ? point : slope) * (1 + 1e-9) + 1e-14 * (1 + Math.abs(fresh[c]));
            assertEquals(fresh[c], kept[c], allowed, "kept evaluation, entry " + c + ": " + where);
        }
    }
}
