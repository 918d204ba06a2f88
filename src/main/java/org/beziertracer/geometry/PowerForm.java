package org.beziertracer.geometry;

import org.beziertracer.math.ScalarKernel;

/**
 * A polynomial patch in the power basis about its parameter square's centre,
 * {@code S(u,v) = Σ a_ij xⁱ yʲ} with {@code x = u − ½}, {@code y = v − ½}, evaluated with its first
 * derivatives by Horner's rule: per row {@code j} the value {@code r_j(x)} and its derivative
 * together (two multiply-adds a coefficient and coordinate), then the rows' sums in {@code y} the
 * same way. Six multiply-adds per control point and no basis to compute, where the bicubic
 * de Casteljau scheme ({@link DeCasteljau3}) takes 32 convex combinations a coordinate and the
 * Bernstein sums ({@link BernsteinEval}) six multiply-adds, three differences and two bases: about
 * twice as fast as either for bicubic and biquintic patches, 10–20 % at degree 9 (issue 9's
 * "per-leaf power / Horner form", measured in the notes).
 *
 * <p>The conversion is the Bernstein-to-power change of basis (G. Farin, <i>Curves and Surfaces
 * for CAGD</i>, 5th ed., 2002, the chapter on the Bernstein form; R. T. Farouki and V. T. Rajan,
 * "On the numerical condition of polynomials in Bernstein form", CAGD 4, 1987: the power basis is
 * the worse conditioned, and its condition grows with the degree): centring the basis keeps
 * {@code |x|, |y| ≤ ½}, so a high term's rounding is scaled down by {@code 2^-(i+j)}. Measured on
 * random nets of size 5, the value differs from de Casteljau's by at most about {@code 2·10⁻¹⁴} at
 * degree 3, {@code 10⁻¹³} at degree 9 and {@code 6·10⁻¹²} at degree 15, the derivatives by ten
 * times that; the patch's exact corners and collapsed edges are kept only to that rounding (a
 * derivative along a collapsed edge is rounding-small rather than zero, which
 * {@link PatchNormals}' relative threshold still counts as degenerate). Past degree 9 the form
 * gains little time and loses accuracy, hence {@link #MAX_DEGREE}.
 *
 * <p>Layout: as the Bézier net, coefficient {@code a_ij} of {@code xⁱyʲ} at
 * {@code 3·(j·(n+1) + i)}. Stateless; the evaluation allocates nothing.
 */
public final class PowerForm {
    private PowerForm() {}

    /** Highest degree (in either direction) converted: past it the Horner form gains little and loses accuracy. */
    public static final int MAX_DEGREE = 9;

    /** {@code T[n][k·(n+1) + i]}: the coefficient of {@code xⁱ} in {@code B_k^n(x + ½)}, degrees 0..MAX_DEGREE. */
    private static final double[][] TO_POWER = new double[MAX_DEGREE + 1][];

    static {
        for (int n = 0; n <= MAX_DEGREE; n++) {
            double[] t = new double[(n + 1) * (n + 1)];
            for (int k = 0; k <= n; k++) {
                // C(n,k) (½ + x)^k (½ − x)^(n−k), expanded by repeated multiplication (exact in double:
                // binary fractions with few bits for these degrees)
                double[] poly = new double[n + 1];
                poly[0] = binomial(n, k);
                int len = 1;
                for (int f = 0; f < n; f++, len++) {
                    double sign = f < k ? 1 : -1;
                    for (int i = len; i > 0; i--) {
                        poly[i] = 0.5 * poly[i] + sign * poly[i - 1];
                    }
                    poly[0] = 0.5 * poly[0];
                }
                System.arraycopy(poly, 0, t, k * (n + 1), n + 1);
            }
            TO_POWER[n] = t;
        }
    }

    private static double binomial(int n, int k) {
        double c = 1;
        for (int i = 1; i <= k; i++) {
            c = c * (n - k + i) / i;
        }
        return c;
    }

    /** True when a polynomial patch of degrees {@code n}×{@code m} has a power form ({@link #MAX_DEGREE}). */
    public static boolean has(int n, int m) {
        return n >= 1 && m >= 1 && Math.max(n, m) <= MAX_DEGREE;
    }

    /**
     * Writes the power form of the 3-D Bézier net at {@code net[off..]} (degrees {@code n}×{@code m},
     * {@link #has}) to {@code out[outOff .. outOff + 3(n+1)(m+1))}; false when a coefficient is not
     * finite (a net near the largest doubles: its sums overflow where de Casteljau's convex
     * combinations do not), and the form must not be used.
     */
    public static boolean fromBezier(double[] net, int off, int n, int m, double[] out, int outOff) {
        double[] tu = TO_POWER[n], tv = TO_POWER[m];
        int rowLen = 3 * (n + 1);
        double[] rows = new double[rowLen * (m + 1)]; // each row in the power basis in x
        boolean finite = true;
        for (int l = 0; l <= m; l++) {
            for (int i = 0; i <= n; i++) {
                for (int c = 0; c < 3; c++) {
                    double s = 0;
                    for (int k = 0; k <= n; k++) {
                        s += tu[k * (n + 1) + i] * net[off + l * rowLen + 3 * k + c];
                    }
                    rows[l * rowLen + 3 * i + c] = s;
                }
            }
        }
        for (int j = 0; j <= m; j++) {
            for (int q = 0; q < rowLen; q++) {
                double s = 0;
                for (int l = 0; l <= m; l++) {
                    s += tv[l * (m + 1) + j] * rows[l * rowLen + q];
                }
                out[outOff + j * rowLen + q] = s;
                finite &= Double.isFinite(s);
            }
        }
        return finite;
    }

    /**
     * {@code S(u,v)}, {@code ∂S/∂u}, {@code ∂S/∂v} of the power form at {@code a[off..]} into
     * {@code out[outOff .. outOff+9)}, the layout of {@link DeCasteljau#evaluateWithDerivatives}.
     */
    public static void evaluateWithDerivatives(double[] a, int off, int n, int m, double u, double v, double[] out,
                                               int outOff) {
        // the same operations as every lane of a batch's SIMD evaluation (LaneKernel), so one ray
        // alone and one ray of a batch get the same bits
        ScalarKernel.powerFormAt(a, off, n, m, u, v, out, outOff, 1);
    }
}
