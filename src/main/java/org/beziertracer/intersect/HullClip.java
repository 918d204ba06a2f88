package org.beziertracer.intersect;

/**
 * Where the convex hull of a distance net's control points meets zero, in O(deg) (typically):
 * the core of the Bézier-clipping step (Nishita, Sederberg, Kakimoto, SIGGRAPH 1990; Sederberg and
 * Nishita, "Curve intersection using Bézier clipping", CAD 22(9), 1990).
 *
 * <p>Column {@code c} of the net contributes the vertical segment from {@code (c/deg, lo[c])} to
 * {@code (c/deg, hi[c])}. The hull is {@code {L(x) ≤ y ≤ U(x)}} with {@code L} the lower hull of
 * the points {@code (c/deg, lo[c])} (convex) and {@code U} the upper hull of the
 * {@code (c/deg, hi[c])} (concave). When the first column lies above zero, the left end of the
 * hull's intersection with the axis is the first zero of {@code L} (there {@code U ≥ L = 0}); it is
 * found by walking the lower hull from the first column: the next hull vertex is the point of
 * least slope, and the walk stops at the first edge that reaches zero. A first column below zero
 * walks {@code U} instead (as the lower hull of {@code -hi}), and the right end walks from the last
 * column. A column within {@code eps} of zero counts as touching it (robustness, Efremov, Havran,
 * Seidel, SCCG 2005). The result equals the smallest interval containing every crossing of a
 * segment between two control points of opposite sign, and every touching column.
 */
final class HullClip {
    private HullClip() {}

    /**
     * Writes {@code [a,b] ⊂ [0,1]}, the x-range where the hull meets zero, into {@code out[0..1]};
     * returns false when it misses zero.
     */
    static boolean zeroInterval(double[] lo, double[] hi, int deg, double eps, double[] out) {
        double invDeg = 1.0 / deg;
        double a = Double.POSITIVE_INFINITY, b = Double.NEGATIVE_INFINITY;
        // Touching columns
        for (int c = 0; c <= deg; c++) {
            if (lo[c] <= eps && hi[c] >= -eps) {
                a = c * invDeg;
                break;
            }
        }
        if (a == Double.POSITIVE_INFINITY) {
            // No column touches zero: the hull meets it only between a column above and one below
            a = fromEnd(lo, hi, deg, eps, 0, 1, invDeg);
            if (Double.isNaN(a)) {
                return false; // the hull stays on one side
            }
            b = fromEnd(lo, hi, deg, eps, deg, -1, invDeg);
            if (Double.isNaN(b)) {
                b = 1; // cannot happen once a exists; stay conservative
            }
            out[0] = Math.min(a, b); // equal up to rounding when the hull only touches zero
            out[1] = Math.max(a, b);
            return true;
        }
        // Some column touches: the ends are the hull crossings or the outermost touching columns
        if (a > 0) {
            double x = fromEnd(lo, hi, deg, eps, 0, 1, invDeg);
            if (x < a) a = x;
        }
        for (int c = deg; c >= 0; c--) {
            if (lo[c] <= eps && hi[c] >= -eps) {
                b = c * invDeg;
                break;
            }
        }
        if (b < 1) {
            double x = fromEnd(lo, hi, deg, eps, deg, -1, invDeg);
            if (x > b) b = x;
        }
        out[0] = a;
        out[1] = b;
        return true;
    }

    /**
     * Walks the lower hull of the points {@code (c/deg, sign·y[c])} from column {@code from} in
     * direction {@code dir} (±1); the start must lie above zero. Returns the x where the hull first
     * reaches zero, or NaN when every point beyond lies above zero.
     */
    private static double firstZero(double[] y, double sign, int deg, int from, int dir, double invDeg) {
        int cur = from;
        double yc = sign * y[cur];
        for (;;) {
            int next = -1;
            double least = Double.POSITIVE_INFINITY;
            for (int c = cur + dir, steps = 1; c >= 0 && c <= deg; c += dir, steps++) {
                double slope = (sign * y[c] - yc) / steps;
                if (slope < least) {
                    least = slope;
                    next = c;
                }
            }
            if (next < 0) {
                return Double.NaN;
            }
            double yn = sign * y[next];
            if (yn <= 0) {
                double xc = cur * invDeg, xn = next * invDeg;
                return xc + (xn - xc) * (yc / (yc - yn));
            }
            cur = next;
            yc = yn;
        }
    }

    /**
     * First hull crossing seen from the end column {@code from} (not touching zero), walking in
     * direction {@code dir}: along the lower hull when that column lies above zero, else along
     * the upper hull. NaN when there is none.
     */
    private static double fromEnd(double[] lo, double[] hi, int deg, double eps, int from, int dir, double invDeg) {
        return lo[from] > eps ? firstZero(lo, 1, deg, from, dir, invDeg) : firstZero(hi, -1, deg, from, dir, invDeg);
    }
}
