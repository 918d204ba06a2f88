package org.beziertracer.geometry;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;

/** Trim loops with known insides for the trimming tests. */
final class TrimShapes {
    private TrimShapes() {}

    static final double H = Math.sqrt(0.5);

    /**
     * The exact circle as one rational quadratic B-spline (9 points, 4 quarter arcs; Piegl &amp;
     * Tiller §7.5), counter-clockwise or clockwise.
     */
    static TrimLoop circle(double cx, double cy, double r, boolean ccw) {
        double[] unit = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
        double[] pts = new double[18], w = new double[9];
        for (int k = 0; k < 9; k++) {
            double x = unit[2 * k], y = unit[2 * k + 1];
            pts[2 * k] = cx + r * x;
            pts[2 * k + 1] = cy + r * (ccw ? y : -y);
            w[k] = k % 2 == 0 ? 1 : H;
        }
        double[] knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
        TrimCurve c = new TrimCurve(SplineBasis.BSPLINE, 2, knots, pts, w);
        return new TrimLoop(List.of(new TrimPiece(c, 0, 1)));
    }

    /** A closed polygon as one degree-1 B-spline through the corners (the first repeated at the end). */
    static TrimLoop polygon(double... uv) {
        int count = uv.length / 2 + 1;
        double[] pts = java.util.Arrays.copyOf(uv, 2 * count);
        pts[2 * count - 2] = uv[0];
        pts[2 * count - 1] = uv[1];
        double[] knots = new double[count + 2];
        for (int k = 0; k < knots.length; k++) {
            knots[k] = Math.max(0, Math.min(count - 1, k - 1));
        }
        TrimCurve c = new TrimCurve(SplineBasis.BSPLINE, 1, knots, pts, null);
        return new TrimLoop(List.of(new TrimPiece(c, 0, count - 1)));
    }

    /** The same polygon as one straight Bézier curve per edge, several curves per loop. */
    static TrimLoop polygonOfEdges(double... uv) {
        List<TrimPiece> pieces = new ArrayList<>();
        int n = uv.length / 2;
        for (int k = 0; k < n; k++) {
            int a = 2 * k, b = 2 * ((k + 1) % n);
            TrimCurve edge = new TrimCurve(SplineBasis.BEZIER, 1, new double[] {0, 1},
                    new double[] {uv[a], uv[a + 1], uv[b], uv[b + 1]}, null);
            pieces.add(new TrimPiece(edge, 0, 1));
        }
        return new TrimLoop(pieces);
    }
}
