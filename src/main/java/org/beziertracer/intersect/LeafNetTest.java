package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;

/**
 * A closer look at a Newton leaf that its record could not settle ({@link NewtonSolver#start}
 * returned {@link NewtonSolver#MAYBE_SEVERAL}: the ray grazes the leaf), from the leaf's own
 * control net mapped into ray space, as Bézier clipping maps it (T. Nishita, T. W. Sederberg,
 * M. Kakimoto, "Ray tracing trimmed rational surface patches", SIGGRAPH 1990): the first two
 * coordinates of a control point are its distances to the two planes whose intersection is the
 * ray, the third its distance along the ray.
 *
 * <ul>
 *   <li><b>No root of its own.</b> The leaf lies in the convex hull of its control points (also for
 *       a rational leaf, whose weights are positive). When a line in the ray-space plane has every
 *       projected control point beyond the tolerance on one side — the plane's two axes, the
 *       normals of the two axes of the corners' parallelogram and of its two diagonals — or every
 *       depth lies outside {@code (tMin, tMax)}, no point of the leaf's own parameter box is a
 *       root within the tolerance: {@link #NO_ROOT}.</li>
 *   <li><b>At most one root of its own.</b> {@link RootUniqueness#atMostOneRoot(double[], int, int, int)}
 *       on the projected net (the exact ranges of the ray-space derivatives' control points, tighter
 *       than the record's balls): {@link #ONE_ROOT}.</li>
 * </ul>
 * Both are proofs about the leaf's own box only; its overlapped domain reaches into the
 * neighbours, which look after their own roots.
 *
 * <p>Allocation-free: the projected net goes into {@code ctx.tmpNet}.
 */
final class LeafNetTest {
    private LeafNetTest() {}

    /** Outcomes of {@link #classify}. */
    static final int NO_ROOT = 0, ONE_ROOT = 1, SEVERAL = 2;

    /** Relative rounding of a projected coordinate, as a multiple of the largest projected coordinate. */
    private static final double ROUNDING = 1e-14;

    /**
     * What the own net of leaf {@code s} proves about its roots with {@code tMin < t < tMax} for the
     * ray of {@code ctx}: {@link #NO_ROOT}, {@link #ONE_ROOT} or {@link #SEVERAL} (nothing proved).
     * The projected net is left in {@code ctx.tmpNet}.
     */
    static int classify(TraceContext ctx, SubPatchTable tab, int s, float reach, double tMin, double tMax,
                        double tolerance) {
        int n = tab.degreeU[s], m = tab.degreeV[s], count = (n + 1) * (m + 1);
        if (cornersMiss(ctx, tab.nets, tab.netOffset[s], n, m, reach + tolerance * Math.sqrt(2))) {
            return NO_ROOT;
        }
        double[] q = ctx.tmpNet;
        ctx.project(tab.nets, tab.netOffset[s], count, q, 0);
        double xLo = Double.POSITIVE_INFINITY, xHi = Double.NEGATIVE_INFINITY;
        double yLo = Double.POSITIVE_INFINITY, yHi = Double.NEGATIVE_INFINITY;
        double zLo = Double.POSITIVE_INFINITY, zHi = Double.NEGATIVE_INFINITY;
        for (int i = 0, p = 0; i < count; i++, p += 3) {
            xLo = Math.min(xLo, q[p]);
            xHi = Math.max(xHi, q[p]);
            yLo = Math.min(yLo, q[p + 1]);
            yHi = Math.max(yHi, q[p + 1]);
            zLo = Math.min(zLo, q[p + 2]);
            zHi = Math.max(zHi, q[p + 2]);
        }
        double big = Math.max(Math.max(Math.max(-xLo, xHi), Math.max(-yLo, yHi)), Math.max(-zLo, zHi));
        double r = tolerance + ROUNDING * big;
        if (xLo > r || xHi < -r || yLo > r || yHi < -r
                || (zLo - r) * ctx.invLength >= tMax || (zHi + r) * ctx.invLength <= tMin) {
            return NO_ROOT;
        }
        if (separatedByCornerAxes(q, n, m, count, r)) {
            return NO_ROOT;
        }
        return RootUniqueness.atMostOneRoot(q, 0, n, m) ? ONE_ROOT : SEVERAL;
    }

    /**
     * True when the ray passes farther than {@code r} from the convex hull of the four corner
     * points of the net at {@code net[off..]} (seen along the ray): a separating line among the
     * plane's axes, the normals of the four edges and of the two diagonals of the corner
     * quadrilateral (every edge of the hull of four points is one of those six segments).
     */
    static boolean cornersMiss(TraceContext ctx, double[] net, int off, int n, int m, double r) {
        double[] c = ctx.corners;
        int row = 3 * (n + 1);
        double big = Math.max(Math.max(project(ctx, net, off, c, 0), project(ctx, net, off + 3 * n, c, 2)),
                Math.max(project(ctx, net, off + row * m, c, 4), project(ctx, net, off + row * m + 3 * n, c, 6)));
        double reach = r + ROUNDING * big;
        double x0 = c[0], y0 = c[1], x1 = c[2], y1 = c[3], x2 = c[4], y2 = c[5], x3 = c[6], y3 = c[7];
        return separated(1, 0, c, reach) || separated(0, 1, c, reach)
                || separated(y1 - y0, x0 - x1, c, reach) || separated(y3 - y1, x1 - x3, c, reach)
                || separated(y2 - y3, x3 - x2, c, reach) || separated(y0 - y2, x2 - x0, c, reach)
                || separated(y3 - y0, x0 - x3, c, reach) || separated(y2 - y1, x1 - x2, c, reach);
    }

    /** The first two ray-space coordinates of the point at {@code src[p..]} into {@code out[o..]}; returns its distance bound |x|+|y|+|z| from the origin. */
    private static double project(TraceContext ctx, double[] src, int p, double[] out, int o) {
        double qx = src[p] - ctx.ox, qy = src[p + 1] - ctx.oy, qz = src[p + 2] - ctx.oz;
        out[o] = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
        out[o + 1] = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
        return Math.abs(qx) + Math.abs(qy) + Math.abs(qz);
    }

    /** True when the four points of {@code c} (x, y pairs) lie beyond {@code r} on one side along {@code (ax, ay)}. */
    private static boolean separated(double ax, double ay, double[] c, double r) {
        double p0 = ax * c[0] + ay * c[1], p1 = ax * c[2] + ay * c[3], p2 = ax * c[4] + ay * c[5], p3 = ax * c[6] + ay * c[7];
        double lo = Math.min(Math.min(p0, p1), Math.min(p2, p3)), hi = Math.max(Math.max(p0, p1), Math.max(p2, p3));
        double gap = lo > 0 ? lo : hi < 0 ? -hi : 0;
        return gap > 0 && gap * gap > r * r * (ax * ax + ay * ay);
    }

    /**
     * True when the normal of one of the corners' parallelogram axes (the mean of the u edges, of
     * the v edges) or of its diagonals has every projected point of {@code q} beyond {@code r}
     * (times √2: a point within {@code r} of the ray in both plane coordinates is within
     * {@code r·√2} of it) on one side of the origin.
     */
    static boolean separatedByCornerAxes(double[] q, int n, int m, int count, double r) {
        int row = 3 * (n + 1), c0 = 0, cn = 3 * n, c0m = row * m, cnm = row * m + 3 * n;
        double ex = 0.5 * (q[cn] - q[c0] + q[cnm] - q[c0m]), ey = 0.5 * (q[cn + 1] - q[c0 + 1] + q[cnm + 1] - q[c0m + 1]);
        double fx = 0.5 * (q[c0m] - q[c0] + q[cnm] - q[cn]), fy = 0.5 * (q[c0m + 1] - q[c0 + 1] + q[cnm + 1] - q[cn + 1]);
        double rr = r * Math.sqrt(2);
        return separates(-ey, ex, q, count, rr) || separates(-fy, fx, q, count, rr)
                || separates(-(ey + fy), ex + fx, q, count, rr) || separates(-(ey - fy), ex - fx, q, count, rr);
    }

    /** True when every point of {@code q} lies beyond {@code r} on one side along the direction {@code (ax, ay)}. */
    private static boolean separates(double ax, double ay, double[] q, int count, double r) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int i = 0, p = 0; i < count; i++, p += 3) {
            double d = ax * q[p] + ay * q[p + 1];
            lo = Math.min(lo, d);
            hi = Math.max(hi, d);
        }
        double reach = r * Math.sqrt(ax * ax + ay * ay);
        return lo > reach || hi < -reach;
    }
}
