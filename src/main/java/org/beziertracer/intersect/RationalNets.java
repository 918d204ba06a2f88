package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SubPatchTable;

/**
 * The ray-space nets of rational leaves, for the clipping and subdivision solvers.
 *
 * <p>A rational leaf is projected like a polynomial one and each point then multiplied by its
 * weight: slot {@code e} of {@link TraceContext#arena} holds {@code (w·d1, w·d2, w·d3)} and the
 * same slot of {@link TraceContext#weightArena} holds {@code w}. Together they are the leaf's
 * homogeneous ray-space net, so de Casteljau restriction and splitting of both (the same steps
 * on each coordinate) are exact. The first two coordinates are the <b>weighted distances</b>
 * {@code w_ij·d_ij}: the ray meets the rational patch exactly where
 * {@code Σ w_ij·d_ij·B_i(u)·B_j(v)} vanishes in both (T. Nishita, T. W. Sederberg, M. Kakimoto,
 * "Ray tracing trimmed rational surface patches", SIGGRAPH 1990), so the convex-hull clip, the
 * sign tests and the single-root test run unchanged on them. Only the ray parameter needs the
 * Euclidean distances {@code d3 = (w·d3)/w}, whose range bounds t over the piece (the rational
 * patch is a convex combination of its Euclidean points).
 *
 * <p>Allocation-free; the polynomial path never calls these.
 */
final class RationalNets {
    private RationalNets() {}

    /** Doubles per weight slot: one per point of the largest net. */
    static final int WEIGHT_SLOT = DeCasteljau.MAX_ORDER * DeCasteljau.MAX_ORDER;

    /** True when leaf {@code s} belongs to a rational patch. */
    static boolean rational(SubPatchTable tab, int s) {
        return tab.weights != null && tab.patchDim[tab.parent[s]] == 4;
    }

    /** Weighs slot 0 of the arena, just projected from leaf {@code s}, and fills weight slot 0. */
    static void weigh(TraceContext ctx, SubPatchTable tab, int s, int points) {
        double[] a = ctx.arena, w = ctx.weightArena, tw = tab.weights;
        int from = tab.netOffset[s] / 3;
        for (int k = 0, p = 0; k < points; k++, p += 3) {
            double wk = tw[from + k];
            w[k] = wk;
            a[p] *= wk;
            a[p + 1] *= wk;
            a[p + 2] *= wk;
        }
    }

    /**
     * The ray-space bounds of the piece in slot {@code slot} into {@code rb} (the layout of
     * {@code Bounds.ofPoints}: minima, then maxima): the first two coordinates over the weighted
     * distances (their signs are those of the distances), the third over the Euclidean
     * {@code d3 = (w·d3)/w}, which bounds the ray parameter. One pass.
     */
    static void rayBounds(TraceContext ctx, int slot, int points, double[] rb) {
        double[] a = ctx.arena, w = ctx.weightArena;
        int p = slot * 3 * points, q = slot * points;
        double lo1 = Double.POSITIVE_INFINITY, lo2 = lo1, lo3 = lo1;
        double hi1 = Double.NEGATIVE_INFINITY, hi2 = hi1, hi3 = hi1;
        for (int k = 0; k < points; k++, p += 3) {
            double d1 = a[p], d2 = a[p + 1], d3 = a[p + 2] / w[q + k];
            if (d1 < lo1) lo1 = d1;
            if (d1 > hi1) hi1 = d1;
            if (d2 < lo2) lo2 = d2;
            if (d2 > hi2) hi2 = d2;
            if (d3 < lo3) lo3 = d3;
            if (d3 > hi3) hi3 = d3;
        }
        rb[0] = lo1; rb[1] = lo2; rb[2] = lo3;
        rb[3] = hi1; rb[4] = hi2; rb[5] = hi3;
    }

    /** Restricts the weights of slot {@code slot} in u to {@code [a,b]}, as the arena was. */
    static void restrictU(TraceContext ctx, int slot, int n, int m, double a, double b) {
        DeCasteljau.restrictU(ctx.weightArena, slot * (n + 1) * (m + 1), n, m, 1, a, b);
    }

    /** Restricts the weights of slot {@code slot} in v to {@code [a,b]}, as the arena was. */
    static void restrictV(TraceContext ctx, int slot, int n, int m, double a, double b) {
        DeCasteljau.restrictV(ctx.weightArena, slot * (n + 1) * (m + 1), n, m, 1, a, b);
    }

    /**
     * Splits the weights of slot {@code slot} in half as {@code BezierClipper.split} split the
     * arena: the halves go to slots {@code slot} and {@code slot + 1}, swapped when it swapped.
     */
    static void split(TraceContext ctx, int slot, int n, int m, boolean inU, boolean swapped) {
        int points = (n + 1) * (m + 1), base = slot * points, next = base + points;
        double[] w = ctx.weightArena, tmp = ctx.tmpNet;
        System.arraycopy(w, base, tmp, 0, points);
        int lo = swapped ? next : base, hi = swapped ? base : next;
        if (inU) {
            DeCasteljau.splitU(tmp, 0, n, m, 1, 0.5, w, lo, w, hi);
        } else {
            DeCasteljau.splitV(tmp, 0, n, m, 1, 0.5, w, lo, w, hi);
        }
    }

    /** Divides the piece in slot {@code slot} by its weights: Euclidean ray-space points again. */
    static void toEuclidean(TraceContext ctx, int slot, int points) {
        double[] a = ctx.arena, w = ctx.weightArena;
        for (int k = 0, p = slot * 3 * points, q = slot * points; k < points; k++, p += 3) {
            double wk = w[q + k];
            a[p] /= wk;
            a[p + 1] /= wk;
            a[p + 2] /= wk;
        }
    }
}
