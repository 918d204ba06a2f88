package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * A shadow ray cannot meet a sub-patch of the patch it leaves when the sub-patch lies below the
 * plane through the ray's origin parallel to the surface's tangent plane there: a proof that skips
 * the clipping search a shadow ray otherwise runs on its own leaf and on its neighbours.
 *
 * <p>The ray leaves the point {@code P = S(u0, v0)} from {@code O = P + h0·n} ({@code n} the unit
 * normal on the light's side, {@code h0 > 0} the renderer's offset), in a direction {@code d}
 * with {@code n·d > 0}. Every point of the ray beyond its origin has {@code n·(R − O) > 0}. The
 * height {@code h(u,v) = n·(S(u,v) − P)} is a polynomial of the patch's degree whose Bézier
 * coefficients over the leaf are {@code n·(P_ij − P)}; split at {@code (u0, v0)} into four pieces
 * (de Casteljau), each piece has P as a corner, where {@code h} and its first derivatives vanish,
 * so on a surface that curves away from the light (the outside of a teapot) every coefficient of
 * every piece is at most about zero. Another leaf of the same patch is split at its point nearest
 * to {@code (u0, v0)} in parameters instead (on a shared edge, where {@code h} is about zero and
 * falls into the leaf). When they are all at most {@code h0/2}, the convex-hull
 * property puts the whole leaf at {@code n·(X − O) ≤ −h0/2 < 0}, and the ray cannot meet it. The
 * margin {@code h0/2} is many orders above the rounding of the coefficients, which the test also
 * requires ({@link #ROUNDING}). Nothing is proven on a surface that curves toward the light (a
 * bowl seen from inside, a saddle); the leaf is then searched as before.
 *
 * <p>The tangent-plane argument is the separating-plane test of ray–hull culling (as in
 * Nishita, Sederberg and Kakimoto 1990, where the ray's planes clip the hull), applied to the
 * pieces that the split at the ray's own origin makes tight around it.
 */
final class OriginLeaf {
    private OriginLeaf() {}

    /**
     * The offset must exceed this fraction of the leaf's size plus the point's distance from the
     * coordinates' origin. The heights and the split round by about 10⁻¹⁴ of that (differences of
     * coordinates of that size, and fewer than 32 de Casteljau levels), so the margin of half the
     * offset stays five orders above it.
     */
    static final double ROUNDING = 1e-9;

    /** A Newton start on the ray's own leaf nearer than this to the origin's point is not tried ({@link #awayFromOrigin}). */
    static final double NEAR_ORIGIN = 0.25;

    /** Leaves whose last test failed, remembered per thread (a power of two). */
    static final int MEMORY = 256;
    /** A remembered leaf is tested again on every this many rays that leave it. */
    static final int RETRY = 32;

    /** Doubles of scratch a context keeps for the test (four nets of the largest degree). */
    static final int SCRATCH = 4 * 16 * 16;

    /**
     * True when leaf {@code s} provably does not meet the context's any-hit ray, which leaves the
     * surface point its {@code origin*} fields describe (a point of this leaf's patch); false when that
     * is not proven (not a polynomial leaf, a ray that does not leave on the normal's side, a
     * surface that curves toward it).
     */
    static boolean cannotMeet(TraceContext ctx, SubPatchTable tab, int s) {
        // A leaf this thread could not prove lately (a saddle, a bowl) is searched without trying
        // again, but for every RETRY-th ray: saves the failing test's time, changes no answer
        int slot = s & (MEMORY - 1);
        if (ctx.originFailed[slot] == s + 1 && ++ctx.originSkipped[slot] % RETRY != 0) {
            return false;
        }
        boolean proven = proven(ctx, tab, s);
        ctx.originFailed[slot] = proven ? 0 : s + 1;
        return proven;
    }

    /**
     * Newton's start on the leaf the ray leaves, when the leaf is proven single-root for the ray:
     * the origin's own point (a root lies within about the offset of it, behind the origin), in
     * leaf parameters into {@code ctx.clip}, clamped to the leaf. The answer is Newton's on the
     * patch, whatever the start; this one saves the evaluations of the way there.
     */
    static void startAtOrigin(TraceContext ctx, SubPatchTable tab, int s) {
        ctx.clip[0] = Math.min(1, Math.max(0, leafParameter(ctx, tab, s, true)));
        ctx.clip[1] = Math.min(1, Math.max(0, leafParameter(ctx, tab, s, false)));
    }

    /**
     * Newton's start {@code (su, sv)} on leaf {@code s}, the leaf a shadow ray leaves, lies at least
     * {@link #NEAR_ORIGIN} (in the leaf's parameters, summed over both) from the origin's point. From a nearer start
     * Newton all but always converges to the origin's own root, behind the ray: counted on the
     * curved patch's frame, 73,600 attempts from within that distance found 280 roots ahead, those
     * from farther 10,670 roots in 41,000 (teapot: none in 20,300, 790 in 8,000).
     */
    static boolean awayFromOrigin(TraceContext ctx, SubPatchTable tab, int s, double su, double sv) {
        double d = Math.abs(su - leafParameter(ctx, tab, s, true)) + Math.abs(sv - leafParameter(ctx, tab, s, false));
        return !(d < NEAR_ORIGIN);
    }

    /** The origin's u ({@code alongU}) or v in leaf {@code s}'s own parameters (0..1 inside the leaf). */
    private static double leafParameter(TraceContext ctx, SubPatchTable tab, int s, boolean alongU) {
        int k = tab.parent[s];
        double[] domain = tab.patchDomain;
        boolean plain = SurfaceParameters.unit(domain, k);
        double x = alongU ? (plain ? ctx.originU : SurfaceParameters.s(domain, k, ctx.originU))
                : (plain ? ctx.originV : SurfaceParameters.t(domain, k, ctx.originV));
        int o = 4 * s + (alongU ? 0 : 2);
        return (x - tab.boxes[o]) / (tab.boxes[o + 1] - tab.boxes[o]);
    }

    /** The test itself. */
    private static boolean proven(TraceContext ctx, SubPatchTable tab, int s) {
        int k = tab.parent[s];
        if (tab.patchDim[k] != 3 || !(ctx.tMin >= 0)) {
            return false;
        }
        // The split at the origin's point, clamped to the leaf: on another leaf of the same patch,
        // the leaf's point nearest to it in parameters (any split point makes the proof; a near
        // one makes it tight)
        double a = Math.min(1, Math.max(0, leafParameter(ctx, tab, s, true)));
        double b = Math.min(1, Math.max(0, leafParameter(ctx, tab, s, false)));
        if (!(a >= 0 && b >= 0)) {
            return false; // NaN
        }
        double nx = ctx.originNx, ny = ctx.originNy, nz = ctx.originNz;
        double px = ctx.originPx, py = ctx.originPy, pz = ctx.originPz;
        double h0 = nx * (ctx.ox - px) + ny * (ctx.oy - py) + nz * (ctx.oz - pz);
        double magnitude = tab.diagonal[s] + Math.abs(px) + Math.abs(py) + Math.abs(pz);
        if (!(nx * ctx.dx + ny * ctx.dy + nz * ctx.dz > 0) || !(h0 > ROUNDING * magnitude)) {
            return false;
        }
        int n = tab.degreeU[s], m = tab.degreeV[s], points = (n + 1) * (m + 1);
        double[] net = tab.nets, w = ctx.originScratch;
        int base = tab.netOffset[s], row = 3 * (n + 1);
        double limit = 0.5 * h0;
        // The leaf's corners are points of the surface and corners of the pieces: on a surface
        // that curves toward the light one of them is above the plane, and the test ends here
        for (int c = 0; c < 4; c++) {
            int o = base + ((c & 1) == 0 ? 0 : 3 * n) + ((c & 2) == 0 ? 0 : m * row);
            if (nx * (net[o] - px) + ny * (net[o + 1] - py) + nz * (net[o + 2] - pz) > limit) {
                return false;
            }
        }
        double sum = 0;
        for (int i = 0, o = base; i < points; i++, o += 3) {
            w[i] = nx * (net[o] - px) + ny * (net[o + 1] - py) + nz * (net[o + 2] - pz);
            sum += w[i];
        }
        // A leaf whose net sags away from the light between its corners (a bowl seen from inside)
        // rises above the plane somewhere: not worth the split (this only saves time; the proof
        // is the split's)
        double corners = w[0] + w[n] + w[m * (n + 1)] + w[points - 1];
        if (sum / points < corners / 4) {
            return false;
        }
        return piecesBelow(w, n, m, a, b, limit);
    }

    /**
     * True when the scalar net {@code w[0 .. (n+1)(m+1))} (row after row, u fastest), split with
     * de Casteljau at {@code (a, b)} into four pieces, has every piece's every coefficient at most
     * {@code limit}; stops at the first one above. {@code w} holds {@link #SCRATCH} doubles; the
     * rest of it is overwritten.
     */
    static boolean piecesBelow(double[] w, int n, int m, double a, double b, double limit) {
        int points = (n + 1) * (m + 1), lo = points, hi = 2 * points, piece = 3 * points;
        splitU(w, 0, n, m, a, w, lo, w, hi);
        return belowInV(w, lo, n, m, b, piece, limit) && belowInV(w, hi, n, m, b, piece, limit);
    }

    /** Splits the scalar net at {@code w[half..]} in v at {@code b}; true when both pieces' coefficients are at most {@code limit}. */
    private static boolean belowInV(double[] w, int half, int n, int m, double b, int piece, double limit) {
        // low piece: copy, then de Casteljau in place toward v = 0..b, checking as points are fixed
        for (int i = 0; i <= n; i++) {
            // column i: coefficients w[half + j(n+1) + i], j = 0..m
            for (int j = 0; j <= m; j++) {
                w[piece + j] = w[half + j * (n + 1) + i];
            }
            if (!curveBelow(w, piece, m, b, limit)) {
                return false;
            }
        }
        return true;
    }

    /**
     * De Casteljau on the scalar curve {@code c[o..o+deg]} at {@code t}: true when every
     * coefficient of both halves is at most {@code limit}. Destroys the curve.
     */
    private static boolean curveBelow(double[] c, int o, int deg, double t, double limit) {
        double s = 1 - t;
        // the low half's coefficients are c[o] after each level; the high half's are the final row
        if (c[o] > limit || c[o + deg] > limit) {
            return false;
        }
        for (int r = 1; r <= deg; r++) {
            for (int k = o; k <= o + deg - r; k++) {
                c[k] = s * c[k] + t * c[k + 1];
            }
            // after level r: c[o] is the low half's coefficient r, c[o + deg - r] the high half's deg - r
            if (c[o] > limit || c[o + deg - r] > limit) {
                return false;
            }
        }
        return true;
    }

    /** Splits the scalar net in u at {@code a} into {@code lo} and {@code hi} (plain de Casteljau per row). */
    private static void splitU(double[] src, int so, int n, int m, double a, double[] lo, int lOff, double[] hi,
                               int hOff) {
        double s = 1 - a;
        for (int j = 0; j <= m; j++) {
            int r = j * (n + 1);
            for (int i = 0; i <= n; i++) {
                hi[hOff + r + i] = src[so + r + i];
            }
            for (int level = 1; level <= n; level++) {
                lo[lOff + r + level - 1] = hi[hOff + r];
                for (int i = 0; i <= n - level; i++) {
                    hi[hOff + r + i] = s * hi[hOff + r + i] + a * hi[hOff + r + i + 1];
                }
            }
            lo[lOff + r + n] = hi[hOff + r];
        }
    }
}
