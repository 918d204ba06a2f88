package org.beziertracer.geometry;

/**
 * Rational Bézier patches in homogeneous form, on flat arrays, allocation-free.
 *
 * <h2>Homogeneous nets</h2>
 * A rational patch {@code S = Σ w_ij P_ij B_i B_j / Σ w_ij B_i B_j} is the central projection of
 * the polynomial patch {@code H(u,v)} in 4-D whose control points are
 * {@code H_ij = (w_ij·x, w_ij·y, w_ij·z, w_ij)}: {@code S = H.xyz / H.w}. A homogeneous net is
 * stored with {@code dim = 4} in the layout of {@link DeCasteljau} (u fastest), so splitting,
 * restriction and sub-patches are {@link DeCasteljau}'s own algorithms with {@code dim = 4}: they
 * are exact for the rational patch because de Casteljau commutes with the projection (G. Farin,
 * <i>Curves and Surfaces for CAGD</i>, 5th ed., the chapter on rational Bézier curves and
 * surfaces; L. Piegl, W. Tiller, <i>The NURBS Book</i>, 2nd ed., §1.4 and §4.2).
 *
 * <h2>Derivatives</h2>
 * Exact first derivatives by the quotient rule on the homogeneous ones:
 * {@code S_u = (H_u.xyz − S·H_u.w) / H.w}, and likewise in v. With every weight 1 the homogeneous
 * coordinate is exactly 1 at every de Casteljau step ({@code (1−t)·1 + t·1} rounds to 1) and its
 * derivatives exactly 0, so every result is bit-identical to the polynomial kernel's; the
 * division by a zero derivative of the weight is skipped to keep signed zeros too.
 *
 * <h2>Bounds</h2>
 * With positive weights, {@code S} is a convex combination of the Euclidean points
 * {@code P_ij} (coefficients {@code w_ij B_i B_j / Σ w B B}), so their box bounds the patch.
 */
public final class RationalDeCasteljau {

    /** Where {@link #evaluateWithDerivatives} keeps the 12 homogeneous values past its working memory. */
    private static final int HOMOGENEOUS = 3 * DeCasteljau.MAX_ORDER * 4;

    private RationalDeCasteljau() {}

    /**
     * Writes the homogeneous net of {@code count} Euclidean points {@code xyz[xyzOff..]} (3
     * doubles each) and their weights {@code w[wOff..]} into {@code dest[destOff..]} (4 doubles
     * each).
     */
    public static void toHomogeneous(double[] xyz, int xyzOff, double[] w, int wOff, int count,
                                     double[] dest, int destOff) {
        for (int k = 0; k < count; k++) {
            double wk = w[wOff + k];
            int s = xyzOff + 3 * k, d = destOff + 4 * k;
            dest[d] = wk * xyz[s];
            dest[d + 1] = wk * xyz[s + 1];
            dest[d + 2] = wk * xyz[s + 2];
            dest[d + 3] = wk;
        }
    }

    /**
     * Writes the Euclidean points ({@code xyz[xyzOff..]}) and weights ({@code w[wOff..]}) of
     * {@code count} homogeneous points {@code h[hOff..]}.
     */
    public static void toEuclidean(double[] h, int hOff, int count, double[] xyz, int xyzOff, double[] w, int wOff) {
        for (int k = 0; k < count; k++) {
            int s = hOff + 4 * k, d = xyzOff + 3 * k;
            double wk = h[s + 3];
            xyz[d] = h[s] / wk;
            xyz[d + 1] = h[s + 1] / wk;
            xyz[d + 2] = h[s + 2] / wk;
            w[wOff + k] = wk;
        }
    }

    /**
     * {@code S(u,v)} of the homogeneous net into {@code out[outOff..+3)}. Uses
     * {@code 2·MAX_ORDER·4 + 4} doubles of {@code scratch}.
     */
    public static void evaluate(double[] hnet, int off, int n, int m, double u, double v,
                                double[] out, int outOff, double[] scratch) {
        int h = 2 * DeCasteljau.MAX_ORDER * 4;
        DeCasteljau.evaluate(hnet, off, n, m, 4, u, v, scratch, h, scratch);
        double w = scratch[h + 3];
        out[outOff] = scratch[h] / w;
        out[outOff + 1] = scratch[h + 1] / w;
        out[outOff + 2] = scratch[h + 2] / w;
    }

    /**
     * {@code S}, {@code ∂S/∂u}, {@code ∂S/∂v} of the homogeneous net at {@code (u,v)} into
     * {@code out[outOff .. outOff+9)} (the layout of
     * {@link DeCasteljau#evaluateWithDerivatives(double[], int, int, int, double, double, double[], double[])}).
     * Degrees must be ≥ 1. Uses {@code scratchOff + 3·MAX_ORDER·4 + 12} doubles of {@code scratch}.
     */
    public static void evaluateWithDerivatives(double[] hnet, int off, int n, int m, double u, double v,
                                               double[] out, int outOff, double[] scratch, int scratchOff) {
        int h = scratchOff + HOMOGENEOUS;
        if (n == 3 && m == 3) {
            DeCasteljau3.bicubic4WithDerivatives(hnet, off, u, v, scratch, h); // the hot case, on locals
        } else {
            DeCasteljau.evaluateWithDerivatives(hnet, off, n, m, 4, u, v, scratch, h, scratch, scratchOff);
        }
        double w = scratch[h + 3], wu = scratch[h + 7], wv = scratch[h + 11];
        for (int c = 0; c < 3; c++) {
            double s = scratch[h + c] / w;
            out[outOff + c] = s;
            out[outOff + 3 + c] = wu == 0 ? scratch[h + 4 + c] / w : (scratch[h + 4 + c] - s * wu) / w;
            out[outOff + 6 + c] = wv == 0 ? scratch[h + 8 + c] / w : (scratch[h + 8 + c] - s * wv) / w;
        }
    }

    /**
     * {@code S}, {@code ∂S/∂u}, {@code ∂S/∂v} into {@code out[0..9)} of a polynomial net
     * ({@code dim = 3}, exactly {@link DeCasteljau#evaluateWithDerivatives(double[], int, int, int,
     * double, double, double[], double[])}) or a homogeneous rational one ({@code dim = 4}): the
     * one call for code that holds both kinds (the whole patches of a scene).
     */
    public static void pointAndDerivatives(double[] net, int off, int n, int m, int dim, double u, double v,
                                           double[] out, double[] scratch) {
        if (dim == 4) {
            evaluateWithDerivatives(net, off, n, m, u, v, out, 0, scratch, 0);
        } else {
            DeCasteljau.evaluateWithDerivatives(net, off, n, m, u, v, out, scratch);
        }
    }
}
