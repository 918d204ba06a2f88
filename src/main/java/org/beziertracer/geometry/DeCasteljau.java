package org.beziertracer.geometry;

/**
 * Stateless, allocation-free de Casteljau algorithms on tensor-product Bézier control nets
 * stored in flat {@code double[]} arrays.
 *
 * <h2>Net layout</h2>
 * A net of degree {@code n} in u and {@code m} in v with {@code dim} coordinates per point
 * occupies {@code (n+1)(m+1)*dim} doubles from offset {@code off}: point
 * {@code k = j*(n+1) + i} holds {@code P_ij} ({@code i} along u, <b>u fastest</b>) and its
 * coordinates are at {@code off + k*dim + c}, {@code c < dim}. This is the layout of
 * {@link org.beziertracer.model.BezierPatch} for {@code dim = 3}; the ray tracer also uses
 * {@code dim = 2} (nets projected into ray space) and {@code dim = 1} (distance nets).
 * Degrees run from 1 to {@code MAX_ORDER - 1} (= {@link org.beziertracer.model.BezierPatch#MAX_DEGREE});
 * degree 0 is accepted too, which is handy for hodograph (derivative) nets.
 *
 * <h2>Scratch and threads</h2>
 * Methods that need working memory take a caller-owned {@code scratch} array of at least
 * {@link #SCRATCH_LENGTH} doubles; its contents on entry and exit are irrelevant. No method
 * allocates, so one scratch array per thread makes every method here safe for concurrent use.
 *
 * <h2>Source</h2>
 * P. de Casteljau's algorithm and its tensor-product form, subdivision, and derivatives from
 * the intermediate points: G. Farin, <i>Curves and Surfaces for CAGD: A Practical Guide</i>,
 * 5th ed., Morgan Kaufmann 2002, the chapters on the de Casteljau algorithm (subdivision,
 * derivatives) and on tensor-product Bézier patches.
 */
public final class DeCasteljau {

    /** Maximum number of control points in one direction (degree 15 + 1). */
    public static final int MAX_ORDER = 16;

    /**
     * Minimum length of the {@code scratch} array any method of the {@code geometry} package
     * needs: room for two full 3-D nets of order {@value #MAX_ORDER}×{@value #MAX_ORDER}
     * ({@code 2*16*16*3 = 1536}). The current methods use at most {@code 9 + 3*MAX_ORDER*3}
     * of it; the generous size leaves room for later methods without changing callers.
     */
    public static final int SCRATCH_LENGTH = 2 * MAX_ORDER * MAX_ORDER * 3;

    private DeCasteljau() {}

    // ---------------------------------------------------------------- evaluation

    /**
     * Evaluates {@code S(u,v)} into {@code out[outOff .. outOff+dim)}. Uses
     * {@code (n+1+m+1)*dim} doubles of {@code scratch}.
     */
    public static void evaluate(double[] net, int off, int n, int m, int dim, double u, double v,
                                double[] out, int outOff, double[] scratch) {
        int rowStride = (n + 1) * dim;
        int col = (n + 1) * dim;                 // column of row results starts here in scratch
        // Reduce every row in u to one point, then the column of those points in v
        for (int j = 0; j <= m; j++) {
            System.arraycopy(net, off + j * rowStride, scratch, 0, rowStride);
            reduceForward(scratch, 0, dim, n, dim, u, n);
            System.arraycopy(scratch, 0, scratch, col + j * dim, dim);
        }
        reduceForward(scratch, col, dim, m, dim, v, m);
        System.arraycopy(scratch, col, out, outOff, dim);
    }

    /**
     * 3-D evaluation with exact first derivatives: {@code S} into {@code out[0..2]},
     * {@code ∂S/∂u} into {@code out[3..5]}, {@code ∂S/∂v} into {@code out[6..8]}.
     */
    public static void evaluateWithDerivatives(double[] net, int off, int n, int m, double u, double v,
                                               double[] out, double[] scratch) {
        evaluateWithDerivatives(net, off, n, m, 3, u, v, out, 0, scratch, 0);
    }

    /**
     * Any-dimension evaluation with exact first derivatives: {@code S}, {@code ∂S/∂u},
     * {@code ∂S/∂v} into {@code out[outOff ..)}, {@code dim} doubles each, in that order.
     *
     * <p>The tensor-product de Casteljau algorithm is run down to level {@code (n-1, m-1)},
     * leaving four points {@code b00, b10, b01, b11}; then {@code S} is their bilinear
     * interpolant at {@code (u,v)}, {@code ∂S/∂u = n·lerp_v(b10-b00, b11-b01)} and
     * {@code ∂S/∂v = m·lerp_u(b01-b00, b11-b10)} (Farin, tensor-product patches). Degrees must be ≥ 1.
     * For {@code dim = 3}, nets of degree {@code n + m > 4} other than bicubics are evaluated
     * by the equivalent {@code O(n·m)} Bernstein sums instead ({@link BernsteinEval}).
     * Uses {@code scratchOff + 3*MAX_ORDER*dim} doubles of {@code scratch}.
     */
    public static void evaluateWithDerivatives(double[] net, int off, int n, int m, int dim, double u, double v,
                                               double[] out, int outOff, double[] scratch, int scratchOff) {
        if (dim == 3) {
            DeCasteljau3.evaluateWithDerivatives(net, off, n, m, u, v, out, outOff, scratch, scratchOff);
            return;
        }
        int rowStride = (n + 1) * dim;
        int colA = scratchOff + MAX_ORDER * dim; // b_{0,j} of level n-1 in u, j = 0..m
        int colB = colA + MAX_ORDER * dim;       // b_{1,j}
        // Reduce every row in u to level n-1: two points per row
        for (int j = 0; j <= m; j++) {
            System.arraycopy(net, off + j * rowStride, scratch, scratchOff, rowStride);
            reduceForward(scratch, scratchOff, dim, n, dim, u, n - 1);
            System.arraycopy(scratch, scratchOff, scratch, colA + j * dim, dim);
            System.arraycopy(scratch, scratchOff + dim, scratch, colB + j * dim, dim);
        }
        // Reduce both columns in v to level m-1
        reduceForward(scratch, colA, dim, m, dim, v, m - 1);
        reduceForward(scratch, colB, dim, m, dim, v, m - 1);
        double su = 1 - u, sv = 1 - v;
        for (int c = 0; c < dim; c++) {
            double b00 = scratch[colA + c], b01 = scratch[colA + dim + c];
            double b10 = scratch[colB + c], b11 = scratch[colB + dim + c];
            double lo = sv * b00 + v * b01;     // points at u-level n-1 ends, v fully reduced
            double hi = sv * b10 + v * b11;
            out[outOff + c] = su * lo + u * hi;
            out[outOff + dim + c] = n * (hi - lo);
            out[outOff + 2 * dim + c] = m * (su * (b01 - b00) + u * (b11 - b10));
        }
    }

    /**
     * Evaluates one Bézier curve of degree {@code deg} with points at
     * {@code pts[ptsOff + k*stride .. +dim)} at {@code t} into {@code out[outOff..+dim)};
     * {@code pts} is left unchanged. Uses {@code (deg+1)*dim} doubles of {@code scratch}.
     */
    public static void evaluateCurve(double[] pts, int ptsOff, int stride, int deg, int dim, double t,
                                     double[] out, int outOff, double[] scratch) {
        for (int k = 0; k <= deg; k++) {
            System.arraycopy(pts, ptsOff + k * stride, scratch, k * dim, dim);
        }
        reduceForward(scratch, 0, dim, deg, dim, t, deg);
        System.arraycopy(scratch, 0, out, outOff, dim);
    }

    // ---------------------------------------------------------------- subdivision

    /**
     * Splits the net in u at {@code t}: {@code lo} receives the net of {@code [0,t]}, {@code hi}
     * the net of {@code [t,1]}, each reparametrised to {@code [0,1]} and with the same layout and
     * size as {@code src}. Either output may be {@code null} (skipped). An output may be
     * {@code src} itself at the same offset (in-place); otherwise outputs must not overlap
     * {@code src} or each other.
     */
    public static void splitU(double[] src, int srcOff, int n, int m, int dim, double t,
                              double[] lo, int loOff, double[] hi, int hiOff) {
        int rowStride = (n + 1) * dim;
        for (int j = 0; j <= m; j++) {
            int r = j * rowStride;
            splitCurve(src, srcOff + r, dim, n, dim, t, lo, loOff + r, hi, hiOff + r);
        }
    }

    /** Splits the net in v at {@code t}; contract as {@link #splitU}. */
    public static void splitV(double[] src, int srcOff, int n, int m, int dim, double t,
                              double[] lo, int loOff, double[] hi, int hiOff) {
        int rowStride = (n + 1) * dim;
        for (int i = 0; i <= n; i++) {
            int c = i * dim;
            splitCurve(src, srcOff + c, rowStride, m, dim, t, lo, loOff + c, hi, hiOff + c);
        }
    }

    /**
     * Restricts the net in place to {@code u ∈ [a,b]}, {@code 0 ≤ a ≤ b ≤ 1} (values outside are
     * clamped), reparametrised to {@code [0,1]}; v is untouched. Two splits: at {@code b}
     * keeping the low part, then at {@code a/b} keeping the high part. Both steps are plain
     * de Casteljau (convex combinations, numerically stable); {@code a/b} carries a relative
     * error of one rounding, i.e. an absolute error of about {@code ulp(a)} in the original
     * parameter, so tiny intervals near 0 or near 1 stay accurate. When {@code a == b} every row collapses to its point at {@code a}; {@code a > b} (or NaN)
     * is treated the same way — callers must pass ordered bounds.
     */
    public static void restrictU(double[] net, int off, int n, int m, int dim, double a, double b) {
        int rowStride = (n + 1) * dim;
        for (int j = 0; j <= m; j++) {
            restrictCurve(net, off + j * rowStride, dim, n, dim, a, b);
        }
    }

    /** Restricts the net in place to {@code v ∈ [a,b]}; contract as {@link #restrictU}. */
    public static void restrictV(double[] net, int off, int n, int m, int dim, double a, double b) {
        int rowStride = (n + 1) * dim;
        for (int i = 0; i <= n; i++) {
            restrictCurve(net, off + i * dim, rowStride, m, dim, a, b);
        }
    }

    /**
     * Writes the net of the sub-patch over the parameter box {@code [u0,u1]×[v0,v1]} to
     * {@code dest} at {@code destOff}. {@code dest} may be {@code src} (at any offset; the
     * source is copied first with {@link System#arraycopy}, which handles overlap).
     */
    public static void subPatch(double[] src, int srcOff, int n, int m, int dim,
                                double u0, double u1, double v0, double v1, double[] dest, int destOff) {
        if (dest != src || destOff != srcOff) {
            System.arraycopy(src, srcOff, dest, destOff, (n + 1) * (m + 1) * dim);
        }
        restrictU(dest, destOff, n, m, dim, u0, u1);
        restrictV(dest, destOff, n, m, dim, v0, v1);
    }

    // ---------------------------------------------------------------- curve kernels

    /**
     * In-place forward de Casteljau on {@code deg+1} points at {@code p[off + k*stride]}:
     * runs {@code levels} levels; afterwards point {@code k} holds {@code b_k^levels}.
     */
    static void reduceForward(double[] p, int off, int stride, int deg, int dim, double t, int levels) {
        double s = 1 - t;
        if (dim == 3) {
            // the hot case (3-D and ray-space nets), unrolled
            for (int r = 1; r <= levels; r++) {
                for (int k = 0, a = off; k <= deg - r; k++, a += stride) {
                    int b = a + stride;
                    p[a] = s * p[a] + t * p[b];
                    p[a + 1] = s * p[a + 1] + t * p[b + 1];
                    p[a + 2] = s * p[a + 2] + t * p[b + 2];
                }
            }
            return;
        }
        for (int r = 1; r <= levels; r++) {
            for (int k = 0, a = off; k <= deg - r; k++, a += stride) {
                for (int c = 0; c < dim; c++) {
                    p[a + c] = s * p[a + c] + t * p[a + stride + c];
                }
            }
        }
    }

    /** Splits one curve; see {@link #splitU} for the aliasing contract (same stride everywhere). */
    static void splitCurve(double[] src, int srcOff, int stride, int deg, int dim, double t,
                           double[] lo, int loOff, double[] hi, int hiOff) {
        double s = 1 - t;
        boolean hiIsSrc = hi == src && hiOff == srcOff;
        if (dim == 3 && hi != null && hi != src) {
            splitCurve3(src, srcOff, stride, deg, s, t, lo, loOff, hi, hiOff);
        } else if (hi != null && !hiIsSrc) {
            // Work in hi: after level r, point 0 is lo_r; at the end point k is hi_k
            copyCurve(src, srcOff, hi, hiOff, stride, deg, dim);
            for (int r = 1; r <= deg; r++) {
                if (lo != null) {
                    copyPoint(hi, hiOff, lo, loOff + (r - 1) * stride, dim);
                }
                for (int k = 0, a = hiOff; k <= deg - r; k++, a += stride) {
                    for (int c = 0; c < dim; c++) {
                        hi[a + c] = s * hi[a + c] + t * hi[a + stride + c];
                    }
                }
            }
            if (lo != null) {
                copyPoint(hi, hiOff, lo, loOff + deg * stride, dim);
            }
        } else if (lo != null) {
            // Work in lo, backwards: after level r, point deg is hi_{deg-r}; at the end point k is lo_k
            if (lo != src || loOff != srcOff) {
                copyCurve(src, srcOff, lo, loOff, stride, deg, dim);
            }
            int last = loOff + deg * stride;
            for (int r = 1; r <= deg; r++) {
                if (hi != null) {
                    copyPoint(lo, last, hi, hiOff + (deg - r + 1) * stride, dim);
                }
                if (dim == 3) {
                    for (int k = deg, a = last; k >= r; k--, a -= stride) {
                        int b = a - stride;
                        lo[a] = s * lo[b] + t * lo[a];
                        lo[a + 1] = s * lo[b + 1] + t * lo[a + 1];
                        lo[a + 2] = s * lo[b + 2] + t * lo[a + 2];
                    }
                    continue;
                }
                for (int k = deg, a = last; k >= r; k--, a -= stride) {
                    for (int c = 0; c < dim; c++) {
                        lo[a + c] = s * lo[a - stride + c] + t * lo[a + c];
                    }
                }
            }
            if (hi != null) {
                copyPoint(lo, last, hi, hiOff, dim);
            }
        }
        // hi is src and lo is null: hi = [t,1] computed in place
        else if (hi != null) {
            reduceForward(hi, hiOff, stride, deg, dim, t, deg);
        }
    }

    /**
     * {@link #splitCurve} of a 3-D curve into another array {@code hi} (the pre-split's case):
     * the same arithmetic, unrolled, without the copy helpers' calls.
     */
    private static void splitCurve3(double[] src, int srcOff, int stride, int deg, double s, double t,
                                    double[] lo, int loOff, double[] hi, int hiOff) {
        for (int k = 0, a = srcOff, b = hiOff; k <= deg; k++, a += stride, b += stride) {
            hi[b] = src[a];
            hi[b + 1] = src[a + 1];
            hi[b + 2] = src[a + 2];
        }
        for (int r = 1; r <= deg; r++) {
            if (lo != null) {
                int l = loOff + (r - 1) * stride;
                lo[l] = hi[hiOff];
                lo[l + 1] = hi[hiOff + 1];
                lo[l + 2] = hi[hiOff + 2];
            }
            for (int k = 0, a = hiOff; k <= deg - r; k++, a += stride) {
                int b = a + stride;
                hi[a] = s * hi[a] + t * hi[b];
                hi[a + 1] = s * hi[a + 1] + t * hi[b + 1];
                hi[a + 2] = s * hi[a + 2] + t * hi[b + 2];
            }
        }
        if (lo != null) {
            int l = loOff + deg * stride;
            lo[l] = hi[hiOff];
            lo[l + 1] = hi[hiOff + 1];
            lo[l + 2] = hi[hiOff + 2];
        }
    }

    /** In-place restriction of one curve to {@code [a,b]}; see {@link #restrictU}. */
    static void restrictCurve(double[] p, int off, int stride, int deg, int dim, double a, double b) {
        a = Math.min(1, Math.max(0, a));
        b = Math.min(1, Math.max(0, b));
        if (!(b > a)) {
            // Degenerate interval: every point becomes the curve point at a
            reduceForward(p, off, stride, deg, dim, a, deg);
            for (int k = 1; k <= deg; k++) {
                copyPoint(p, off, p, off + k * stride, dim);
            }
            return;
        }
        if (dim == 3) {
            DeCasteljau3.restrictCurve(p, off, stride, deg, a, b);
            return;
        }
        if (b < 1) {
            splitCurve(p, off, stride, deg, dim, b, p, off, null, 0);
        }
        if (a > 0) {
            double t = Math.min(1, a / b);
            reduceForward(p, off, stride, deg, dim, t, deg);   // keeps [t,1] in place
        }
    }

    private static void copyCurve(double[] src, int srcOff, double[] dst, int dstOff, int stride, int deg, int dim) {
        if (stride == dim) {
            System.arraycopy(src, srcOff, dst, dstOff, (deg + 1) * dim);
        } else {
            for (int k = 0; k <= deg; k++) {
                System.arraycopy(src, srcOff + k * stride, dst, dstOff + k * stride, dim);
            }
        }
    }

    private static void copyPoint(double[] src, int srcOff, double[] dst, int dstOff, int dim) {
        for (int c = 0; c < dim; c++) {
            dst[dstOff + c] = src[srcOff + c];
        }
    }
}
