package org.beziertracer.intersect;

import org.beziertracer.geometry.RationalDeCasteljau;
import org.beziertracer.geometry.SubPatchTable;

/**
 * Newton iteration for the ray–patch equations in ray space: find {@code (u,v)} with
 * {@code n1·(S(u,v)−o) = 0} and {@code n2·(S(u,v)−o) = 0}, a 2×2 system whose Jacobian is
 * {@code [n1·Su n1·Sv; n2·Su n2·Sv]} (memoir ch. I 3.3.3.3; Toth, "On ray tracing parametric
 * surfaces", SIGGRAPH 1985). Works on the parent patch's own net, so a root is found to full
 * double precision whatever sub-patch produced the start. A rational patch is evaluated through
 * its homogeneous net with the exact rational Jacobian (the quotient rule,
 * {@link RationalDeCasteljau#evaluateWithDerivatives}); a polynomial one up to degree 9 from its
 * power form ({@link SubPatchTable#evaluatePatch}, {@link org.beziertracer.geometry.PowerForm}),
 * above that by de Casteljau or the Bernstein sums.
 */
final class RayPatchNewton {
    private RayPatchNewton() {}

    /** Outcome codes of {@link #solve}. */
    static final int CONVERGED = 0, SINGULAR = 1, DIVERGED = 2;
    /**
     * A step is taken unevaluated ({@link #extrapolate}) when the bound on its second-order error
     * is within this fraction of the residual tolerance: the level {@link #refine} reaches.
     */
    static final double EXTRAPOLATED = 1e-3;

    /**
     * Iterates from {@code (u,v)} on patch {@code k}; on return {@code ctx.rootU/rootV/rootT}
     * hold the last iterate and its ray parameter, and {@code ctx.eval} the surface point and
     * first derivatives there ({@code ctx.evalPatch = k}; {@link PatchLeaves#intersect} keeps
     * them for {@link SceneIntersector#surfacePoint}).
     *
     * @param maxSteps      iteration cap
     * @param lo/hi bounds  the iterate must stay in {@code [uLo,uHi]×[vLo,vHi]} or the solve fails
     * @return {@link #CONVERGED}, {@link #SINGULAR} (Jacobian vanishes) or {@link #DIVERGED}
     */
    static int solve(TraceContext ctx, SubPatchTable table, int k, double u, double v, int maxSteps,
                     double uLo, double uHi, double vLo, double vHi, double tolerance) {
        double[] e = ctx.eval;
        double curvature = table.patchCurvature[k];
        ctx.evalPatch = k; // from here on ctx.eval holds S, Su, Sv of patch k at (ctx.evalU, ctx.evalV)
        for (int step = 0; step <= maxSteps; step++) {
            if (step > 0 || !fromOrigin(ctx, table, k, u, v)) {
                evaluate(ctx, table, k, u, v);
            }
            double f1 = ctx.residual1, f2 = ctx.residual2;
            if (Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance && step > 0) {
                return CONVERGED;
            }
            if (step == maxSteps) {
                break;
            }
            double a = ctx.n1x * e[3] + ctx.n1y * e[4] + ctx.n1z * e[5];
            double b = ctx.n1x * e[6] + ctx.n1y * e[7] + ctx.n1z * e[8];
            double c = ctx.n2x * e[3] + ctx.n2y * e[4] + ctx.n2z * e[5];
            double d = ctx.n2x * e[6] + ctx.n2y * e[7] + ctx.n2z * e[8];
            double det = a * d - b * c;
            double scale = Math.abs(a * d) + Math.abs(b * c);
            if (!(Math.abs(det) > 1e-300) || Math.abs(det) <= 1e-14 * scale) {
                return Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance ? CONVERGED : SINGULAR;
            }
            double du = (b * f2 - d * f1) / det;
            double dv = (c * f1 - a * f2) / det;
            if (extrapolate(ctx, curvature, du, dv, tolerance, uLo, uHi, vLo, vHi)) {
                return CONVERGED;
            }
            if (Math.abs(du) < 1e-15 && Math.abs(dv) < 1e-15
                    && Math.max(Math.abs(f1), Math.abs(f2)) <= 1e-3 * tolerance) {
                // Already a root to rounding (as in refine): the step could not move the point
                // by more than rounding, so the evaluation here stands and none is repeated
                return CONVERGED;
            }
            u += du;
            v += dv;
            if (!(u >= uLo && u <= uHi && v >= vLo && v <= vHi)) {
                ctx.escapeU = u; // where the iteration left the box (NewtonSolver may restart there)
                ctx.escapeV = v;
                return DIVERGED;
            }
            if (Math.abs(du) < 1e-15 && Math.abs(dv) < 1e-15) {
                // one more evaluation at the final iterate for t
                evaluate(ctx, table, k, u, v);
                return Math.abs(ctx.residual1) <= tolerance && Math.abs(ctx.residual2) <= tolerance
                        ? CONVERGED : DIVERGED;
            }
        }
        return DIVERGED;
    }

    /**
     * When {@code (u, v)} of patch {@code k} is the point a shadow ray leaves (its own leaf's start,
     * {@link OriginLeaf#startAtOrigin}) and the patch's domain is the unit square, that point's
     * evaluation, made when its hit was shaded, is taken as the first iterate's instead of evaluating
     * again (the same point and derivatives, or the solver's own extrapolation of them: within the
     * tolerance's thousandth, {@link #extrapolate}); true when it was.
     */
    private static boolean fromOrigin(TraceContext ctx, SubPatchTable table, int k, double u, double v) {
        if (!startsAtOrigin(ctx, table, k, u, v)) {
            return false;
        }
        double[] e = ctx.eval;
        e[0] = ctx.originPx; e[1] = ctx.originPy; e[2] = ctx.originPz;
        e[3] = ctx.originSux; e[4] = ctx.originSuy; e[5] = ctx.originSuz;
        e[6] = ctx.originSvx; e[7] = ctx.originSvy; e[8] = ctx.originSvz;
        takeIterate(ctx, u, v);
        ctx.originEvaluations++;
        return true;
    }

    /**
     * True when a solve on patch {@code k} from {@code (u, v)} takes its first iterate's evaluation
     * from the point the context's shadow ray leaves ({@link #fromOrigin}) instead of evaluating.
     */
    static boolean startsAtOrigin(TraceContext ctx, SubPatchTable table, int k, double u, double v) {
        int s = ctx.originLeaf;
        return s >= 0 && ctx.originDerivatives && u == ctx.originU && v == ctx.originV && table.parent[s] == k
                && SurfaceParameters.unit(table.patchDomain, k);
    }

    /**
     * S, Su, Sv of the patch at {@code (u, v)} into {@code ctx.eval}; the iterate as the root so
     * far (u, v and its t along the ray) and its residuals to the ray's two planes.
     */
    private static void evaluate(TraceContext ctx, SubPatchTable table, int k, double u, double v) {
        table.evaluatePatch(k, u, v, ctx.eval, ctx.scratch);
        ctx.evaluations++;
        takeIterate(ctx, u, v);
    }

    /**
     * Makes {@code (u, v)}, whose point is in {@code ctx.eval[0..3)}, the iterate: the root so far
     * (u, v and its t along the ray), the point of {@code ctx.eval}, and its residuals to the
     * ray's two planes.
     */
    private static void takeIterate(TraceContext ctx, double u, double v) {
        double[] e = ctx.eval;
        double qx = e[0] - ctx.ox, qy = e[1] - ctx.oy, qz = e[2] - ctx.oz;
        ctx.residual1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
        ctx.residual2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        ctx.rootU = u;
        ctx.rootV = v;
        ctx.evalU = u;
        ctx.evalV = v;
        ctx.rootT = (ctx.n3x * qx + ctx.n3y * qy + ctx.n3z * qz) * ctx.invLength;
    }

    /**
     * Takes the Newton step {@code (du, dv)} from the last evaluation without evaluating again,
     * when that is as exact as an evaluation: the linear model {@code F + J·Δ} is zero there, and
     * the patch departs from it by at most {@code ½·M·(|du|+|dv|)²} ({@code M} the patch's
     * {@link SubPatchTable#patchCurvature},
     * {@link org.beziertracer.geometry.NetMeasures#secondDerivativeBound}). When that bound plus
     * the linear model's own residual at the new point (the rounding of the step) is within
     * {@link #EXTRAPOLATED} of the tolerance and the step stays in the box, the root moves by the
     * step and the point by {@code Su·du + Sv·dv} (so its t follows), the derivatives in
     * {@code ctx.eval} are kept (they move by at most {@code M·(|du|+|dv|)}, which the normal at
     * the hit does not see), and the result is true. Rational patches carry {@code M = +∞} and
     * never extrapolate. The result does not depend on anything but the evaluation and the step,
     * so a ray's root stays the same whatever ray came before (renders repeat bit for bit).
     */
    static boolean extrapolate(TraceContext ctx, double curvature, double du, double dv, double tolerance,
                               double uLo, double uHi, double vLo, double vHi) {
        double reach = Math.abs(du) + Math.abs(dv), remainder = 0.5 * curvature * reach * reach;
        if (!(remainder <= EXTRAPOLATED * tolerance)) {
            return false;
        }
        double u = ctx.rootU + du, v = ctx.rootV + dv;
        if (!(u >= uLo && u <= uHi && v >= vLo && v <= vHi)) {
            return false;
        }
        double[] e = ctx.eval;
        double px = e[0] + e[3] * du + e[6] * dv, py = e[1] + e[4] * du + e[7] * dv, pz = e[2] + e[5] * du + e[8] * dv;
        double qx = px - ctx.ox, qy = py - ctx.oy, qz = pz - ctx.oz;
        double r1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz, r2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        // The linear model's own residual there (zero but for the rounding of an ill-conditioned
        // step) counts too
        if (!(Math.max(Math.abs(r1), Math.abs(r2)) + remainder <= EXTRAPOLATED * tolerance)) {
            return false;
        }
        e[0] = px;
        e[1] = py;
        e[2] = pz;
        takeIterate(ctx, u, v);
        ctx.extrapolations++;
        return true;
    }

    /**
     * One more Newton step from a converged {@link #solve} (whose last evaluation, at
     * {@code ctx.rootU/rootV}, is still in {@code ctx.eval}): near a simple root Newton converges
     * quadratically, so a root accepted at the residual tolerance becomes exact to rounding. The
     * step is kept only when it stays in {@code [uLo,uHi]×[vLo,vHi]} and does not increase the
     * residual. One evaluation, skipped when the residual is already below
     * {@code 1e-3 × tolerance} (one more step could not move the point by more than rounding).
     */
    static void refine(TraceContext ctx, SubPatchTable table, int k, double uLo, double uHi, double vLo, double vHi,
                       double tolerance) {
        double[] e = ctx.eval;
        double qx = e[0] - ctx.ox, qy = e[1] - ctx.oy, qz = e[2] - ctx.oz;
        double f1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
        double f2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        if (Math.max(Math.abs(f1), Math.abs(f2)) <= 1e-3 * tolerance) {
            return;
        }
        double a = ctx.n1x * e[3] + ctx.n1y * e[4] + ctx.n1z * e[5];
        double b = ctx.n1x * e[6] + ctx.n1y * e[7] + ctx.n1z * e[8];
        double c = ctx.n2x * e[3] + ctx.n2y * e[4] + ctx.n2z * e[5];
        double d = ctx.n2x * e[6] + ctx.n2y * e[7] + ctx.n2z * e[8];
        double det = a * d - b * c;
        if (!(Math.abs(det) > 1e-300) || Math.abs(det) <= 1e-14 * (Math.abs(a * d) + Math.abs(b * c))) {
            return;
        }
        double du = (b * f2 - d * f1) / det, dv = (c * f1 - a * f2) / det;
        if (extrapolate(ctx, table.patchCurvature[k], du, dv, tolerance, uLo, uHi, vLo, vHi)) {
            return;
        }
        double u = ctx.rootU + du;
        double v = ctx.rootV + dv;
        if (!(u >= uLo && u <= uHi && v >= vLo && v <= vHi)) {
            return;
        }
        double[] g = ctx.refineEval;
        table.evaluatePatch(k, u, v, g, ctx.scratch);
        ctx.evaluations++;
        qx = g[0] - ctx.ox; qy = g[1] - ctx.oy; qz = g[2] - ctx.oz;
        double g1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
        double g2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        if (Math.max(Math.abs(g1), Math.abs(g2)) <= Math.max(Math.abs(f1), Math.abs(f2))) {
            System.arraycopy(g, 0, e, 0, 9); // keep ctx.eval at the root
            takeIterate(ctx, u, v);
        }
    }
}
