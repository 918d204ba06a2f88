package org.beziertracer.model.io;

/**
 * An affine map {@code x' = R x + T} (IGES entity 124, transformation matrix: {@code R11 R12 R13
 * T1 R21 … T3}), row-major 3×4. Composition follows the IGES rule that an entity's matrix maps
 * into the space of the matrix its own directory entry points to. Immutable.
 */
record IgesMatrix(double[] m) {

    static final IgesMatrix IDENTITY = new IgesMatrix(new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});

    /** A uniform scale by {@code s}, then a move by {@code (x, y, z)}. */
    static IgesMatrix scaleMove(double s, double x, double y, double z) {
        return new IgesMatrix(new double[] {s, 0, 0, x, 0, s, 0, y, 0, 0, s, z});
    }

    boolean identity() {
        return java.util.Arrays.equals(m, IDENTITY.m);
    }

    /** {@code this ∘ inner}: first {@code inner}, then this. */
    IgesMatrix after(IgesMatrix inner) {
        if (inner.identity()) {
            return this;
        }
        if (identity()) {
            return inner;
        }
        double[] a = m, b = inner.m, c = new double[12];
        for (int r = 0; r < 3; r++) {
            for (int col = 0; col < 4; col++) {
                double s = col == 3 ? a[4 * r + 3] : 0;
                for (int k = 0; k < 3; k++) {
                    s += a[4 * r + k] * b[4 * k + col];
                }
                c[4 * r + col] = s;
            }
        }
        return new IgesMatrix(c);
    }

    /** The points {@code x y z …} mapped (the same array when this is the identity). */
    double[] apply(double[] points) {
        if (identity()) {
            return points;
        }
        double[] out = new double[points.length];
        for (int k = 0; k + 2 < points.length; k += 3) {
            double x = points[k], y = points[k + 1], z = points[k + 2];
            for (int r = 0; r < 3; r++) {
                out[k + r] = m[4 * r] * x + m[4 * r + 1] * y + m[4 * r + 2] * z + m[4 * r + 3];
            }
        }
        return out;
    }
}
