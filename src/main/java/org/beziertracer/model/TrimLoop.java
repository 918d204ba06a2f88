package org.beziertracer.model;

import java.util.List;

import org.beziertracer.math.BezierDecomposition;

/**
 * A closed loop of trim curves in a surface's parameter domain, in order: each piece ends where
 * the next one starts and the last where the first starts, within {@link #CLOSURE_TOLERANCE}
 * (relative to the larger of 1 and the coordinates). Remaining gaps of that size are closed by
 * straight segments when the loop is used, so the loop is exactly closed. Immutable.
 */
public record TrimLoop(List<TrimPiece> pieces) {

    /** Largest gap allowed between consecutive pieces, relative to {@code max(1, |u|, |v|)}. */
    public static final double CLOSURE_TOLERANCE = 1e-9;

    public TrimLoop {
        pieces = List.copyOf(pieces);
        if (pieces.isEmpty()) {
            throw new IllegalArgumentException("a trim loop needs at least one curve");
        }
        double[][] ends = new double[pieces.size()][];
        for (int k = 0; k < ends.length; k++) {
            ends[k] = ends(pieces.get(k));
        }
        for (int k = 0; k < ends.length; k++) {
            double[] a = ends[k], b = ends[(k + 1) % ends.length];
            double gap = Math.hypot(b[0] - a[2], b[1] - a[3]);
            double scale = Math.max(1, Math.max(Math.max(Math.abs(a[2]), Math.abs(a[3])),
                    Math.max(Math.abs(b[0]), Math.abs(b[1]))));
            if (!(gap <= CLOSURE_TOLERANCE * scale)) {
                throw new IllegalArgumentException("expected a closed trim loop, found a gap of " + gap + " between the end ("
                        + a[2] + ", " + a[3] + ") of curve " + (k + 1) + " and the start (" + b[0] + ", " + b[1]
                        + ") of curve " + ((k + 1) % ends.length + 1) + " (at most " + CLOSURE_TOLERANCE + " allowed)");
            }
        }
    }

    /** Control points of the unit circle from (1,0) counter-clockwise: 9 points, 4 quarter arcs. */
    private static final double[] UNIT_CIRCLE = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};

    /**
     * The exact circle of centre {@code (cu, cv)} and radius {@code r}, one rational quadratic
     * B-spline of 9 points (4 quarter arcs, weights {@code 1, √2/2, 1}; Piegl &amp; Tiller §7.5),
     * counter-clockwise or clockwise, on {@code [0,4]}.
     */
    public static TrimLoop circle(double cu, double cv, double r, boolean ccw) {
        double[] pts = new double[18], w = new double[9];
        for (int k = 0; k < 9; k++) {
            pts[2 * k] = cu + r * UNIT_CIRCLE[2 * k];
            pts[2 * k + 1] = cv + r * (ccw ? UNIT_CIRCLE[2 * k + 1] : -UNIT_CIRCLE[2 * k + 1]);
            w[k] = k % 2 == 0 ? 1 : Math.sqrt(0.5);
        }
        double[] knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
        return new TrimLoop(List.of(new TrimPiece(new TrimCurve(SplineBasis.BSPLINE, 2, knots, pts, w), 0, 4)));
    }

    /** The closed polygon through the corners {@code u0 v0 u1 v1 …}, one degree-1 B-spline. */
    public static TrimLoop polygon(double... uv) {
        int count = uv.length / 2 + 1;
        double[] pts = java.util.Arrays.copyOf(uv, 2 * count);
        pts[2 * count - 2] = uv[0];
        pts[2 * count - 1] = uv[1];
        double[] knots = new double[count + 2];
        for (int k = 0; k < knots.length; k++) {
            knots[k] = Math.max(0, Math.min(count - 1, k - 1));
        }
        return new TrimLoop(List.of(new TrimPiece(new TrimCurve(SplineBasis.BSPLINE, 1, knots, pts, null), 0, count - 1)));
    }

    /** {@code (u, v)} of the piece's start, then of its end. */
    public static double[] ends(TrimPiece piece) {
        TrimCurve c = piece.curve();
        double lo = Math.min(piece.from(), piece.to()), hi = Math.max(piece.from(), piece.to());
        BezierDecomposition.Segments s = BezierDecomposition.curve(c.degree(), c.knots(), c.homogeneous(), 3, lo, hi);
        double[] p = s.points();
        int first = 0, last = p.length - 3;
        if (piece.from() > piece.to()) {
            first = last;
            last = 0;
        }
        return new double[] {p[first] / p[first + 2], p[first + 1] / p[first + 2],
                p[last] / p[last + 2], p[last + 1] / p[last + 2]};
    }
}
