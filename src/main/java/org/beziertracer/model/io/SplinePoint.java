package org.beziertracer.model.io;

/**
 * A point of a rational B-spline surface by de Boor's algorithm in each direction (Piegl &amp;
 * Tiller, <i>The NURBS Book</i>, 1997, algorithms A2.1, A2.2 and A4.3): the STEP writer's vertices and
 * the reader's projection of vertices onto line trims. Immutable.
 */
record SplinePoint(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV, double[] points,
                   double[] weights) {

    /** The points of {@code s} (in its own frame). */
    static SplinePoint of(IgesSurface s) {
        return new SplinePoint(s.degreeU(), s.degreeV(), s.knotsU(), s.knotsV(), s.countU(), s.countV(), s.points(),
                s.weights());
    }

    /** The point {@code (u, v)} at {@code t} of a rational 2-D B-spline ({@code u v} pairs, weights or null). */
    static double[] curve(int degree, double[] knots, double[] uv, double[] weights, double t) {
        int count = uv.length / 2, s = span(knots, degree, count, t);
        double[] b = basis(knots, degree, s, t);
        double u = 0, v = 0, w = 0;
        for (int i = 0; i <= degree; i++) {
            int k = s - degree + i;
            double bw = b[i] * (weights == null ? 1 : weights[k]);
            u += bw * uv[2 * k];
            v += bw * uv[2 * k + 1];
            w += bw;
        }
        return new double[] {u / w, v / w};
    }

    double[] at(double u, double v) {
        int su = span(knotsU, p, countU, u), sv = span(knotsV, q, countV, v);
        double[] bu = basis(knotsU, p, su, u), bv = basis(knotsV, q, sv, v);
        double x = 0, y = 0, z = 0, w = 0;
        for (int j = 0; j <= q; j++) {
            for (int i = 0; i <= p; i++) {
                int k = (sv - q + j) * countU + (su - p + i);
                double b = bu[i] * bv[j] * (weights == null ? 1 : weights[k]);
                x += b * points[3 * k];
                y += b * points[3 * k + 1];
                z += b * points[3 * k + 2];
                w += b;
            }
        }
        return new double[] {x / w, y / w, z / w};
    }

    /** The knot span {@code [t_s, t_s+1)} holding {@code t} (the last non-empty one at the end). */
    static int span(double[] t, int degree, int count, double x) {
        int s = degree;
        while (s < count - 1 && !(x < t[s + 1])) {
            s++;
        }
        while (s > degree && !(t[s] < t[s + 1])) {
            s--; // at the end of the range: the last span that is not empty
        }
        return s;
    }

    /** The {@code degree + 1} non-zero basis functions at {@code x} in span {@code s} (Cox–de Boor, A2.2). */
    static double[] basis(double[] t, int degree, int s, double x) {
        double[] n = new double[degree + 1], left = new double[degree + 1], right = new double[degree + 1];
        n[0] = 1;
        for (int j = 1; j <= degree; j++) {
            left[j] = x - t[s + 1 - j];
            right[j] = t[s + j] - x;
            double saved = 0;
            for (int r = 0; r < j; r++) {
                double temp = n[r] / (right[r + 1] + left[j - r]);
                n[r] = saved + right[r + 1] * temp;
                saved = left[j - r] * temp;
            }
            n[j] = saved;
        }
        return n;
    }

    /** Homogeneous points {@code (w·x, w·y, w·z, w)} of {@code xyz} points and their weights (null: all 1). */
    static double[] homogeneous(double[] points, double[] weights) {
        int n = points.length / 3;
        double[] h = new double[4 * n];
        for (int k = 0; k < n; k++) {
            double wk = weights == null ? 1 : weights[k];
            h[4 * k] = wk * points[3 * k];
            h[4 * k + 1] = wk * points[3 * k + 1];
            h[4 * k + 2] = wk * points[3 * k + 2];
            h[4 * k + 3] = wk;
        }
        return h;
    }
}
