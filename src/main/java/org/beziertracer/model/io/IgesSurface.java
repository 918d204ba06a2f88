package org.beziertracer.model.io;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimRegion;

/**
 * One IGES surface as an exact rational B-spline surface (the form of entity 128, to which the
 * surface of revolution 120, the tabulated cylinder 122 and the bounded plane 108 convert
 * exactly): degrees, knots, {@code countU × countV} control points (u fastest), weights (null
 * when polynomial) and the parameter range used. Immutable.
 *
 * @param trimmable whether parameter-space trim curves of a file can refer to these parameters
 *                  (false for a surface of revolution, whose angle has no exact rational map)
 */
record IgesSurface(int degreeU, int degreeV, double[] knotsU, double[] knotsV, int countU, int countV,
                   double[] points, double[] weights, double[] range, boolean trimmable) {

    /** A surface with its trim region (null when untrimmed), before it is mapped into place. */
    record Trimmed(IgesSurface surface, TrimRegion trim) { }

    /**
     * The surface mapped by {@code m} (affine: exact), with {@code trim}.
     *
     * @throws IllegalArgumentException one line naming the problem (a degree above 15, bad knots)
     */
    FreeFormSurface toFreeForm(TrimRegion trim, IgesMatrix m) {
        return new FreeFormSurface(SplineBasis.BSPLINE, degreeU, degreeV, knotsU, knotsV, countU, countV,
                m.apply(points), weights, range, trim);
    }

    /**
     * The surface swept by {@code curve} moved along {@code direction} (entity 122: u the curve's
     * parameter normalised to [0, 1], v in [0, 1]).
     */
    static IgesSurface tabulated(IgesCurve curve, double[] direction) {
        int n = curve.count();
        double[] pts = new double[6 * n], w = curve.weights() == null ? null : new double[2 * n];
        double[] c = curve.points();
        for (int k = 0; k < n; k++) {
            for (int a = 0; a < 3; a++) {
                pts[3 * k + a] = c[3 * k + a];
                pts[3 * (n + k) + a] = c[3 * k + a] + direction[a];
            }
            if (w != null) {
                w[k] = curve.weights()[k];
                w[n + k] = curve.weights()[k];
            }
        }
        double[] knots = curve.knots().clone();
        double t0 = curve.t0(), span = curve.t1() - curve.t0();
        for (int k = 0; k < knots.length; k++) {
            knots[k] = (knots[k] - t0) / span;
        }
        // the normalised range is [0, 1] exactly, whatever the rounding of the knots
        double[] range = {0, 1, 0, 1};
        clampEnds(knots, curve.degree());
        return new IgesSurface(curve.degree(), 1, knots, new double[] {0, 0, 1, 1}, n, 2, pts, w, range, true);
    }

    /** The end knots raised to 1 where rounding left them below, so the range [0, 1] lies inside. */
    private static void clampEnds(double[] knots, int degree) {
        for (int k = knots.length - 1 - degree; k < knots.length; k++) {
            knots[k] = Math.max(knots[k], 1); // (end − t0) / (t1 − t0) may round below 1
        }
    }

    /**
     * The surface of revolution of {@code curve} about the axis through {@code a} along unit
     * {@code d}, from angle {@code from} to {@code to} (entity 120; Piegl &amp; Tiller §8.5,
     * algorithm A8.1): u the curve's parameter, v quarter arcs at most.
     */
    static IgesSurface revolution(IgesCurve curve, double[] a, double[] d, double from, double to) {
        int n = curve.count();
        IgesCurve unit = IgesCurve.arc(new double[3], new double[] {1, 0, 0}, new double[] {0, 1, 0}, from, to);
        int m = unit.count();
        double[] c = curve.points(), pts = new double[3 * n * m], w = new double[n * m];
        double[] arc = unit.points();
        for (int k = 0; k < n; k++) {
            double px = c[3 * k] - a[0], py = c[3 * k + 1] - a[1], pz = c[3 * k + 2] - a[2];
            double along = px * d[0] + py * d[1] + pz * d[2];
            double[] o = {a[0] + along * d[0], a[1] + along * d[1], a[2] + along * d[2]};
            double[] x = {c[3 * k] - o[0], c[3 * k + 1] - o[1], c[3 * k + 2] - o[2]};
            double[] y = {d[1] * x[2] - d[2] * x[1], d[2] * x[0] - d[0] * x[2], d[0] * x[1] - d[1] * x[0]};
            double wk = curve.weights() == null ? 1 : curve.weights()[k];
            for (int j = 0; j < m; j++) {
                int at = j * n + k;
                double cos = arc[3 * j], sin = arc[3 * j + 1];
                for (int q = 0; q < 3; q++) {
                    pts[3 * at + q] = o[q] + cos * x[q] + sin * y[q];
                }
                w[at] = wk * unit.weights()[j];
            }
        }
        return new IgesSurface(curve.degree(), 2, curve.knots(), unit.knots(), n, m, pts, w,
                new double[] {curve.t0(), curve.t1(), unit.t0(), unit.t1()}, false);
    }
}
