package org.beziertracer.model;

/**
 * One curve of a trim loop: {@code curve} from parameter {@code from} to {@code to} (an OBJ
 * {@code trim}/{@code hole} triple {@code u0 u1 curv2d}); {@code from > to} runs the curve
 * backwards. Both ends lie in the curve's parameter range.
 */
public record TrimPiece(TrimCurve curve, double from, double to) {
    public TrimPiece {
        if (curve == null) {
            throw new IllegalArgumentException("a trim piece needs a curve");
        }
        double lo = curve.start(), hi = curve.end();
        if (!(from >= lo && from <= hi && to >= lo && to <= hi) || from == to) {
            throw new IllegalArgumentException("expected a curve range inside [" + lo + ", " + hi
                    + "] with different ends, found [" + from + ", " + to + "]");
        }
    }
}
