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
     * True when whole sub-patch {@code s} of {@code tab} provably meets any ray of unit direction
     * {@code (dx, dy, dz)} at most once, from its precomputed {@link SubPatchTable#uniqueness}
     * data: one dot product, no pass over the net.
     *
     * <p>With {@code Su/n} in the ball {@code (a, ra)} and {@code Sv/m} in {@code (b, rb)}, write
     * the four partial derivatives of the test above as {@code n1·a1, n1·b1, n2·a2, n2·b2} with
     * {@code a1, a2} in the first ball and {@code b1, b2} in the second. At the centres the
     * expression is {@code (n1·a)(n2·b) − (n1·b)(n2·a) = (n1 × n2)·(a × b) = d̂·(a × b)}
     * (Binet–Cauchy; {@code n1 × n2 = d̂} for the frame of {@link TraceContext}), and each of the six
     * cross terms of the expansion is at most a product of lengths ({@code |n·x| ≤ |x|} for a
     * unit {@code n}), in all {@code E = 2·(|a|·rb + |b|·ra + ra·rb)}. So {@code |d̂·(a × b)| > E}
     * keeps the expression away from zero. Weaker than the box test on the projected net, so a
     * failure proves nothing; the caller then runs {@link #atMostOneRoot(double[], int, int, int)}.
     */
    static boolean atMostOneRoot(SubPatchTable tab, int s, double dx, double dy, double dz) {
        double[] q = tab.uniqueness;
        int o = 4 * s;
        return Math.abs(dx * q[o] + dy * q[o + 1] + dz * q[o + 2]) > q[o + 3];
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
