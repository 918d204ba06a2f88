package org.beziertracer.geometry;

import static org.beziertracer.math.Processor.mad;

import org.beziertracer.math.Processor;

/**
 * Evaluation of a 3-D tensor-product Bézier patch with its first derivatives in
 * {@code O(n·m)} operations, for any degree: the Bernstein bases are computed once per direction
 * ({@code O(n + m)}), then one pass over the control net sums
 * <pre>
 *   r_j = Σ_i B_i^n(u) P_ij,   d_j = Σ_i B_i^{n−1}(u) (P_{i+1,j} − P_ij),
 *   S = Σ_j B_j^m(v) r_j,   S_u = n Σ_j B_j^m(v) d_j,   S_v = m Σ_j B_j^{m−1}(v) (r_{j+1} − r_j)
 * </pre>
 * (the derivatives in hodograph form) — six multiply-adds and three differences per control
 * point, where the tensor-product de Casteljau algorithm ({@link DeCasteljau#evaluateWithDerivatives})
 * needs {@code O(n²·m)}. The sums use {@link Processor#mad} (never fused: the same bits on every
 * processor), and where it has 32 floating-point registers ({@link Processor#WIDE_REGISTER_FILE})
 * rows are summed two at a time, so that two rows' chains of dependent additions overlap: at degree 9
 * about 10 % less time than one row at a time with separate multiplies and adds on 16 registers
 * (AVX2), about 30 % less on 32 (AVX-512); two rows at a time would spill on 16.
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
    public static final int SCRATCH = 6 * ORDER;

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
        evaluateWithDerivatives(net, off, n, m, u, v, out, outOff, scratch, scratchOff, Processor.WIDE_REGISTER_FILE);
    }

    /**
     * {@link #evaluateWithDerivatives}, its rows summed two at a time ({@code inPairs}, an odd last
     * row alone) or one at a time.
     */
    static void evaluateWithDerivatives(double[] net, int off, int n, int m, double u, double v, double[] out,
                                        int outOff, double[] scratch, int scratchOff, boolean inPairs) {
        bases(n, u, m, v, scratch, scratchOff, scratchOff + ORDER, scratchOff + 2 * ORDER, scratchOff + 3 * ORDER);
        if (inPairs) {
            sumRowsInPairs(net, off, n, m, out, outOff, scratch, scratchOff);
        } else {
            sumRows(net, off, n, m, out, outOff, scratch, scratchOff);
        }
    }

    /** The sums of {@link #evaluateWithDerivatives} a row at a time, the bases in {@code scratch}. */
    private static void sumRows(double[] net, int off, int n, int m, double[] out, int outOff, double[] scratch,
                                int scratchOff) {
        int bu = scratchOff, lu = bu + ORDER, bv = lu + ORDER, lv = bv + ORDER;
        double sx = 0, sy = 0, sz = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        double qx = 0, qy = 0, qz = 0; // r_(j-1)
        double w0 = scratch[bu];
        for (int j = 0, row = off; j <= m; j++, row += 3 * (n + 1)) {
            // r_j and d_j along the row
            double px = net[row], py = net[row + 1], pz = net[row + 2];
            double rx = w0 * px, ry = w0 * py, rz = w0 * pz, dx = 0, dy = 0, dz = 0;
            for (int i = 1, p = row + 3; i <= n; i++, p += 3) {
                double nx = net[p], ny = net[p + 1], nz = net[p + 2];
                double wi = scratch[bu + i], li = scratch[lu + i - 1];
                rx = mad(wi, nx, rx); ry = mad(wi, ny, ry); rz = mad(wi, nz, rz);
                dx = mad(li, nx - px, dx); dy = mad(li, ny - py, dy); dz = mad(li, nz - pz, dz);
                px = nx; py = ny; pz = nz;
            }
            double wj = scratch[bv + j];
            sx = mad(wj, rx, sx); sy = mad(wj, ry, sy); sz = mad(wj, rz, sz);
            ux = mad(wj, dx, ux); uy = mad(wj, dy, uy); uz = mad(wj, dz, uz);
            if (j > 0) {
                double lj = scratch[lv + j - 1];
                vx = mad(lj, rx - qx, vx); vy = mad(lj, ry - qy, vy); vz = mad(lj, rz - qz, vz);
            }
            qx = rx; qy = ry; qz = rz;
        }
        store(out, outOff, n, m, sx, sy, sz, ux, uy, uz, vx, vy, vz);
    }

    /**
     * The sums of {@link #evaluateWithDerivatives} two rows at a time (j and k = j+1), an odd last
     * row alone: two independent sets of sums per pass keep the multiply-add units busy where one
     * row's sums would wait on each other, but they need 26 registers
     * ({@link Processor#WIDE_REGISTER_FILE}). (The last row alone, not paired with itself and
     * dropped, nor folded into one loop with {@link #sumRows}: both compiled to code slower than a
     * row at a time, KernelBench degree 8.)
     */
    private static void sumRowsInPairs(double[] net, int off, int n, int m, double[] out, int outOff,
                                       double[] scratch, int scratchOff) {
        int bu = scratchOff, lu = bu + ORDER, bv = lu + ORDER, lv = bv + ORDER;
        double sx = 0, sy = 0, sz = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        double qx = 0, qy = 0, qz = 0; // r_(j-1)
        double w0 = scratch[bu];
        int rowStride = 3 * (n + 1), j = 0, row = off;
        for (; j < m; j += 2, row += 2 * rowStride) {
            int rowK = row + rowStride;
            double px = net[row], py = net[row + 1], pz = net[row + 2];
            double ax = net[rowK], ay = net[rowK + 1], az = net[rowK + 2];
            double rx = w0 * px, ry = w0 * py, rz = w0 * pz, dx = 0, dy = 0, dz = 0;
            double gx = w0 * ax, gy = w0 * ay, gz = w0 * az, ex = 0, ey = 0, ez = 0;
            for (int i = 1, p = row + 3, q = rowK + 3; i <= n; i++, p += 3, q += 3) {
                double nx = net[p], ny = net[p + 1], nz = net[p + 2];
                double mx = net[q], my = net[q + 1], mz = net[q + 2];
                double wi = scratch[bu + i], li = scratch[lu + i - 1];
                rx = mad(wi, nx, rx); ry = mad(wi, ny, ry); rz = mad(wi, nz, rz);
                dx = mad(li, nx - px, dx); dy = mad(li, ny - py, dy); dz = mad(li, nz - pz, dz);
                gx = mad(wi, mx, gx); gy = mad(wi, my, gy); gz = mad(wi, mz, gz);
                ex = mad(li, mx - ax, ex); ey = mad(li, my - ay, ey); ez = mad(li, mz - az, ez);
                px = nx; py = ny; pz = nz;
                ax = mx; ay = my; az = mz;
            }
            double wj = scratch[bv + j], wk = scratch[bv + j + 1], lk = scratch[lv + j];
            sx = mad(wj, rx, sx); sy = mad(wj, ry, sy); sz = mad(wj, rz, sz);
            ux = mad(wj, dx, ux); uy = mad(wj, dy, uy); uz = mad(wj, dz, uz);
            if (j > 0) {
                double lj = scratch[lv + j - 1];
                vx = mad(lj, rx - qx, vx); vy = mad(lj, ry - qy, vy); vz = mad(lj, rz - qz, vz);
            }
            sx = mad(wk, gx, sx); sy = mad(wk, gy, sy); sz = mad(wk, gz, sz);
            ux = mad(wk, ex, ux); uy = mad(wk, ey, uy); uz = mad(wk, ez, uz);
            vx = mad(lk, gx - rx, vx); vy = mad(lk, gy - ry, vy); vz = mad(lk, gz - rz, vz);
            qx = gx; qy = gy; qz = gz;
        }
        if (j == m) {
            // The odd last row: sumRows's loop body, written out again on purpose. Handing the sums
            // to sumRows through the scratch array read 5-8 % slower at degrees 8-10 (alternating
            // in one JVM), and one method with both loops slower still.
            // r_j and d_j along the row
            double px = net[row], py = net[row + 1], pz = net[row + 2];
            double rx = w0 * px, ry = w0 * py, rz = w0 * pz, dx = 0, dy = 0, dz = 0;
            for (int i = 1, p = row + 3; i <= n; i++, p += 3) {
                double nx = net[p], ny = net[p + 1], nz = net[p + 2];
                double wi = scratch[bu + i], li = scratch[lu + i - 1];
                rx = mad(wi, nx, rx); ry = mad(wi, ny, ry); rz = mad(wi, nz, rz);
                dx = mad(li, nx - px, dx); dy = mad(li, ny - py, dy); dz = mad(li, nz - pz, dz);
                px = nx; py = ny; pz = nz;
            }
            double wj = scratch[bv + j];
            sx = mad(wj, rx, sx); sy = mad(wj, ry, sy); sz = mad(wj, rz, sz);
            ux = mad(wj, dx, ux); uy = mad(wj, dy, uy); uz = mad(wj, dz, uz);
            if (j > 0) {
                double lj = scratch[lv + j - 1];
                vx = mad(lj, rx - qx, vx); vy = mad(lj, ry - qy, vy); vz = mad(lj, rz - qz, vz);
            }
        }
        store(out, outOff, n, m, sx, sy, sz, ux, uy, uz, vx, vy, vz);
    }

    /** S, S_u and S_v from the sums (the derivatives times their degrees) into {@code out[outOff..]}. */
    private static void store(double[] out, int outOff, int n, int m, double sx, double sy, double sz, double ux,
                              double uy, double uz, double vx, double vy, double vz) {
        out[outOff] = sx; out[outOff + 1] = sy; out[outOff + 2] = sz;
        out[outOff + 3] = n * ux; out[outOff + 4] = n * uy; out[outOff + 5] = n * uz;
        out[outOff + 6] = m * vx; out[outOff + 7] = m * vy; out[outOff + 8] = m * vz;
    }

    /**
     * {@link #basis} in u (degree {@code n}, into {@code bu}, {@code lu}) and in v (degree
     * {@code m}, into {@code bv}, {@code lv}) at once, value for value the same: the four chains of
     * powers run side by side (the powers of {@code 1 − t} at {@code lv + ORDER} and
     * {@code lv + 2·ORDER}).
     */
    static void bases(int n, double u, int m, double v, double[] b, int bu, int lu, int bv, int lv) {
        double su = 1 - u, sv = 1 - v;
        int kn = n - 1, km = m - 1, pu = lv + ORDER, pv = pu + ORDER;
        // t^i into the lower bases' slots, (1-t)^i past them
        double tu = 1, tv = 1, ru = 1, rv = 1;
        for (int i = 0, k = Math.max(kn, km); i <= k; i++) {
            b[lu + i] = tu; b[lv + i] = tv; b[pu + i] = ru; b[pv + i] = rv;
            tu *= u; tv *= v; ru *= su; rv *= sv;
        }
        both(n, u, su, b, bu, lu, pu);
        both(m, v, sv, b, bv, lv, pv);
    }

    /**
     * The degree-{@code (deg−1)} basis {@code L_i = C(deg−1,i)·tⁱ·s^(deg−1−i)} in place of the
     * powers {@code tⁱ} at {@code lo} (the powers {@code sⁱ} at {@code po}), and with it the
     * degree-{@code deg} basis {@code B_i = s·L_i + t·L_(i−1)} into {@code bo}, in one pass.
     */
    private static void both(int deg, double t, double s, double[] b, int bo, int lo, int po) {
        int k = deg - 1, binom = k * ORDER;
        double previous = 0;
        for (int i = 0; i <= k; i++) {
            double l = BINOMIAL[binom + i] * b[lo + i] * b[po + k - i];
            b[lo + i] = l;
            b[bo + i] = i == 0 ? s * l : s * l + t * previous;
            previous = l;
        }
        b[bo + deg] = t * previous;
    }

    /**
     * The degree-{@code deg} Bernstein basis at {@code t} into {@code b[bo .. bo+deg]} and the
     * degree-{@code (deg−1)} basis into {@code b[lo .. lo+deg−1]}; {@code deg ≥ 1}. Uses
     * {@code b[lo + ORDER .. lo + 2·ORDER)} for the powers of {@code 1 − t}.
     */
    static void basis(int deg, double t, double[] b, int bo, int lo) {
        double s = 1 - t;
        int po = lo + ORDER;
        double tp = 1, sp = 1;
        for (int i = 0; i < deg; i++) {
            b[lo + i] = tp;
            b[po + i] = sp;
            tp *= t;
            sp *= s;
        }
        both(deg, t, s, b, bo, lo, po);
    }
}
