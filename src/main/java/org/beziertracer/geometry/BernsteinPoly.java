package org.beziertracer.geometry;

import java.util.Arrays;

/**
 * A polynomial {@code p(t) = Σ_{k=0..d} c_k B_k^d(t)} on {@code [0,1]} in Bernstein form, with
 * {@code dim} coordinates per coefficient (dim 1: a scalar polynomial; 3: a space curve; 4: a
 * homogeneous curve {@code (w·x, w·y, w·z, w)}). Degrees are not capped (products of border
 * curves reach degree 70 for bicubic patches).
 *
 * <h2>Layout</h2>
 * Coefficient {@code k}, coordinate {@code c} is {@code coeffs[k·dim + c]}.
 *
 * <h2>What it offers, and its sources</h2>
 * <ul>
 *   <li>Sums and differences after degree elevation, derivatives (hodographs) and de Casteljau
 *       subdivision: G. Farin, <i>Curves and Surfaces for CAGD: A Practical Guide</i>, 5th ed.,
 *       2002, the chapters on the de Casteljau algorithm, derivatives and degree elevation.</li>
 *   <li>Products of two polynomials in Bernstein form without leaving the basis,
 *       {@code (ab)_k = Σ_{i+j=k} C(m,i) C(n,j) / C(m+n,k) · a_i b_j} (convex weights): R. T.
 *       Farouki and V. T. Rajan, "Algorithms for polynomials in Bernstein form", CAGD 5 (1988)
 *       1–26. Dot and cross products of vector polynomials are sums of such products.</li>
 *   <li>Bounds from the coefficients: the values lie in their convex hull, so
 *       {@code |p(t)| ≤ max_k |c_k|} and {@code min_k c_k ≤ p(t) ≤ max_k c_k}, and the bounds
 *       converge to the true range, quadratically in the interval's length, under subdivision
 *       (J. M. Lane and R. F. Riesenfeld, "Bounds on a polynomial", BIT 21 (1981) 112–117).</li>
 * </ul>
 *
 * <p>Immutable (the array is never handed out) and thread-safe. For analysis code, not the ray
 * hot path: every operation allocates its result.
 */
public final class BernsteinPoly {

    private final int degree;
    private final int dim;
    private final double[] coeffs;

    private BernsteinPoly(int degree, int dim, double[] coeffs) {
        this.degree = degree;
        this.dim = dim;
        this.coeffs = coeffs;
    }

    /** The polynomial of degree {@code degree} with {@code (degree+1)·dim} coefficients (copied). */
    public static BernsteinPoly of(int degree, int dim, double... coeffs) {
        if (degree < 0 || dim < 1 || coeffs.length != (degree + 1) * dim) {
            throw new IllegalArgumentException("degree " + degree + ", dim " + dim + " needs "
                    + (degree + 1) * dim + " coefficients, got " + coeffs.length);
        }
        return new BernsteinPoly(degree, dim, coeffs.clone());
    }

    /** The constant {@code value} (degree 0, one coordinate a value). */
    public static BernsteinPoly constant(double... value) {
        return new BernsteinPoly(0, value.length, value.clone());
    }

    /** Degree. */
    public int degree() { return degree; }

    /** Coordinates per coefficient. */
    public int dim() { return dim; }

    /** Coordinate {@code c} of coefficient {@code k}. */
    public double coefficient(int k, int c) { return coeffs[k * dim + c]; }

    /** Coordinates {@code from..from+count-1} of every coefficient (e.g. the xyz of a homogeneous curve). */
    public BernsteinPoly coordinates(int from, int count) {
        double[] out = new double[(degree + 1) * count];
        for (int k = 0; k <= degree; k++) {
            System.arraycopy(coeffs, k * dim + from, out, k * count, count);
        }
        return new BernsteinPoly(degree, count, out);
    }

    /** The same polynomial of degree {@code target ≥ degree}, by repeated degree elevation. */
    public BernsteinPoly elevateTo(int target) {
        if (target < degree) {
            throw new IllegalArgumentException("cannot elevate degree " + degree + " to " + target);
        }
        double[] c = coeffs;
        for (int d = degree; d < target; d++) {
            double[] e = new double[(d + 2) * dim];
            for (int i = 0; i <= d + 1; i++) {
                double a = (double) i / (d + 1);
                for (int q = 0; q < dim; q++) {
                    double left = i > 0 ? c[(i - 1) * dim + q] : 0, here = i <= d ? c[i * dim + q] : 0;
                    e[i * dim + q] = a * left + (1 - a) * here;
                }
            }
            c = e;
        }
        return c == coeffs ? this : new BernsteinPoly(target, dim, c);
    }

    /** {@code this + other} (same dim; the lower degree elevated). */
    public BernsteinPoly plus(BernsteinPoly other) { return combine(other, 1); }

    /** {@code this − other} (same dim; the lower degree elevated). */
    public BernsteinPoly minus(BernsteinPoly other) { return combine(other, -1); }

    private BernsteinPoly combine(BernsteinPoly other, double sign) {
        if (other.dim != dim) {
            throw new IllegalArgumentException("dims differ: " + dim + " and " + other.dim);
        }
        int d = Math.max(degree, other.degree);
        double[] a = elevateTo(d).coeffs, b = other.elevateTo(d).coeffs, out = new double[a.length];
        for (int k = 0; k < out.length; k++) {
            out[k] = a[k] + sign * b[k];
        }
        return new BernsteinPoly(d, dim, out);
    }

    /** {@code s · this}. */
    public BernsteinPoly times(double s) {
        double[] out = coeffs.clone();
        for (int k = 0; k < out.length; k++) {
            out[k] *= s;
        }
        return new BernsteinPoly(degree, dim, out);
    }

    /** The derivative {@code d Σ (c_{k+1} − c_k) B_k^{d−1}}; the zero constant for degree 0. */
    public BernsteinPoly derivative() {
        if (degree == 0) {
            return new BernsteinPoly(0, dim, new double[dim]);
        }
        double[] out = new double[degree * dim];
        for (int k = 0; k < degree; k++) {
            for (int q = 0; q < dim; q++) {
                out[k * dim + q] = degree * (coeffs[(k + 1) * dim + q] - coeffs[k * dim + q]);
            }
        }
        return new BernsteinPoly(degree - 1, dim, out);
    }

    /** {@code s(t) · this(t)} for a scalar polynomial {@code s}. */
    public BernsteinPoly scaledBy(BernsteinPoly s) {
        requireDim(s, 1);
        int d = degree + s.degree;
        double[] out = new double[(d + 1) * dim];
        for (int i = 0; i <= degree; i++) {
            for (int j = 0; j <= s.degree; j++) {
                double w = weight(degree, i, s.degree, j) * s.coeffs[j];
                for (int q = 0; q < dim; q++) {
                    out[(i + j) * dim + q] += w * coeffs[i * dim + q];
                }
            }
        }
        return new BernsteinPoly(d, dim, out);
    }

    /** The scalar polynomial {@code this(t) · other(t)} (same dim). */
    public BernsteinPoly dot(BernsteinPoly other) {
        requireDim(other, dim);
        int d = degree + other.degree;
        double[] out = new double[d + 1];
        for (int i = 0; i <= degree; i++) {
            for (int j = 0; j <= other.degree; j++) {
                double s = 0;
                for (int q = 0; q < dim; q++) {
                    s += coeffs[i * dim + q] * other.coeffs[j * dim + q];
                }
                out[i + j] += weight(degree, i, other.degree, j) * s;
            }
        }
        return new BernsteinPoly(d, 1, out);
    }

    /** The vector polynomial {@code this(t) × other(t)} (both dim 3). */
    public BernsteinPoly cross(BernsteinPoly other) {
        requireDim(this, 3);
        requireDim(other, 3);
        int d = degree + other.degree;
        double[] out = new double[(d + 1) * 3];
        for (int i = 0; i <= degree; i++) {
            double ax = coeffs[3 * i], ay = coeffs[3 * i + 1], az = coeffs[3 * i + 2];
            for (int j = 0; j <= other.degree; j++) {
                double bx = other.coeffs[3 * j], by = other.coeffs[3 * j + 1], bz = other.coeffs[3 * j + 2];
                double w = weight(degree, i, other.degree, j);
                int k = 3 * (i + j);
                out[k] += w * (ay * bz - az * by);
                out[k + 1] += w * (az * bx - ax * bz);
                out[k + 2] += w * (ax * by - ay * bx);
            }
        }
        return new BernsteinPoly(d, 3, out);
    }

    /** {@code C(m,i) C(n,j) / C(m+n,i+j)}: the weight of {@code a_i b_j} in the product's coefficient {@code i+j}. */
    private static double weight(int m, int i, int n, int j) {
        return Binomials.of(m, i) * Binomials.of(n, j) / Binomials.of(m + n, i + j);
    }

    private static void requireDim(BernsteinPoly p, int dim) {
        if (p.dim != dim) {
            throw new IllegalArgumentException("expected dim " + dim + ", got " + p.dim);
        }
    }

    /**
     * The two halves on {@code [0, ½]} and {@code [½, 1]}, each reparametrised to {@code [0,1]}
     * (de Casteljau at ½: every intermediate point an exact-halving average).
     */
    public BernsteinPoly[] halves() { return splitAt(0.5); }

    /** The pieces on {@code [0, t]} and {@code [t, 1]}, each reparametrised to {@code [0,1]} (de Casteljau at t). */
    public BernsteinPoly[] splitAt(double t) {
        // One triangle in place: after step r, right[k] for k ≤ degree − r holds level r, and
        // right[degree − r] is final (later steps touch lower k only); left[r] is level r at k = 0.
        double[] left = new double[coeffs.length], right = coeffs.clone();
        System.arraycopy(right, 0, left, 0, dim);
        double s = 1 - t;
        for (int r = 1; r <= degree; r++) {
            int end = (degree - r + 1) * dim;
            if (t == 0.5) {
                for (int k = 0; k < end; k++) {
                    right[k] = 0.5 * (right[k] + right[k + dim]);
                }
            } else {
                for (int k = 0; k < end; k++) {
                    right[k] = s * right[k] + t * right[k + dim];
                }
            }
            System.arraycopy(right, 0, left, r * dim, dim);
        }
        return new BernsteinPoly[] {new BernsteinPoly(degree, dim, left), new BernsteinPoly(degree, dim, right)};
    }

    /** The piece on {@code [a, b]} ({@code 0 ≤ a < b ≤ 1}) reparametrised to {@code [0,1]}. */
    public BernsteinPoly restricted(double a, double b) {
        BernsteinPoly p = b < 1 ? splitAt(b)[0] : this;
        return a > 0 ? p.splitAt(a / b)[1] : p;
    }

    /** A copy of the coefficients, {@code dim} doubles each (for tests). */
    double[] coefficients() { return coeffs.clone(); }

    /** The value at {@code t} (de Casteljau), {@code dim} doubles. */
    public double[] value(double t) {
        double[] work = coeffs.clone();
        for (int r = degree; r > 0; r--) {
            for (int k = 0; k < r * dim; k++) {
                work[k] = (1 - t) * work[k] + t * work[k + dim];
            }
        }
        return Arrays.copyOf(work, dim);
    }

    /** The value at an end: {@code t = 0} (the first coefficient) or {@code t = 1} (the last); exact. */
    public double[] end(boolean atOne) {
        int k = atOne ? degree : 0;
        return Arrays.copyOfRange(coeffs, k * dim, k * dim + dim);
    }

    /** Coordinate 0 at an end (for scalar polynomials). */
    public double endValue(boolean atOne) { return coeffs[(atOne ? degree : 0) * dim]; }

    /** {@code max_k |c_k|}: an upper bound of {@code |p(t)|} on {@code [0,1]} (convex hull). */
    public double maxNorm() {
        double m = 0;
        for (int k = 0; k <= degree; k++) {
            m = Math.max(m, norm(k));
        }
        return m;
    }

    /** Euclidean norm of coefficient {@code k}. */
    public double norm(int k) {
        double s = 0;
        for (int q = 0; q < dim; q++) {
            double c = coeffs[k * dim + q];
            s += c * c;
        }
        return Math.sqrt(s);
    }

    /** {@code min_k c_k} of a scalar polynomial: a lower bound of {@code p(t)} on {@code [0,1]}. */
    public double min() {
        requireDim(this, 1);
        double m = Double.POSITIVE_INFINITY;
        for (double c : coeffs) {
            m = Math.min(m, c);
        }
        return m;
    }

    /** {@code max_k c_k} of a scalar polynomial: an upper bound of {@code p(t)} on {@code [0,1]}. */
    public double max() {
        requireDim(this, 1);
        double m = Double.NEGATIVE_INFINITY;
        for (double c : coeffs) {
            m = Math.max(m, c);
        }
        return m;
    }

    /**
     * {@code p(t) / t}, when {@code p(0) = 0}: since {@code B_k^d(t) = (d/k) t B_{k−1}^{d−1}(t)},
     * the quotient has coefficients {@code c_k · d / k}, {@code k = 1..d}. The first coefficient
     * is dropped whatever its value (the caller decides it is zero).
     */
    public BernsteinPoly dividedByT() {
        if (degree == 0) {
            throw new IllegalStateException("a constant has no factor t");
        }
        double[] out = new double[degree * dim];
        for (int k = 1; k <= degree; k++) {
            for (int q = 0; q < dim; q++) {
                out[(k - 1) * dim + q] = coeffs[k * dim + q] * degree / k;
            }
        }
        return new BernsteinPoly(degree - 1, dim, out);
    }

    /** {@code p(t) / (1 − t)}, when {@code p(1) = 0}: coefficients {@code c_k · d / (d − k)}, {@code k = 0..d−1}. */
    public BernsteinPoly dividedByOneMinusT() {
        if (degree == 0) {
            throw new IllegalStateException("a constant has no factor 1 - t");
        }
        double[] out = new double[degree * dim];
        for (int k = 0; k < degree; k++) {
            for (int q = 0; q < dim; q++) {
                out[k * dim + q] = coeffs[k * dim + q] * degree / (degree - k);
            }
        }
        return new BernsteinPoly(degree - 1, dim, out);
    }

    /** The same polynomial with its coefficients in reverse order: {@code p(1 − t)}. */
    public BernsteinPoly reversed() {
        double[] out = new double[coeffs.length];
        for (int k = 0; k <= degree; k++) {
            System.arraycopy(coeffs, k * dim, out, (degree - k) * dim, dim);
        }
        return new BernsteinPoly(degree, dim, out);
    }

    @Override
    public String toString() {
        return "BernsteinPoly[degree " + degree + ", dim " + dim + "]";
    }

    /** Binomial coefficients as doubles, Pascal's triangle grown on demand (exact to 2^53, then to rounding). */
    private static final class Binomials {
        private static volatile double[][] rows = build(64);

        static double of(int n, int k) {
            double[][] r = rows;
            if (n >= r.length) {
                synchronized (Binomials.class) {
                    if (n >= rows.length) {
                        rows = build(Math.max(n + 1, 2 * rows.length));
                    }
                    r = rows;
                }
            }
            return r[n][k];
        }

        private static double[][] build(int count) {
            double[][] r = new double[count][];
            for (int n = 0; n < count; n++) {
                r[n] = new double[n + 1];
                r[n][0] = r[n][n] = 1;
                for (int k = 1; k < n; k++) {
                    r[n][k] = r[n - 1][k - 1] + r[n - 1][k];
                }
            }
            return r;
        }
    }
}
