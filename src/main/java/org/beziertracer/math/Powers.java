package org.beziertracer.math;

/**
 * Whole powers by repeated squaring, for the exponents a material's Phong lobe mostly has.
 */
public final class Powers {
    private Powers() {}

    /** Largest exponent {@link #pow} takes by squaring (ten squarings at most). */
    static final int MAX_SQUARED = 1024;

    /**
     * {@code xᵉ}: for a whole {@code e} in {@code 0..}{@value #MAX_SQUARED} by binary exponentiation
     * (D. E. Knuth, <i>The Art of Computer Programming</i>, vol. 2, 3rd ed., 1997, §4.6.3, the
     * right-to-left binary method), else {@link Math#pow}. That is at most {@code 2·⌊log₂ e⌋}
     * rounded multiplications; a rounding made while squaring is raised with the square to the power
     * still to come, so the relative error of a normal result is below about {@code e·2⁻⁵³}
     * ({@code 4.5·10⁻¹⁵} for the exponent 40, far below what an 8-bit pixel shows), where
     * {@code Math.pow} is within one ulp. For the exponent 40 it is six multiplications where
     * {@code Math.pow} (a logarithm and an exponential) costs several times more.
     * Results in the subnormal range carry fewer digits.
     */
    public static double pow(double x, double e) {
        int k = (int) e;
        if (k != e || k < 0 || k > MAX_SQUARED) {
            return Math.pow(x, e);
        }
        double result = 1, square = x;
        while (true) {
            if ((k & 1) != 0) {
                result *= square;
            }
            k >>>= 1;
            if (k == 0) {
                return result;
            }
            square *= square;
        }
    }
}
