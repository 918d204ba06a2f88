package org.beziertracer.model;

import java.util.Arrays;

import org.beziertracer.math.KnotVector;

/**
 * An immutable 2-D curve in a surface's parameter domain (an OBJ {@code curv2}): Bézier or
 * B-spline, rational or not, of degree 1..{@value BezierPatch#MAX_DEGREE}.
 *
 * <p>{@code points} holds the control points as {@code u, v} pairs; {@code weights} is null for a
 * polynomial curve, else one positive finite weight per point (kept as given, also when all are
 * 1, so the curve is written back as it was read). {@code parm} is read as {@link SplineBasis}
 * says: the knot vector of a B-spline, the segment breakpoints of a Bézier curve. The curve is
 * defined on {@code [start(), end()]}.
 */
public final class TrimCurve {

    private final SplineBasis basis;
    private final int degree;
    private final double[] parm;
    private final double[] points;
    private final double[] weights;

    /**
     * @throws IllegalArgumentException one line naming the problem: a degree out of range, a
     *                                  parameter vector that does not fit, a non-finite
     *                                  coordinate, a weight that is not positive and finite
     */
    public TrimCurve(SplineBasis basis, int degree, double[] parm, double[] points, double[] weights) {
        BezierPatch.checkDegree("the curve", degree);
        if (points.length % 2 != 0 || points.length < 4) {
            throw new IllegalArgumentException("a curve needs at least 2 control points (u v pairs), got "
                    + points.length + " coordinates");
        }
        int count = points.length / 2;
        String problem = basis.problem(degree, parm, count);
        if (problem != null) {
            throw new IllegalArgumentException(problem);
        }
        for (double x : points) {
            if (!Double.isFinite(x)) {
                throw new IllegalArgumentException("control point coordinates must be finite, got " + x);
            }
        }
        if (weights != null) {
            BezierPatch.checkWeights(weights, count);
        }
        this.basis = basis;
        this.degree = degree;
        this.parm = parm.clone();
        this.points = points.clone();
        this.weights = weights == null ? null : weights.clone();
    }

    public SplineBasis basis() { return basis; }

    public int degree() { return degree; }

    public boolean rational() { return weights != null; }

    public int pointCount() { return points.length / 2; }

    /** The parameter values as given (a copy). */
    public double[] parm() { return parm.clone(); }

    /** {@code u, v} pairs (a copy). */
    public double[] points() { return points.clone(); }

    /** The weights (a copy), or null for a polynomial curve. */
    public double[] weights() { return weights == null ? null : weights.clone(); }

    /** The B-spline knot vector. */
    public double[] knots() { return basis.knotVector(degree, parm); }

    public double start() { return KnotVector.start(degree, knots()); }

    public double end() { return KnotVector.end(degree, knots()); }

    /** Homogeneous control points {@code (w·u, w·v, w)}, 3 doubles each ({@code w = 1} when polynomial). */
    public double[] homogeneous() {
        int count = pointCount();
        double[] h = new double[3 * count];
        for (int k = 0; k < count; k++) {
            double w = weights == null ? 1 : weights[k];
            h[3 * k] = w * points[2 * k];
            h[3 * k + 1] = w * points[2 * k + 1];
            h[3 * k + 2] = w;
        }
        return h;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof TrimCurve c && c.basis == basis && c.degree == degree && Arrays.equals(c.parm, parm)
                && Arrays.equals(c.points, points) && Arrays.equals(c.weights, weights);
    }

    @Override
    public int hashCode() {
        return ((basis.hashCode() * 31 + degree) * 31 + Arrays.hashCode(points)) * 31 + Arrays.hashCode(parm);
    }

    @Override
    public String toString() {
        return (rational() ? "rational " : "") + basis.objName() + " curve of degree " + degree + ", "
                + pointCount() + " points";
    }
}
