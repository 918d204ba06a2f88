package org.beziertracer.intersect;

import org.beziertracer.geometry.PowerForm;
import org.beziertracer.geometry.RationalDeCasteljau;
import org.beziertracer.geometry.SubPatchTable;

/**
 * Ray–patch intersection by Newton iteration at the BVH leaves (memoir ch. I 3.3.3.3; D. L. Toth,
 * "On ray tracing parametric surfaces", SIGGRAPH 1985), as W. Martin, E. Cohen, R. Fish and
 * P. Shirley practise it in "Practical ray tracing of trimmed NURBS surfaces", JGT 5(1), 2000:
 * <ul>
 *   <li>the leaves are refined until Newton converges from the leaf's start
 *       ({@link NewtonRefinement}, the Newton method's own split);</li>
 *   <li>the start comes from the leaf (M. Geimer and O. Abert, "Interactive ray tracing of trimmed
 *       bicubic Bézier surfaces without triangulation", WSCG 2005: "an optimized bounding volume
 *       hierarchy provides good initial guesses"): here the point where the ray crosses the leaf's
 *       parallelogram ({@link NewtonLeafRecords}), whose thickness R also rejects leaves the ray
 *       misses before any evaluation;</li>
 *   <li>leaf domains overlap: a root is accepted anywhere in the leaf's parameter box grown by
 *       {@link #OVERLAP} leaf width on every side (within the patch), so a root near a border
 *       between leaves is found from either side, and rejected outside it; iterates may roam the
 *       patch's domain grown by {@link #WANDER}. An iterate leaving that, a singular Jacobian,
 *       {@link #MAX_STEPS} steps or (Martin et al.'s divergence test, from step
 *       {@link #GROWTH_CHECK_FROM} on) a growing residual ends the attempt;</li>
 *   <li>more starts where they help: on leaves that may hold several roots.</li>
 * </ul>
 * A leaf may hold several roots for this ray when its single-root test (that of
 * {@link RootUniqueness}, with the record's balls) fails: the ray grazes it. There the leaf's
 * centre is tried as a second start and, while no root is found, its four quarter points
 * ({@link #QUARTERS}; a grazing ray can leave the parallelogram's start outside the basin of every
 * root), their iterates confined to the overlapped domain (not clipped to the patch: an iterate
 * heading for a root near the patch's border may overshoot it by a little) so that a start with no root nearby
 * fails fast; a root found may be the farther of a fold's two, so the found root's reflections
 * through the first start and through the centre are tried as well, and the nearest root is kept
 * (an attempt stops early once its t passes the nearest root so far). Nothing but
 * Newton runs: no clipping, no subdivision; a leaf whose attempts all fail is a miss.
 *
 * <p>Each attempt solves {@code F(u,v) = (n1·(S(u,v) − o), n2·(S(u,v) − o)) = 0} on the parent
 * patch (ray-space planes of {@link TraceContext}) and converges when {@code |F| ≤ tolerance}; a
 * point whose residual and next step (in world space) are both within {@link #CLOSE}{@code ·tolerance}
 * is close enough that the step squares its error, so that step is taken without a further
 * evaluation (t follows to first order). An attempt whose t is beyond {@code (tMin, tMax)} by more than its last step, or which
 * comes back to a root already found, stops early.
 *
 * <p>Allocation-free; per-thread state in the {@link TraceContext}.
 */
final class NewtonSolver {
    private NewtonSolver() {}

    /** Iteration cap of one attempt (Martin et al. use about 7; our domains are wider). */
    static final int MAX_STEPS = 10;
    /** Growth of a leaf's parameter box on every side, in leaf widths: the overlapped domain, where roots are accepted. */
    static final double OVERLAP = 1;
    /**
     * Iterates may also wander this far beyond the patch's own domain (the polynomial extends
     * beyond it; near a fold, Newton's first steps overshoot before they converge).
     */
    static final double WANDER = 0.5;
    /** From this step on, a residual larger than the previous one ends the attempt (Martin et al.). */
    static final int GROWTH_CHECK_FROM = 3;
    /** A point with a residual within this factor of the tolerance takes its last step unevaluated. */
    static final double CLOSE = 1e5;
    /** An attempt coming within this fraction of a leaf width of a root already found stops. */
    static final double SAME_ROOT = 1e-3;
    /** Slack of the patch's own domain [0,1]² (roots on a patch border survive rounding). */
    static final double PATCH_SLACK = 1e-9;
    /** Further starts (leaf parameters, pairs) on a leaf that may hold several roots when neither start nor centre converged. */
    private static final double[] QUARTERS = {0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75};
    /** Outcomes of {@link #start}. */
    static final int MISS = 0, SINGLE_ROOT = 1, MAYBE_SEVERAL = 2;
    /** Outcomes of {@link #iterate}. */
    static final int CONVERGED = 0, FAILED = 1;
    /** Doubles of {@link TraceContext#newton}: domain, t range, the root to avoid, the leaf size. */
    static final int SCRATCH = 10;
    private static final int ULO = 0, UHI = 1, VLO = 2, VHI = 3, TMIN = 4, TMAX = 5, AVOID_U = 6,
            AVOID_V = 7, WIDTH_U = 8, WIDTH_V = 9;

    /**
     * Nearest root of sub-patch {@code s} with {@code tMin < t < tMax}: on success in
     * {@code ctx.rootT, rootU, rootV} (parent-patch parameters) and true.
     *
     * @param records the table's {@link NewtonLeafRecords}
     */
    static boolean intersect(TraceContext ctx, SubPatchTable tab, float[] records, int s, double tMin,
                             double tMax, double tolerance) {
        int o = NewtonLeafRecords.STRIDE * s;
        int kind = start(ctx, records, o, tMin, tMax, tolerance);
        if (kind == MISS) {
            return false;
        }
        return search(ctx, tab, records, s, kind == SINGLE_ROOT, tMin, tMax, tolerance);
    }

    /**
     * Meets the ray with the leaf's parallelogram grown by R: {@link #MISS} when the leaf provably
     * does not meet the ray in {@code (tMin, tMax)}; else the start (the parallelogram's
     * parameters where the ray crosses it, clamped to the leaf) in {@code ctx.clip}, and
     * {@link #SINGLE_ROOT} when the leaf provably meets the ray at most once.
     */
    static int start(TraceContext ctx, float[] rec, int o, double tMin, double tMax, double tolerance) {
        double cx = rec[o + NewtonLeafRecords.C] - ctx.ox, cy = rec[o + NewtonLeafRecords.C + 1] - ctx.oy;
        double cz = rec[o + NewtonLeafRecords.C + 2] - ctx.oz;
        double x0 = ctx.n1x * cx + ctx.n1y * cy + ctx.n1z * cz, y0 = ctx.n2x * cx + ctx.n2y * cy + ctx.n2z * cz;
        double z0 = ctx.n3x * cx + ctx.n3y * cy + ctx.n3z * cz;
        int a = o + NewtonLeafRecords.A, b = o + NewtonLeafRecords.B;
        double xa = ctx.n1x * rec[a] + ctx.n1y * rec[a + 1] + ctx.n1z * rec[a + 2];
        double ya = ctx.n2x * rec[a] + ctx.n2y * rec[a + 1] + ctx.n2z * rec[a + 2];
        double za = ctx.n3x * rec[a] + ctx.n3y * rec[a + 1] + ctx.n3z * rec[a + 2];
        double xb = ctx.n1x * rec[b] + ctx.n1y * rec[b + 1] + ctx.n1z * rec[b + 2];
        double yb = ctx.n2x * rec[b] + ctx.n2y * rec[b + 1] + ctx.n2z * rec[b + 2];
        double zb = ctx.n3x * rec[b] + ctx.n3y * rec[b + 1] + ctx.n3z * rec[b + 2];
        double r = rec[o + NewtonLeafRecords.R] + tolerance;
        // Depth of the grown parallelogram against (tMin, tMax)
        double zSpan = 0.5 * (Math.abs(za) + Math.abs(zb)) + r;
        if ((z0 - zSpan) * ctx.invLength >= tMax || (z0 + zSpan) * ctx.invLength <= tMin) {
            return MISS;
        }
        // The ray is the origin of the ray plane: solve P(s,t) = 0 there (centred parameters)
        double det = xa * yb - ya * xb;
        double la = Math.sqrt(xa * xa + ya * ya), lb = Math.sqrt(xb * xb + yb * yb);
        double[] st = ctx.clip;
        st[0] = 0.5;
        st[1] = 0.5;
        if (Math.abs(det) > 1e-9 * la * lb) {
            double ss = (y0 * xb - x0 * yb) / det, tt = (ya * x0 - xa * y0) / det;
            // a shift by r moves s by at most r·|b|/|det| and t by r·|a|/|det|
            double gs = r * lb / Math.abs(det), gt = r * la / Math.abs(det);
            if (ss < -0.5 - gs || ss > 0.5 + gs || tt < -0.5 - gt || tt > 0.5 + gt) {
                return MISS;
            }
            st[0] = Math.min(1, Math.max(0, ss + 0.5));
            st[1] = Math.min(1, Math.max(0, tt + 0.5));
        } else {
            // seen edge-on: the box of the grown parallelogram
            double xs = 0.5 * (Math.abs(xa) + Math.abs(xb)) + r, ys = 0.5 * (Math.abs(ya) + Math.abs(yb)) + r;
            if (Math.abs(x0) > xs || Math.abs(y0) > ys) {
                return MISS;
            }
        }
        // Single-root test of RootUniqueness with these balls: the Jacobians stay away from singular
        double ra = rec[o + NewtonLeafRecords.RA], rb = rec[o + NewtonLeafRecords.RB];
        double bound = rb * (Math.abs(xa) + Math.abs(ya)) + ra * (Math.abs(xb) + Math.abs(yb)) + 2 * ra * rb
                + 1e-10 * (la + ra) * (lb + rb);
        return Math.abs(det) > bound ? SINGLE_ROOT : MAYBE_SEVERAL;
    }

    /** Runs the attempts from the start in {@code ctx.clip}; keeps the nearest accepted root. */
    private static boolean search(TraceContext ctx, SubPatchTable tab, float[] rec, int s, boolean singleRoot,
                                  double tMin, double tMax, double tolerance) {
        int o = NewtonLeafRecords.STRIDE * s, k = tab.parent[s];
        double u0 = rec[o + NewtonLeafRecords.U0], du = rec[o + NewtonLeafRecords.DU];
        double v0 = rec[o + NewtonLeafRecords.V0], dv = rec[o + NewtonLeafRecords.DV];
        double[] w = ctx.newton;
        setDomain(w, u0, du, v0, dv);
        // the overlapped domain itself: quarter iterates stay in it (not clipped to the patch,
        // so that one heading for a root near the patch's border may step across it on its way)
        double cuLo = w[ULO], cuHi = w[UHI], cvLo = w[VLO], cvHi = w[VHI];
        double uLo = Math.max(-PATCH_SLACK, w[ULO]), uHi = Math.min(1 + PATCH_SLACK, w[UHI]);
        double vLo = Math.max(-PATCH_SLACK, w[VLO]), vHi = Math.min(1 + PATCH_SLACK, w[VHI]);
        // roots are accepted in the leaf's overlapped domain; iterates may also roam the patch
        w[ULO] = Math.min(w[ULO], -WANDER);
        w[UHI] = Math.max(w[UHI], 1 + WANDER);
        w[VLO] = Math.min(w[VLO], -WANDER);
        w[VHI] = Math.max(w[VHI], 1 + WANDER);
        double s0 = ctx.clip[0], t0 = ctx.clip[1], su = s0, sv = t0;
        boolean found = false;
        double bestT = tMax, bestU = 0, bestV = 0;
        // A single-root leaf gets one attempt (a root it misses near its border lies in a
        // neighbour's overlapped domain); a leaf that may hold several roots also gets its
        // centre, its quarter points while nothing is found and, once a root is found, that
        // root's reflections through the first start and through the centre, for a nearer root
        // across a fold
        int quarter = 0, reflection = 0;
        for (int attempt = 0; attempt < (singleRoot ? 1 : 2 + QUARTERS.length / 2 + 2); attempt++) {
            if (attempt == 1) {
                su = 0.5;
                sv = 0.5;
            } else if (attempt > 1 && !found && quarter < QUARTERS.length) {
                su = QUARTERS[quarter++];
                sv = QUARTERS[quarter++];
                confine(w, cuLo, cuHi, cvLo, cvHi); // a quarter start that leaves the overlap fails fast
            } else if (attempt > 1 && found && reflection < 2) {
                double ru = (bestU - u0) / du, rv = (bestV - v0) / dv;
                su = Math.min(1, Math.max(0, reflection == 0 ? 2 * s0 - ru : 1 - ru));
                sv = Math.min(1, Math.max(0, reflection == 0 ? 2 * t0 - rv : 1 - rv));
                reflection++;
            } else if (attempt > 1) {
                break;
            }
            w[TMIN] = tMin;
            w[TMAX] = bestT;
            if (iterate(ctx, tab.patchNets, tab.patchNetOffset[k], tab.patchPowerOffset[k], tab.patchDegreeU[k],
                    tab.patchDegreeV[k], tab.patchDim[k],
                    u0 + su * du, v0 + sv * dv, w, tolerance) == CONVERGED) {
                double u = ctx.rootU, v = ctx.rootV;
                if (u >= uLo && u <= uHi && v >= vLo && v <= vHi && ctx.rootT > tMin && ctx.rootT < bestT) {
                    bestT = ctx.rootT;
                    bestU = u;
                    bestV = v;
                    found = true;
                    w[AVOID_U] = u;
                    w[AVOID_V] = v;
                }
            }
        }
        return found && root(ctx, k, bestT, bestU, bestV);
    }

    /** The nearest root found on patch {@code k} into {@code ctx} (parameters clamped to the patch); true. */
    private static boolean root(TraceContext ctx, int k, double t, double u, double v) {
        // ctx.eval holds the last attempt's last evaluation: reusable only if it is at the root
        ctx.evalPatch = ctx.evalU == u && ctx.evalV == v ? k : -1;
        ctx.rootT = t;
        ctx.rootU = Math.min(1, Math.max(0, u));
        ctx.rootV = Math.min(1, Math.max(0, v));
        return true;
    }

    /** Iterates of the next attempts stay in {@code [uLo, uHi] × [vLo, vHi]}. */
    private static void confine(double[] w, double uLo, double uHi, double vLo, double vHi) {
        w[ULO] = uLo;
        w[UHI] = uHi;
        w[VLO] = vLo;
        w[VHI] = vHi;
    }

    /** The overlapped domain of the leaf {@code [u0, u0+du] × [v0, v0+dv]} into {@code w}; no root to avoid. */
    static void setDomain(double[] w, double u0, double du, double v0, double dv) {
        w[ULO] = u0 - OVERLAP * du;
        w[UHI] = u0 + (1 + OVERLAP) * du;
        w[VLO] = v0 - OVERLAP * dv;
        w[VHI] = v0 + (1 + OVERLAP) * dv;
        w[WIDTH_U] = du;
        w[WIDTH_V] = dv;
        w[AVOID_U] = Double.NaN;
        w[TMIN] = Double.NEGATIVE_INFINITY;
        w[TMAX] = Double.POSITIVE_INFINITY;
    }

    /**
     * Newton iteration from {@code (u,v)} on the degree {@code n}×{@code m} net at
     * {@code net[off..]} (evaluated from its {@link PowerForm} at {@code net[power..]} when
     * {@code power ≥ 0}), within the domain, t range and root to avoid held in {@code w}
     * ({@link #setDomain}): {@link #CONVERGED} with the root in {@code ctx.rootU, rootV, rootT}, or
     * {@link #FAILED}. {@code ctx.eval} holds the last evaluation, at {@code ctx.evalU, evalV}
     * (the root itself unless the last step was taken unevaluated).
     */
    static int iterate(TraceContext ctx, double[] net, int off, int power, int n, int m, int dim, double u, double v,
                       double[] w, double tolerance) {
        double[] e = ctx.eval;
        double previous = Double.POSITIVE_INFINITY;
        for (int step = 0; step <= MAX_STEPS; step++) {
            if (power >= 0) {
                PowerForm.evaluateWithDerivatives(net, power, n, m, u, v, e, 0);
            } else {
                RationalDeCasteljau.pointAndDerivatives(net, off, n, m, dim, u, v, e, ctx.scratch);
            }
            ctx.evaluations++;
            double qx = e[0] - ctx.ox, qy = e[1] - ctx.oy, qz = e[2] - ctx.oz;
            double f1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz, f2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
            ctx.rootU = u;
            ctx.rootV = v;
            ctx.evalU = u;
            ctx.evalV = v;
            ctx.rootT = (ctx.n3x * qx + ctx.n3y * qy + ctx.n3z * qz) * ctx.invLength;
            double residual = Math.max(Math.abs(f1), Math.abs(f2));
            if (residual <= tolerance) {
                return CONVERGED;
            }
            if (step >= GROWTH_CHECK_FROM && residual > previous) {
                return FAILED;
            }
            previous = residual;
            double a = ctx.n1x * e[3] + ctx.n1y * e[4] + ctx.n1z * e[5], b = ctx.n1x * e[6] + ctx.n1y * e[7] + ctx.n1z * e[8];
            double c = ctx.n2x * e[3] + ctx.n2y * e[4] + ctx.n2z * e[5], d = ctx.n2x * e[6] + ctx.n2y * e[7] + ctx.n2z * e[8];
            double det = a * d - b * c;
            if (step == MAX_STEPS || !(Math.abs(det) > 1e-300) || Math.abs(det) <= 1e-14 * (Math.abs(a * d) + Math.abs(b * c))) {
                return FAILED;
            }
            double du = (b * f2 - d * f1) / det, dv = (c * f1 - a * f2) / det;
            // The step in world space: when it and the residual are tiny, one more evaluation
            // could only confirm what the quadratic convergence already gives
            double sx = e[3] * du + e[6] * dv, sy = e[4] * du + e[7] * dv, sz = e[5] * du + e[8] * dv;
            double move2 = sx * sx + sy * sy + sz * sz, close = CLOSE * tolerance;
            if (residual <= close && move2 <= close * close) {
                ctx.rootU = u + du;
                ctx.rootV = v + dv;
                ctx.rootT += (ctx.n3x * sx + ctx.n3y * sy + ctx.n3z * sz) * ctx.invLength;
                return CONVERGED;
            }
            u += du;
            v += dv;
            if (stopsEarly(ctx, w, u, v, move2 * ctx.invLength * ctx.invLength, step)) {
                return FAILED;
            }
        }
        return FAILED;
    }

    /**
     * True when the next iterate {@code (u,v)} leaves the domain, comes back to the root to avoid,
     * or (after the first step, in the quadratic regime, where the remaining steps move less than
     * this one, of squared length {@code move2} in t units) has a t beyond {@code (tMin, tMax)} by
     * more than this step.
     */
    private static boolean stopsEarly(TraceContext ctx, double[] w, double u, double v, double move2, int step) {
        if (!(u >= w[ULO] && u <= w[UHI] && v >= w[VLO] && v <= w[VHI])) {
            return true;
        }
        if (Math.abs(u - w[AVOID_U]) < SAME_ROOT * w[WIDTH_U] && Math.abs(v - w[AVOID_V]) < SAME_ROOT * w[WIDTH_V]) {
            return true;
        }
        double beyond = Math.max(ctx.rootT - w[TMAX], w[TMIN] - ctx.rootT);
        return step > 0 && beyond > 0 && beyond * beyond > move2;
    }
}
