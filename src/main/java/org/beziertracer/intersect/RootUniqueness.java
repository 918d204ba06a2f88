package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * A sufficient test that a ray meets a ray-space piece at most once, from the bounds of the
 * piece's first derivatives (hodographs).
 *
 * <p>The ray meets the surface where {@code F = (F1, F2) = 0}, the first two ray-space
 * coordinates. If {@code p ≠ q} were two roots, the mean-value theorem along the segment
 * {@code d = q − p} gives {@code ∇F1(ξ1)·d = 0} and {@code ∇F2(ξ2)·d = 0} for some {@code ξ1},
 * {@code ξ2} of the piece; in the plane both gradients are then perpendicular to {@code d},
 * so {@code F1u(ξ1)·F2v(ξ2) − F1v(ξ1)·F2u(ξ2) = 0}. Bounding each partial derivative by the
 * range of its hodograph's control points (convex-hull property; the factors {@code n} and
 * {@code m} are common to both products and dropped) and evaluating that expression in interval
 * arithmetic: an interval that excludes zero proves the root, if any, is unique. This is the
 * single-solution test of G. Elber and M.-S. Kim, "Geometric constraint solver using
 * multivariate rational spline functions", ACM Solid Modeling 2001 (normal cones that do not
 * overlap), in its cheapest, box form.
 */
final class RootUniqueness {
    private RootUniqueness() {}

    /**
     * True when whole sub-patch {@code s} of {@code tab} provably meets the current ray of
     * {@code ctx} at most once, from its precomputed {@link SubPatchTable#uniqueness} balls: four
     * dot products, no pass over the net.
     *
     * <p>With {@code Su/n} in the ball {@code (a, ra)} and {@code Sv/m} in {@code (b, rb)}, the
     * four partial derivatives of the test below are {@code n1·a1, n1·b1, n2·a2, n2·b2} with
     * {@code a1 = a + α1}, {@code a2 = a + α2} ({@code |α| ≤ ra}) and {@code b1, b2} likewise. The
     * expression is {@code D0 = (n1·a)(n2·b) − (n1·b)(n2·a)} plus six cross terms, which pair up as
     * {@code |(n1·a)(n2·β2) − (n2·a)(n1·β1)| ≤ rb·(|n1·a| + |n2·a|)}, the same with {@code b} and
     * {@code ra}, and two products of deviations, each at most {@code ra·rb} ({@code |n·x| ≤ |x|}
     * for a unit {@code n}). So {@code |D0| > rb·(|n1·a| + |n2·a|) + ra·(|n1·b| + |n2·b|) + 2·ra·rb}
     * keeps the expression away from zero. A failure proves nothing; the caller then runs the box
     * test on the projected net, {@link #atMostOneRoot(double[], int, int, int)}.
     */
    static boolean atMostOneRoot(TraceContext ctx, SubPatchTable tab, int s) {
        double[] q = tab.uniqueness;
        int o = 9 * s;
        double ax = q[o], ay = q[o + 1], az = q[o + 2], bx = q[o + 3], by = q[o + 4], bz = q[o + 5];
        double ra = q[o + 6], rb = q[o + 7];
        double a1 = ctx.n1x * ax + ctx.n1y * ay + ctx.n1z * az, a2 = ctx.n2x * ax + ctx.n2y * ay + ctx.n2z * az;
        double b1 = ctx.n1x * bx + ctx.n1y * by + ctx.n1z * bz, b2 = ctx.n2x * bx + ctx.n2y * by + ctx.n2z * bz;
        double bound = rb * (Math.abs(a1) + Math.abs(a2)) + ra * (Math.abs(b1) + Math.abs(b2)) + 2 * ra * rb
                + q[o + 8];
        return Math.abs(a1 * b2 - b1 * a2) > bound;
    }

    /**
     * True when the piece at {@code net[base..]} (ray-space points, 3 doubles each, degree
     * {@code n}×{@code m}) provably meets the ray at most once.
     */
    static boolean atMostOneRoot(double[] net, int base, int n, int m) {
        int row = 3 * (n + 1);
        double f1uLo = Double.POSITIVE_INFINITY, f1uHi = Double.NEGATIVE_INFINITY;
        double f2uLo = Double.POSITIVE_INFINITY, f2uHi = Double.NEGATIVE_INFINITY;
        double f1vLo = Double.POSITIVE_INFINITY, f1vHi = Double.NEGATIVE_INFINITY;
        double f2vLo = Double.POSITIVE_INFINITY, f2vHi = Double.NEGATIVE_INFINITY;
        // Differences along u (hodograph in u) ...
        for (int j = 0; j <= m; j++) {
            for (int i = 0, p = base + j * row; i < n; i++, p += 3) {
                double d1 = net[p + 3] - net[p], d2 = net[p + 4] - net[p + 1];
                if (d1 < f1uLo) f1uLo = d1;
                if (d1 > f1uHi) f1uHi = d1;
                if (d2 < f2uLo) f2uLo = d2;
                if (d2 > f2uHi) f2uHi = d2;
            }
        }
        // ... and along v
        for (int p = base, end = base + m * row; p < end; p += 3) {
            double d1 = net[p + row] - net[p], d2 = net[p + row + 1] - net[p + 1];
            if (d1 < f1vLo) f1vLo = d1;
            if (d1 > f1vHi) f1vHi = d1;
            if (d2 < f2vLo) f2vLo = d2;
            if (d2 > f2vHi) f2vHi = d2;
        }
        // [f1u]·[f2v] − [f1v]·[f2u] must exclude zero
        double aLo = productLo(f1uLo, f1uHi, f2vLo, f2vHi), aHi = productHi(f1uLo, f1uHi, f2vLo, f2vHi);
        double bLo = productLo(f1vLo, f1vHi, f2uLo, f2uHi), bHi = productHi(f1vLo, f1vHi, f2uLo, f2uHi);
        // Margin for the rounding of the differences and products (relative, generous)
        double scale = (Math.abs(aLo) + Math.abs(aHi) + Math.abs(bLo) + Math.abs(bHi)) * 1e-12;
        return aLo - bHi > scale || aHi - bLo < -scale;
    }

    private static double productLo(double aLo, double aHi, double bLo, double bHi) {
        return Math.min(Math.min(aLo * bLo, aLo * bHi), Math.min(aHi * bLo, aHi * bHi));
    }

    private static double productHi(double aLo, double aHi, double bLo, double bHi) {
        return Math.max(Math.max(aLo * bLo, aLo * bHi), Math.max(aHi * bLo, aHi * bHi));
    }
}
