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
