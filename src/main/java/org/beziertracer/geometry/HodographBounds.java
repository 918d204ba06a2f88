package org.beziertracer.geometry;

/**
 * Ray-independent data for a cheap single-root test of a sub-patch (see
 * {@code intersect.RootUniqueness#atMostOneRoot(TraceContext, SubPatchTable, int)}):
 * the first-derivative directions of the net, bounded by balls.
 *
 * <p>The control points of the u-hodograph of a degree n×m net are {@code n·(P[i+1][j] − P[i][j])}
 * and those of the v-hodograph {@code m·(P[i][j+1] − P[i][j])} (Farin, "Curves and Surfaces for
 * CAGD", 5th ed., §16.6); by the convex-hull property {@code Su/n} lies, everywhere on the patch,
 * in the ball of centre {@code a} (centre of the differences' bounding box) and radius
 * {@code ra} (largest distance of a difference from {@code a}), and {@code Sv/m} in the ball
 * {@code (b, rb)}. Stored per sub-patch, {@link #STRIDE} doubles: {@code a, b, ra, rb} and a
 * margin for rounding.
 */
final class HodographBounds {
    private HodographBounds() {}

    /** Doubles per sub-patch in {@link SubPatchTable#uniqueness}. */
    static final int STRIDE = 9;

    /**
     * Writes {@code (a, b, ra, rb, margin)} of the degree {@code n}×{@code m} net at
     * {@code net[off..]} to {@code out[o..o+9)}; {@code ab} is scratch of 6 doubles.
     */
    static void compute(double[] net, int off, int n, int m, double[] out, int o, double[] ab) {
        int row = 3 * (n + 1);
        double ra = ballOf(net, off, n, m, 3, row, ab, 0);
        double rb = ballOf(net, off, n + 1, m - 1, row, row, ab, 3);
        System.arraycopy(ab, 0, out, o, 6);
        double la = Math.sqrt(ab[0] * ab[0] + ab[1] * ab[1] + ab[2] * ab[2]);
        double lb = Math.sqrt(ab[3] * ab[3] + ab[4] * ab[4] + ab[5] * ab[5]);
        out[o + 6] = ra;
        out[o + 7] = rb;
        // Rounding of the differences, of the centres' projections and of the products (generous)
        out[o + 8] = 1e-10 * (la + ra) * (lb + rb);
    }

    /** Writes data for which the single-root test never succeeds (infinite radii): for rational pieces. */
    static void never(double[] out, int o) {
        java.util.Arrays.fill(out, o, o + STRIDE, 0);
        out[o + 6] = Double.POSITIVE_INFINITY;
        out[o + 7] = Double.POSITIVE_INFINITY;
        out[o + 8] = Double.POSITIVE_INFINITY;
    }

    /**
     * Ball around the differences {@code net[p + step] − net[p]} for {@code cols} points per row
     * and {@code rows + 1} rows ({@code rowStride} doubles apart): centre to {@code ab[c..c+3)},
     * returns the radius. With {@code step = 3} and n columns of differences per row this is the
     * u-hodograph; with {@code step = rowStride} the v-hodograph.
     */
    private static double ballOf(double[] net, int off, int cols, int rows, int step, int rowStride,
                                 double[] ab, int c) {
        double loX = Double.POSITIVE_INFINITY, loY = loX, loZ = loX;
        double hiX = Double.NEGATIVE_INFINITY, hiY = hiX, hiZ = hiX;
        for (int pass = 0; pass < 2; pass++) {
            double cx = 0.5 * (loX + hiX), cy = 0.5 * (loY + hiY), cz = 0.5 * (loZ + hiZ), r2 = 0;
            for (int j = 0; j <= rows; j++) {
                for (int i = 0, p = off + j * rowStride; i < cols; i++, p += 3) {
                    double x = net[p + step] - net[p], y = net[p + step + 1] - net[p + 1];
                    double z = net[p + step + 2] - net[p + 2];
                    if (pass == 0) {
                        loX = Math.min(loX, x); hiX = Math.max(hiX, x);
                        loY = Math.min(loY, y); hiY = Math.max(hiY, y);
                        loZ = Math.min(loZ, z); hiZ = Math.max(hiZ, z);
                    } else {
                        double ex = x - cx, ey = y - cy, ez = z - cz;
                        r2 = Math.max(r2, ex * ex + ey * ey + ez * ez);
                    }
                }
            }
            if (pass == 1) {
                ab[c] = cx; ab[c + 1] = cy; ab[c + 2] = cz;
                return Math.sqrt(r2);
            }
        }
        throw new AssertionError();
    }
}
