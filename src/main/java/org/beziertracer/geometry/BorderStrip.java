package org.beziertracer.geometry;

import org.beziertracer.model.BezierPatch;

/**
 * One side of a patch seen from a border: the boundary curve and the patch's derivatives across
 * it, as polynomials in the border parameter {@code t} (Bernstein form, homogeneous
 * {@code (w·x, w·y, w·z, w)} coordinates, dim 4).
 *
 * <p>Write the patch in border coordinates {@code (t, s)}: {@code t} runs along the side (reversed
 * when asked, so that two sides of one border run the same way) and {@code s ≥ 0} runs into the
 * patch, the side being {@code s = 0}. Re-index the homogeneous net as {@code R_ik}, {@code i} along
 * the border (degree {@code d}), {@code k} inward (degree {@code e}). Then along the border
 * (Farin, <i>Curves and Surfaces for CAGD</i>, 5th ed., the chapter on derivatives of
 * tensor-product patches: cross-boundary derivatives from the first rows of the net):
 * <pre>
 *   X(t)    = Σ_i R_i0 B_i^d(t)
 *   X_s(t)  = e Σ_i (R_i1 − R_i0) B_i^d(t)
 *   X_ss(t) = e(e−1) Σ_i (R_i2 − 2 R_i1 + R_i0) B_i^d(t)        (0 when e = 1)
 *   X_t, X_tt, X_ts: derivatives in t of the above (hodographs)
 * </pre>
 * {@link #outward} negates {@code s} (the first-order cross derivatives), so that of two sides of a
 * border, one seen outward and the other inward, the cross directions point the same way: from
 * the first patch into the second.
 *
 * <p>Sides are numbered 0: {@code u = 0}, 1: {@code u = 1}, 2: {@code v = 0}, 3: {@code v = 1}.
 * Immutable.
 *
 * @param x    X(t), dim 4
 * @param xt   X_t
 * @param xs   X_s
 * @param xtt  X_tt
 * @param xts  X_ts
 * @param xss  X_ss
 * @param rational whether the patch has weights (else w ≡ 1 and its derivatives vanish)
 * @param sign {@code ±1}: the patch's own normal {@code S_u × S_v} is {@code sign · (S_t × S_s)}
 */
public record BorderStrip(BernsteinPoly x, BernsteinPoly xt, BernsteinPoly xs, BernsteinPoly xtt,
                          BernsteinPoly xts, BernsteinPoly xss, boolean rational, int sign) {

    /** Side names, by number: {@code u=0, u=1, v=0, v=1}. */
    public static final String[] SIDE_NAMES = {"u=0", "u=1", "v=0", "v=1"};

    /**
     * The strip of {@code side} of {@code patch}.
     *
     * @param reversed {@code t} runs against the side's own parameter
     * @param outward  {@code s} points out of the patch instead of into it
     */
    public static BorderStrip of(BezierPatch patch, int side, boolean reversed, boolean outward) {
        if (side < 0 || side > 3) {
            throw new IllegalArgumentException("side must be 0..3, got " + side);
        }
        int n = patch.degreeU(), m = patch.degreeV();
        boolean alongV = side < 2; // u = 0 or u = 1: the border runs along v
        int d = alongV ? m : n, e = alongV ? n : m;
        double[][] rows = new double[Math.min(e, 2) + 1][];
        for (int k = 0; k < rows.length; k++) {
            double[] row = new double[4 * (d + 1)];
            for (int i = 0; i <= d; i++) {
                int along = reversed ? d - i : i;
                int across = side == 0 || side == 2 ? k : e - k;
                int pu = alongV ? across : along, pv = alongV ? along : across;
                double w = patch.weight(pu, pv);
                for (int c = 0; c < 3; c++) {
                    row[4 * i + c] = w * patch.get(pu, pv, c);
                }
                row[4 * i + 3] = w;
            }
            rows[k] = row;
        }
        BernsteinPoly r0 = BernsteinPoly.of(d, 4, rows[0]), r1 = BernsteinPoly.of(d, 4, rows[1]);
        double s = outward ? -1 : 1;
        BernsteinPoly x = r0;
        BernsteinPoly xs = r1.minus(r0).times(s * e);
        BernsteinPoly xss = e >= 2
                ? BernsteinPoly.of(d, 4, rows[2]).minus(r1.times(2)).plus(r0).times(e * (e - 1.0))
                : BernsteinPoly.of(d, 4, new double[4 * (d + 1)]);
        BernsteinPoly xt = x.derivative();
        // S_t × S_s against S_u × S_v: t = ±(along), s = ±(across); (v, u) order flips the cross product
        int tSign = reversed ? -1 : 1;
        int sSign = (side == 0 || side == 2 ? 1 : -1) * (outward ? -1 : 1);
        int sign = tSign * sSign * (alongV ? -1 : 1);
        return new BorderStrip(x, xt, xs, xt.derivative(), xs.derivative(), xss, patch.isRational(), sign);
    }

    /** Euclidean position, border tangent and cross derivative, for a polynomial patch (dim 3). */
    public BernsteinPoly position() { return x.coordinates(0, 3); }

    /** The weight along the border (dim 1). */
    public BernsteinPoly weight() { return x.coordinates(3, 1); }

    /**
     * A normal of the surface along the border, polynomial in {@code t} and pointing along
     * {@code S_t × S_s}: for a polynomial patch {@code X_t × X_s}; for a rational one
     * {@code w (X_t × X_s) − w_t (X × X_s) − w_s (X_t × X)}, which is {@code w³ (S_t × S_s)} (a
     * positive multiple, weights being positive).
     */
    public BernsteinPoly normal() {
        BernsteinPoly pt = xt.coordinates(0, 3), ps = xs.coordinates(0, 3);
        if (!rational) {
            return pt.cross(ps);
        }
        BernsteinPoly p = x.coordinates(0, 3), w = weight();
        BernsteinPoly wt = xt.coordinates(3, 1), ws = xs.coordinates(3, 1);
        return pt.cross(ps).scaledBy(w).minus(p.cross(ps).scaledBy(wt)).minus(pt.cross(p).scaledBy(ws));
    }

    /**
     * Euclidean {@code S, S_t, S_s, S_tt, S_ts, S_ss} at {@code t} (18 doubles), by the quotient
     * rule from the homogeneous derivatives (as {@link SecondDerivatives} does for patches).
     */
    public double[] euclidean(double t) {
        double[] h0 = x.value(t), ht = xt.value(t), hs = xs.value(t);
        double[] htt = xtt.value(t), hts = xts.value(t), hss = xss.value(t);
        double w = h0[3], wt = ht[3], ws = hs[3], wtt = htt[3], wts = hts[3], wss = hss[3];
        double[] out = new double[18];
        for (int c = 0; c < 3; c++) {
            double p = h0[c] / w;
            double pt = (ht[c] - wt * p) / w, ps = (hs[c] - ws * p) / w;
            out[c] = p;
            out[3 + c] = pt;
            out[6 + c] = ps;
            out[9 + c] = (htt[c] - 2 * wt * pt - wtt * p) / w;
            out[12 + c] = (hts[c] - wt * ps - ws * pt - wts * p) / w;
            out[15 + c] = (hss[c] - 2 * ws * ps - wss * p) / w;
        }
        return out;
    }
}
