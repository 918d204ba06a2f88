package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * A shadow ray's own leaf, proven to hold at most one root for the ray, holds none ahead of the
 * ray: its one root is the origin's own point, just behind the ray's origin. Proven from the
 * evaluation kept at that point, without evaluating the patch.
 *
 * <p>The ray leaves {@code P = S(x0)}, {@code x0 = (u0, v0)}, from {@code O = P + h0·n}. In the
 * ray's frame the roots are the zeros of {@code F(x) = (n1·(S(x) − O), n2·(S(x) − O))}, with
 * Jacobian {@code J = [n1·Su n1·Sv; n2·Su n2·Sv]}. The simplified Newton map
 * {@code G(x) = x − J̃⁻¹F(x)}, {@code J̃} the Jacobian kept at {@code x0}, is a contraction by
 * {@code q = β·(εJ + M·r)} on the ball {@code ‖x − x0‖₁ ≤ r}, where {@code β ≥ ‖J̃⁻¹‖},
 * {@code M} bounds the patch's second derivatives (so {@code J} moves by at most {@code M·r} there)
 * and {@code εJ} bounds how far the kept derivatives may be from the exact ones at {@code x0};
 * when {@code η/(1 − q) ≤ r}, {@code η} the first step's length (plus the kept point's error), it
 * maps the ball into itself and has a fixed point there (Banach), a root of the patch: the
 * Newton–Kantorovich argument (L. V. Kantorovich, "On Newton's method for functional equations",
 * 1948; J. M. Ortega and W. C. Rheinboldt, <i>Iterative Solution of Nonlinear Equations in Several
 * Variables</i>, 1970, ch. 12.6). With {@code r = 2η} and {@code q ≤ ½} both hold. That root lies
 * within {@code q·r} of the first Newton iterate {@code x1 = x0 + δ}, so its distance along the
 * ray is at most the linear model's at {@code x1}, plus {@code max(|Su|, |Sv|)·q·r} for the
 * distance to {@code x1}, {@code ½·M·r²} for the curvature and the kept values' errors. When the
 * ball lies in the leaf and that distance is below {@code tMin}, the leaf's only root is behind the
 * ray and the leaf is not searched. What the search would have found is the same: that root, out
 * of the ray's interval.
 *
 * <p>The kept point and derivatives are those the renderer shaded with: the solver's last
 * evaluation, moved by up to two unevaluated Newton steps ({@link RayPatchNewton#extrapolate},
 * {@link RayPatchNewton#refine}), each within {@link RayPatchNewton#EXTRAPOLATED} of the
 * tolerance; so the point is within {@code 2·EXTRAPOLATED·tolerance} of {@code S(x0)} and the
 * derivatives within {@code M} times the two steps' lengths of the exact ones. A grazing ray (a
 * nearly singular {@code J̃}) or an origin near the leaf's border proves nothing and is searched
 * as before.
 */
final class OriginRoot {
    private OriginRoot() {}

    /** The contraction factor the ball must reach (Kantorovich's ½, with room for rounding). */
    static final double CONTRACTION = 0.25;

    /**
     * True when leaf {@code s}, the leaf the context's any-hit ray leaves ({@code ctx.originLeaf},
     * its derivatives kept), provably holds a root of the ray within the leaf behind
     * {@code tMin}: since the caller proved the leaf holds at most one root, none lies ahead.
     * False when that is not proven (no kept derivatives, a rational or reparametrised patch, a
     * grazing ray, an origin too near the leaf's border).
     */
    static boolean behind(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tolerance) {
        int o = 4 * s;
        return s == ctx.originLeaf
                && behindIn(ctx, tab, tab.parent[s], tab.boxes[o], tab.boxes[o + 1], tab.boxes[o + 2], tab.boxes[o + 3],
                        tMin, tolerance);
    }

    /**
     * As {@link #behind}, for the piece {@code [uLo, uHi]×[vLo, vHi]} of patch {@code k} (the patch the
     * context's any-hit ray leaves, from a point of that piece), proven single-root for the ray by
     * the caller: a leaf, or a quarter of one ({@link LeafQuarters}).
     */
    static boolean behindIn(TraceContext ctx, SubPatchTable tab, int k, double uLo, double uHi, double vLo, double vHi,
                            double tMin, double tolerance) {
        double curvature = tab.patchCurvature[k];
        if (!ctx.originDerivatives || tab.patchDim[k] != 3 || !(curvature < Double.POSITIVE_INFINITY)
                || !SurfaceParameters.unit(tab.patchDomain, k)) {
            return false;
        }
        double qx = ctx.originPx - ctx.ox, qy = ctx.originPy - ctx.oy, qz = ctx.originPz - ctx.oz;
        double f1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz, f2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        double sux = ctx.originSux, suy = ctx.originSuy, suz = ctx.originSuz;
        double svx = ctx.originSvx, svy = ctx.originSvy, svz = ctx.originSvz;
        double a = ctx.n1x * sux + ctx.n1y * suy + ctx.n1z * suz, b = ctx.n1x * svx + ctx.n1y * svy + ctx.n1z * svz;
        double c = ctx.n2x * sux + ctx.n2y * suy + ctx.n2z * suz, d = ctx.n2x * svx + ctx.n2y * svy + ctx.n2z * svz;
        double det = a * d - b * c;
        if (!(Math.abs(det) > 1e-6 * (Math.abs(a * d) + Math.abs(b * c)))) {
            return false; // the ray sees the tangent plane edge-on, or NaN
        }
        double du = (b * f2 - d * f1) / det, dv = (c * f1 - a * f2) / det;
        // ‖J̃⁻¹‖ from the Euclidean residual to the step's |du| + |dv| (Cauchy–Schwarz on each row)
        // (Math.sqrt, not Math.hypot: a sum that overflows makes β infinite, which proves nothing)
        double beta = (Math.sqrt(b * b + d * d) + Math.sqrt(a * a + c * c)) / Math.abs(det) * (1 + 1e-12);
        double su = Math.sqrt(sux * sux + suy * suy + suz * suz), sv = Math.sqrt(svx * svx + svy * svy + svz * svz);
        double magnitude = Math.abs(ctx.originPx) + Math.abs(ctx.originPy) + Math.abs(ctx.originPz)
                + Math.abs(ctx.ox) + Math.abs(ctx.oy) + Math.abs(ctx.oz);
        // The kept values' errors: two unevaluated steps' remainders in the point (plus the
        // rounding of the point, of O and of the ray's frame), two steps' lengths in the derivatives
        double pointError = 2 * RayPatchNewton.EXTRAPOLATED * tolerance + 1e-14 * magnitude;
        double derivativeError = 2 * Math.sqrt(2 * RayPatchNewton.EXTRAPOLATED * tolerance * curvature)
                + 1e-14 * (su + sv);
        double stepError = beta * pointError; // the exact first step's distance from (du, dv)
        double eta = Math.abs(du) + Math.abs(dv) + stepError;
        double r = 2 * eta;
        double q = beta * (derivativeError + curvature * r);
        if (!(q <= CONTRACTION)) {
            return false;
        }
        // The ball ‖x − x0‖₁ ≤ r in the piece, where the piece's single root is the patch's only one
        double u0 = ctx.originU, v0 = ctx.originV;
        if (!(u0 - r >= uLo && u0 + r <= uHi && v0 - r >= vLo && v0 + r <= vHi)) {
            return false;
        }
        // Distance along the ray of that root: the linear model at x1, then the bounds
        double along = ctx.n3x * (qx + sux * du + svx * dv) + ctx.n3y * (qy + suy * du + svy * dv)
                + ctx.n3z * (qz + suz * du + svz * dv);
        double slack = Math.max(su, sv) * (q * r + stepError) + derivativeError * r + 0.5 * curvature * r * r + pointError
                + tolerance;
        return (along + slack) * ctx.invLength < tMin;
    }
}
