package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * Proves that a single-root leaf holds no root at all, from its border alone.
 *
 * <p>On a leaf that {@link RootUniqueness} proves single-root for the ray, the ray-space map
 * {@code F = (F1, F2)} is one-to-one: the single-root argument (the mean-value theorem along the
 * segment from {@code p} to {@code q} and the non-vanishing of every mixed Jacobian) uses only
 * {@code F(p) = F(q)}, so it excludes that for every {@code p ≠ q}. A continuous one-to-one map of
 * the closed parameter square is a homeomorphism onto its image, a closed disk bounded by the
 * image of the square's border. So the ray meets the leaf exactly when the origin lies in that
 * disk, that is when the closed curve {@code F(∂leaf)}, four Bézier curves (the border rows and
 * columns of the net, in ray space), winds around the origin. The winding number is the signed
 * count of the curve's crossings of the half-line {@code {y = 0, x > 0}} (J. Kajiya's
 * ray-crossing test for curves, as in the point-in-region tests of Nishita, Sederberg and
 * Kakimoto 1990 for trim curves). Each border curve is split with de Casteljau until every piece
 * is settled by its control points (convex hull): wholly above, below or left of the half-line,
 * or monotone in y with both ends clear of the axis and wholly right of the origin. Every test
 * keeps a margin {@code eps} (rounding of the projection), so a curve passing within {@code eps}
 * of the origin, or a vertex on the half-line, is never settled: the caller then searches the leaf
 * as before. A winding number of zero, every piece settled, is a proof that the leaf holds no
 * root.
 *
 * <p>Allocation-free: the pieces live in the context's {@link TraceContext#curveStack}.
 */
final class BoundaryWinding {
    private BoundaryWinding() {}

    /**
     * Halvings of a border curve before it is given up on. A piece crossing the half-line settles
     * once it lies right of the origin, so a ray passing a distance {@code d} beside a border of
     * length {@code L} needs about {@code log₂(L/d)} halvings, and only the pieces near the ray
     * are halved (two a level at most, so a curve through the ray itself costs about
     * {@code 2·MAX_DEPTH} halvings before it is given up). At 6 one ray in 130 passing within a fifth
     * of a leaf's width beside it was left to clipping (wavy10 with an off-eye light: about 800 leaves
     * a frame, each clipped in about 10 µs where the winding takes 1); at 16, none of
     * {@code BoundaryWindingTest}'s 73,154.
     */
    static final int MAX_DEPTH = 16;

    /**
     * True when polynomial leaf {@code s}, proven single-root for the ray of {@code ctx}, provably
     * holds no root: the image of its border does not wind around the ray. False when it does, or
     * when that could not be settled within {@code eps}.
     */
    static boolean holdsNoRoot(TraceContext ctx, SubPatchTable tab, int s, double eps) {
        return holdsNoRoot(ctx, tab.nets, tab.netOffset[s], tab.degreeU[s], tab.degreeV[s], eps);
    }

    /**
     * {@link #holdsNoRoot(TraceContext, SubPatchTable, int, double)} for a piece of a patch proven
     * single-root for the ray, its border given as four 3-D curves, each stored forwards (increasing
     * parameter, {@code 3·(deg + 1)} doubles) at {@code curves[off + k·stride]}, {@code k} = 0..3:
     * {@code v = v0} and {@code u = u1} (degrees {@code n} and {@code m}), then {@code v = v1} and
     * {@code u = u0}, which the closed loop runs backwards.
     */
    static boolean bordersHoldNoRoot(TraceContext ctx, double[] curves, int off, int stride, int n, int m,
                                     double eps) {
        return windsZero(ctx, curves, off, 3, off + stride, 3, off + 2 * stride + 3 * n, -3,
                off + 3 * stride + 3 * m, -3, n, m, eps);
    }

    /** The net at {@code net[off..]}: its border rows and columns, in loop order. */
    private static boolean holdsNoRoot(TraceContext ctx, double[] net, int off, int n, int m, double eps) {
        int row = 3 * (n + 1);
        return windsZero(ctx, net, off, 3, off + 3 * n, row, off + row * m + 3 * n, -3, off + row * m, -row, n, m, eps);
    }

    /**
     * True when the closed loop of the four curves {@code pts[f_k + i·s_k]} (degrees n, m, n, m)
     * settles and its winding number about the ray is zero.
     */
    private static boolean windsZero(TraceContext ctx, double[] pts, int f0, int s0, int f1, int s1, int f2, int s2,
                                     int f3, int s3, int n, int m, double eps) {
        int c0 = crossings(ctx, pts, f0, s0, n, eps);
        if (c0 == UNSETTLED) {
            return false;
        }
        int c1 = crossings(ctx, pts, f1, s1, m, eps);
        if (c1 == UNSETTLED) {
            return false;
        }
        int c2 = crossings(ctx, pts, f2, s2, n, eps);
        if (c2 == UNSETTLED) {
            return false;
        }
        int c3 = crossings(ctx, pts, f3, s3, m, eps);
        return c3 != UNSETTLED && c0 + c1 + c2 + c3 == 0;
    }

    /** {@link #crossings} could not settle a piece. */
    static final int UNSETTLED = Integer.MIN_VALUE;

    /**
     * Signed crossings of the half-line {@code y = 0, x > 0} by the border curve of degree
     * {@code deg} whose 3-D control points are {@code net[first + i·step]}, projected into the
     * ray's plane: +1 for each crossing upwards, −1 downwards; {@link #UNSETTLED} when a piece
     * could not be settled within {@link #MAX_DEPTH} halvings.
     */
    static int crossings(TraceContext ctx, double[] net, int first, int step, int deg, double eps) {
        double[] st = ctx.curveStack;
        int len = 2 * (deg + 1);
        for (int i = 0, p = first; i <= deg; i++, p += step) {
            double qx = net[p] - ctx.ox, qy = net[p + 1] - ctx.oy, qz = net[p + 2] - ctx.oz;
            st[2 * i] = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
            st[2 * i + 1] = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        }
        int[] depth = ctx.curveDepth;
        depth[0] = 0;
        int sp = 1, count = 0;
        while (sp > 0) {
            int base = (sp - 1) * len;
            int piece = settle(st, base, deg, eps);
            if (piece != UNSETTLED) {
                count += piece;
                sp--;
                continue;
            }
            int d = depth[sp - 1];
            if (d >= MAX_DEPTH) {
                return UNSETTLED;
            }
            // Halve: both halves in place of the piece, one above the other
            halve(st, base, base + len, deg);
            depth[sp - 1] = d + 1;
            depth[sp] = d + 1;
            sp++;
        }
        return count;
    }

    /**
     * The signed crossings of the piece at {@code st[base..]} when its control points settle them;
     * else {@link #UNSETTLED}.
     */
    private static int settle(double[] st, int base, int deg, double eps) {
        double yMin = Double.POSITIVE_INFINITY, yMax = Double.NEGATIVE_INFINITY;
        double xMin = Double.POSITIVE_INFINITY, xMax = Double.NEGATIVE_INFINITY;
        boolean up = true, down = true;
        for (int i = 0; i <= deg; i++) {
            double x = st[base + 2 * i], y = st[base + 2 * i + 1];
            xMin = Math.min(xMin, x);
            xMax = Math.max(xMax, x);
            yMin = Math.min(yMin, y);
            yMax = Math.max(yMax, y);
            if (i > 0) {
                double prev = st[base + 2 * i - 1];
                up &= y >= prev;
                down &= y <= prev;
            }
        }
        if (yMin > eps || yMax < -eps || xMax < -eps) {
            return 0; // wholly above, below, or left of the half-line
        }
        double y0 = st[base + 1], y1 = st[base + 2 * deg + 1];
        if ((up || down) && Math.abs(y0) > eps && Math.abs(y1) > eps) {
            if ((y0 > 0) == (y1 > 0)) {
                return 0; // monotone in y, both ends on one side: no crossing at all
            }
            if (xMin > eps) {
                return y1 > 0 ? 1 : -1; // one crossing, and it is right of the origin
            }
        }
        return UNSETTLED;
    }

    /**
     * de Casteljau at ½ in one pass over the triangle: the right half of the 2-D curve at
     * {@code st[base..]} stays there, the left half goes to {@code st[other..]} (the order of the
     * two pieces on the stack does not matter: their crossings are summed).
     */
    private static void halve(double[] st, int base, int other, int deg) {
        st[other] = st[base];
        st[other + 1] = st[base + 1];
        for (int level = 1; level <= deg; level++) {
            for (int i = 0; i <= deg - level; i++) {
                int p = base + 2 * i;
                st[p] = 0.5 * (st[p] + st[p + 2]);
                st[p + 1] = 0.5 * (st[p + 1] + st[p + 3]);
            }
            // b_0^level: the left half's point number level; the right half's point i is b_i^(deg-i)
            st[other + 2 * level] = st[base];
            st[other + 2 * level + 1] = st[base + 1];
        }
    }
}
