package org.beziertracer.math;

/**
 * Checks and queries on B-spline knot vectors (L. Piegl, W. Tiller, <i>The NURBS Book</i>, 2nd ed.,
 * Springer 1997, ch. 2). A curve of degree {@code p} with {@code count} control points has
 * {@code count + p + 1} knots {@code U_0 ≤ U_1 ≤ …}; it is defined on
 * {@code [U_p, U_count]}, clamped or not. Stateless.
 */
public final class KnotVector {
    private KnotVector() {}

    /**
     * Null when {@code knots} is a valid knot vector for {@code pointCount} control points of
     * degree {@code degree}, else one line saying what is wrong: the wrong length, a knot that
     * is not finite, a knot that decreases, a multiplicity above {@code degree + 1}, or an empty
     * parameter range {@code [U_p, U_count]}.
     */
    public static String problem(int degree, double[] knots, int pointCount) {
        int expected = pointCount + degree + 1;
        if (knots.length != expected) {
            return "expected " + expected + " knots (" + pointCount + " control points + degree " + degree
                    + " + 1), found " + knots.length;
        }
        int run = 1;
        for (int k = 0; k < knots.length; k++) {
            if (!Double.isFinite(knots[k])) {
                return "expected finite knots, found " + knots[k] + " as knot " + (k + 1);
            }
            if (k == 0) {
                continue;
            }
            if (knots[k] < knots[k - 1]) {
                return "expected knots that never decrease, found " + text(knots[k]) + " after " + text(knots[k - 1]);
            }
            run = knots[k] == knots[k - 1] ? run + 1 : 1;
            if (run > degree + 1) {
                return "expected each knot at most degree + 1 = " + (degree + 1) + " times, found "
                        + text(knots[k]) + " " + run + " times";
            }
        }
        if (!(knots[degree] < knots[pointCount])) {
            return "expected a non-empty parameter range [U_p, U_n] = [" + text(knots[degree]) + ", "
                    + text(knots[pointCount]) + "] (degree " + degree + ", " + pointCount + " control points)";
        }
        return null;
    }

    /** Start of the parameter range, {@code U_p}. */
    public static double start(int degree, double[] knots) {
        return knots[degree];
    }

    /** End of the parameter range, {@code U_count}. */
    public static double end(int degree, double[] knots) {
        return knots[knots.length - degree - 1];
    }

    /** How often {@code t} occurs among the first {@code length} knots. */
    static int multiplicity(double[] knots, int length, double t) {
        int count = 0;
        for (int k = 0; k < length; k++) {
            if (knots[k] == t) {
                count++;
            }
        }
        return count;
    }

    /**
     * The span {@code k} used to insert or evaluate at {@code t ∈ [U_p, U_count]}: the largest
     * index in {@code [p, count-1]} with {@code U_k ≤ t} and {@code U_k < U_{k+1}} (so at the end
     * of the range the last non-empty span).
     */
    static int span(int degree, double[] knots, int pointCount, double t) {
        int k = pointCount - 1;
        while (k > degree && (knots[k] > t || knots[k] == knots[k + 1])) {
            k--;
        }
        return k;
    }

    private static String text(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
