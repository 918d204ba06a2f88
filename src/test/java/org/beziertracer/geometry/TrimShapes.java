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

    /** The exact circle ({@link TrimLoop#circle}). */
    static TrimLoop circle(double cx, double cy, double r, boolean ccw) {
        return TrimLoop.circle(cx, cy, r, ccw);
    }

    /** A closed polygon as one degree-1 B-spline ({@link TrimLoop#polygon}). */
    static TrimLoop polygon(double... uv) {
        return TrimLoop.polygon(uv);
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
