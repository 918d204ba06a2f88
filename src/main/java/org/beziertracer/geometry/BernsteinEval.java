package org.beziertracer.geometry;

/**
 * Evaluation of a 3-D tensor-product Bézier patch with its first derivatives in
 * {@code O(n·m)} operations, for any degree: the Bernstein bases are computed once per direction
 * ({@code O(n + m)}), then one pass over the control net sums
 * <pre>
 *   r_j = Σ_i B_i^n(u) P_ij,   d_j = Σ_i B_i^{n−1}(u) (P_{i+1,j} − P_ij),
 *   S = Σ_j B_j^m(v) r_j,   S_u = n Σ_j B_j^m(v) d_j,   S_v = m Σ_j B_j^{m−1}(v) (r_{j+1} − r_j)
 * </pre>
 * (the derivatives in hodograph form) — nine flops per control point, where the tensor-product
 * de Casteljau algorithm ({@link DeCasteljau#evaluateWithDerivatives}) needs {@code O(n²·m)}.
 *
 * <p>The basis of degree {@code n − 1} is {@code C(n−1,i) tⁱ (1−t)^{n−1−i}} (powers by repeated
 * multiplication, binomials exact in double up to degree 15), the degree-{@code n} basis follows
 * from {@code B_i^n = (1−t) B_i^{n−1} + t B_{i−1}^{n−1}} (G. Farin, <i>Curves and Surfaces for
 * CAGD</i>, 5th ed., 2002, the chapters on the Bernstein form and on derivatives of tensor-product
 * patches). Every basis value is a product of non-negative factors, so the sums are as well
 * conditioned as de Casteljau's convex combinations (the error is a few ulps of the net's size
 * times the degree; tested against de Casteljau for degrees 1..15). As in de Casteljau, a
 * derivative is built from differences of control points, so where an edge collapses to a point
 * the derivative along it is exactly zero (which {@link PatchNormals} relies on to detect the
 * degenerate normal), and at {@code t = 0} or {@code 1} the basis is exactly a unit vector.
 *
 * <p>Allocation-free; thread-safe with one scratch array per thread.
 */
public final class BernsteinEval {
    private BernsteinEval() {}

    private static final int ORDER = DeCasteljau.MAX_ORDER;

    /** Scratch doubles {@link #evaluateWithDerivatives} uses from its scratch offset. */
    public static final int SCRATCH = 4 * ORDER;

    /** {@code C(k, i)} at {@code k * ORDER + i}, exact. */
    private static final double[] BINOMIAL = new double[ORDER * ORDER];

    static {
        for (int k = 0; k < ORDER; k++) {
            BINOMIAL[k * ORDER] = 1;
            for (int i = 1; i <= k; i++) {
                BINOMIAL[k * ORDER + i] = BINOMIAL[(k - 1) * ORDER + i - 1] + (i < k ? BINOMIAL[(k - 1) * ORDER + i] : 0);
            }
        }
    }

    /**
     * Writes {@code S(u,v)}, {@code ∂S/∂u}, {@code ∂S/∂v} of the degree {@code n}×{@code m} 3-D net at
     * {@code net[off..]} (layout of {@link DeCasteljau}) to {@code out[outOff .. outOff+9)}, the
     * layout of {@link DeCasteljau#evaluateWithDerivatives}. Degrees 1..15; uses {@link #SCRATCH}
     * doubles of {@code scratch} from {@code scratchOff}.
     */
    public static void evaluateWithDerivatives(double[] net, int off, int n, int m, double u, double v,
                                               double[] out, int outOff, double[] scratch, int scratchOff) {
        int bu = scratchOff, lu = bu + ORDER, bv = lu + ORDER, lv = bv + ORDER;
        basis(n, u, scratch, bu, lu);
        basis(m, v, scratch, bv, lv);
        double sx = 0, sy = 0, sz = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        double qx = 0, qy = 0, qz = 0; // r_(j-1)
        for (int j = 0, row = off; j <= m; j++, row += 3 * (n + 1)) {
            // r_j and d_j along the row
            double px = net[row], py = net[row + 1], pz = net[row + 2];
            double w = scratch[bu];
            double rx = w * px, ry = w * py, rz = w * pz, dx = 0, dy = 0, dz = 0;
            for (int i = 1, p = row + 3; i <= n; i++, p += 3) {
                double nx = net[p], ny = net[p + 1], nz = net[p + 2];
                double wi = scratch[bu + i], li = scratch[lu + i - 1];
                rx += wi * nx; ry += wi * ny; rz += wi * nz;
                dx += li * (nx - px); dy += li * (ny - py); dz += li * (nz - pz);
                px = nx; py = ny; pz = nz;
            }
            double wj = scratch[bv + j];
            sx += wj * rx; sy += wj * ry; sz += wj * rz;
            ux += wj * dx; uy += wj * dy; uz += wj * dz;
            if (j > 0) {
                double lj = scratch[lv + j - 1];
                vx += lj * (rx - qx); vy += lj * (ry - qy); vz += lj * (rz - qz);
            }
            qx = rx; qy = ry; qz = rz;
        }
        out[outOff] = sx; out[outOff + 1] = sy; out[outOff + 2] = sz;
        out[outOff + 3] = n * ux; out[outOff + 4] = n * uy; out[outOff + 5] = n * uz;
        out[outOff + 6] = m * vx; out[outOff + 7] = m * vy; out[outOff + 8] = m * vz;
    }

    /**
     * The degree-{@code deg} Bernstein basis at {@code t} into {@code b[bo .. bo+deg]} and the
     * degree-{@code (deg−1)} basis into {@code b[lo .. lo+deg−1]}; {@code deg ≥ 1}.
     */
    static void basis(int deg, double t, double[] b, int bo, int lo) {
        double s = 1 - t;
        int k = deg - 1, binom = k * ORDER;
        // L_i = C(k,i) t^i s^(k-i), i = 0..k: t powers first, then times the s powers
        double tp = 1;
        for (int i = 0; i <= k; i++) {
            b[lo + i] = BINOMIAL[binom + i] * tp;
            tp *= t;
        }
        double sp = 1;
        for (int i = k; i >= 0; i--) {
            b[lo + i] *= sp;
            sp *= s;
        }
        // B_i = s L_i + t L_(i-1)
        b[bo] = s * b[lo];
        for (int i = 1; i < deg; i++) {
            b[bo + i] = s * b[lo + i] + t * b[lo + i - 1];
        }
        b[bo + deg] = t * b[lo + k];
    }
}
