package org.beziertracer.model.io;

import org.beziertracer.math.BezierDecomposition;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimPiece;

/**
 * One IGES curve as an exact rational B-spline (the form of entity 126, to which lines 110 and
 * arcs 100 convert exactly): degree, knots, control points {@code x y z}, weights (null when
 * polynomial) and the parameter range {@code [t0, t1]} used. Immutable.
 *
 * <p>Arcs follow Piegl &amp; Tiller, <i>The NURBS Book</i> (1997), §7.5 (algorithm A7.1).
 */
record IgesCurve(int degree, double[] knots, double[] points, double[] weights, double t0, double t1) {

    /** The straight segment from {@code a} to {@code b}, on {@code [0, 1]}. */
    static IgesCurve line(double[] a, double[] b) {
        return new IgesCurve(1, new double[] {0, 0, 1, 1}, new double[] {a[0], a[1], a[2], b[0], b[1], b[2]}, null, 0, 1);
    }

    /**
     * The arc of centre {@code c}, axes {@code x}, {@code y} (each of length the radius) from angle
     * {@code from} to {@code to} (radians, {@code to > from}), quarter arcs at most, on {@code [0, arcs]}.
     */
    static IgesCurve arc(double[] c, double[] x, double[] y, double from, double to) {
        int arcs = Math.max(1, (int) Math.ceil((to - from) / (Math.PI / 2) - 1e-12));
        double step = (to - from) / arcs, w1 = Math.cos(step / 2);
        double[] pts = new double[3 * (2 * arcs + 1)], w = new double[2 * arcs + 1];
        for (int k = 0; k <= 2 * arcs; k++) {
            double angle = from + k * step / 2, s = k % 2 == 0 ? 1 : 1 / w1;
            double cos = Math.cos(angle) * s, sin = Math.sin(angle) * s;
            for (int a = 0; a < 3; a++) {
                pts[3 * k + a] = c[a] + cos * x[a] + sin * y[a];
            }
            w[k] = k % 2 == 0 ? 1 : w1;
        }
        double[] knots = new double[2 * arcs + 4];
        for (int k = 0; k < knots.length; k++) {
            knots[k] = Math.max(0, Math.min(arcs, (k - 1) / 2));
        }
        return new IgesCurve(2, knots, pts, w, 0, arcs);
    }

    int count() { return points.length / 3; }

    /** This curve with every control point mapped by {@code m} (an affine map keeps the curve exact). */
    IgesCurve mapped(IgesMatrix m) {
        return new IgesCurve(degree, knots, m.apply(points), weights, t0, t1);
    }

    /** The point at {@code t0} (or {@code t1}), exact to rounding (a Bézier end point after knot insertion). */
    double[] end(boolean last) {
        double[] h = SplinePoint.homogeneous(points, weights);
        double[] p = BezierDecomposition.curve(degree, knots, h, 4, t0, t1).points();
        int at = last ? p.length - 4 : 0;
        return new double[] {p[at] / p[at + 3], p[at + 1] / p[at + 3], p[at + 2] / p[at + 3]};
    }

    /** The curve's {@code x y} as a parameter-space trim piece, run backwards when {@code reversed}. */
    TrimPiece toTrimPiece(boolean reversed) {
        double[] uv = new double[2 * count()];
        for (int k = 0; k < count(); k++) {
            uv[2 * k] = points[3 * k];
            uv[2 * k + 1] = points[3 * k + 1];
        }
        TrimCurve c = new TrimCurve(SplineBasis.BSPLINE, degree, knots, uv, weights);
        return reversed ? new TrimPiece(c, t1, t0) : new TrimPiece(c, t0, t1);
    }
}
