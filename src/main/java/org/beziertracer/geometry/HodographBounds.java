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

    /**
     * The same data for a rational net: Euclidean points {@code xyz[off..]} and their weights
     * {@code w[wOff..]}. The first derivative of the rational patch is
     * {@code S_u = (H_u.xyz − S·H_u.w) / H.w} (quotient rule on the homogeneous patch {@code H});
     * with {@code c} the centre of the control box, {@code H_u.xyz − S·H_u.w =
     * n·Σ Δ(w·(P−c))·B − (S−c)·n·Σ Δw·B}, so over the piece {@code S_u/n} lies in the box
     * {@code [a_lo − h·D, a_hi + h·D] / [w_min, w_max]} (interval arithmetic), {@code a} ranging
     * over the differences {@code Δ(w·(P−c))}, {@code h} the half extents of the control box,
     * {@code D} the largest {@code |Δw|} and {@code w} over the weights (the convex-hull
     * property of {@code H}). The ball around that box is looser than a polynomial piece's, and
     * tight for flat pieces with even weights.
     */
    static void computeRational(double[] xyz, int off, double[] w, int wOff, int n, int m, double[] out, int o) {
        int points = (n + 1) * (m + 1);
        double[] lo = new double[3], hi = new double[3];
        double wMin = Double.POSITIVE_INFINITY, wMax = 0;
        for (int k = 0; k < points; k++) {
            for (int c = 0; c < 3; c++) {
                lo[c] = Math.min(k == 0 ? Double.POSITIVE_INFINITY : lo[c], xyz[off + 3 * k + c]);
                hi[c] = Math.max(k == 0 ? Double.NEGATIVE_INFINITY : hi[c], xyz[off + 3 * k + c]);
            }
            wMin = Math.min(wMin, w[wOff + k]);
            wMax = Math.max(wMax, w[wOff + k]);
        }
        double ra = rationalBall(xyz, off, w, wOff, n, m, 1, n + 1, lo, hi, wMin, wMax, out, o);
        double rb = rationalBall(xyz, off, w, wOff, n, m, n + 1, n + 1, lo, hi, wMin, wMax, out, o + 3);
        double la = Math.sqrt(out[o] * out[o] + out[o + 1] * out[o + 1] + out[o + 2] * out[o + 2]);
        double lb = Math.sqrt(out[o + 3] * out[o + 3] + out[o + 4] * out[o + 4] + out[o + 5] * out[o + 5]);
        out[o + 6] = ra;
        out[o + 7] = rb;
        out[o + 8] = 1e-10 * (la + ra) * (lb + rb);
    }

    /**
     * Centre (to {@code out[o..o+3)}) and radius of a ball holding {@code S_u/n} ({@code step} 1)
     * or {@code S_v/m} ({@code step} = points per row) over a rational piece; see
     * {@link #computeRational}.
     */
    private static double rationalBall(double[] xyz, int off, double[] w, int wOff, int n, int m, int step, int row,
                                       double[] lo, double[] hi, double wMin, double wMax, double[] out, int o) {
        double[] aLo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] aHi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double dMax = 0;
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int p = j * row + i, q = p + step;
                if ((step == 1 && i == n) || (step != 1 && j == m)) {
                    continue;
                }
                double wp = w[wOff + p], wq = w[wOff + q];
                dMax = Math.max(dMax, Math.abs(wq - wp));
                for (int c = 0; c < 3; c++) {
                    double centre = 0.5 * (lo[c] + hi[c]);
                    double a = wq * (xyz[off + 3 * q + c] - centre) - wp * (xyz[off + 3 * p + c] - centre);
                    aLo[c] = Math.min(aLo[c], a);
                    aHi[c] = Math.max(aHi[c], a);
                }
            }
        }
        double r2 = 0;
        for (int c = 0; c < 3; c++) {
            double h = 0.5 * (hi[c] - lo[c]);
            double nLo = aLo[c] - h * dMax, nHi = aHi[c] + h * dMax;
            double sLo = nLo >= 0 ? nLo / wMax : nLo / wMin, sHi = nHi >= 0 ? nHi / wMin : nHi / wMax;
            out[o + c] = 0.5 * (sLo + sHi);
            r2 += 0.25 * (sHi - sLo) * (sHi - sLo);
        }
        return Math.sqrt(r2);
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
