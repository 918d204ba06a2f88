package org.beziertracer.intersect;

import java.util.stream.IntStream;

import org.beziertracer.geometry.SubPatchTable;

/**
 * What {@link NewtonSolver} needs of each leaf (and what {@link ClippingLeaves} keep for its
 * enclosure and start, {@link BezierClipper#intersect}), in one flat record of {@link #STRIDE}
 * floats (64 bytes) so that a leaf test reads one or two cache lines (the leaf's control net is
 * not touched; Newton evaluates the parent patch):
 * <pre>
 *   U0, DU, V0, DV   the leaf's parameter box in its patch: [U0, U0+DU] × [V0, V0+DV]
 *   C  (3)           centre of the leaf's four corner points
 *   A, B (3 each)    centres of the smallest boxes around the scaled hodograph control points
 *                    n·(P[i+1][j] − P[i][j]) and m·(P[i][j+1] − P[i][j])
 *   RA, RB           radii of the balls around A and B that hold those points, hence hold the
 *                    derivatives Su and Sv of the leaf (in its own parameters) everywhere on it
 *                    (convex-hull property of the hodographs; Farin, Curves and Surfaces for
 *                    CAGD, 5th ed., §16.6)
 *   R                the leaf lies within R of its parallelogram P(s,t) = C + (s−½)A + (t−½)B
 * </pre>
 * The bound R is the smaller of two bounds. (1) Along any path from the corner {@code (0,0)},
 * {@code S(s,t) − P00 − sA − tB} is the integral of {@code Su − A} and {@code Sv − B}, so
 * {@code |S − (P00 + sA + tB)| ≤ s·RA + t·RB}, and {@code P00 + sA + tB} is {@code P(s,t)} shifted
 * by {@code P00 − C + (A+B)/2}; this bound adds the two (polynomial leaves only). (2) Every
 * control point {@code P[i][j]} lies within distance {@code d} of the parallelogram's point
 * {@code P(i/n, j/m)} (d the largest such distance), so the convex hull of the control points,
 * which holds the leaf (also a rational one, its weights being positive), lies within {@code d}
 * of the parallelogram. Bound (2) is usually several times the smaller on curved leaves: (1)
 * grows with the whole spread of the derivatives, (2) with the leaf's deviation from the plane
 * of A and B.
 * The parallelogram is the leaf's enclosure (a thin parallelepiped, as in K. Qin, M. Gong, G. Tong,
 * "Fast ray tracing NURBS surfaces", J. Comput. Sci. Technol. 11(1), 1996, whose ray–enclosure
 * intersection also gives the start) and its axes the single-root test's balls
 * ({@link RootUniqueness}).
 *
 * <p>Immutable after {@link #build}; shared by render threads.
 */
final class NewtonLeafRecords {
    private NewtonLeafRecords() {}

    /** Doubles per leaf. */
    static final int STRIDE = 16;
    static final int U0 = 0, DU = 1, V0 = 2, DV = 3, C = 4, A = 7, B = 10, RA = 13, RB = 14, R = 15;

    /**
     * The records of every sub-patch of {@code table}, as floats (one 64-byte record a leaf): the
     * box entries are exact (dyadic fractions), and the rounding of C, A and B is added to R, RA
     * and RB (rounded up), so every bound still holds.
     */
    static float[] build(SubPatchTable table) {
        float[] rec = new float[STRIDE * table.count];
        int chunks = (table.count + CHUNK - 1) / CHUNK;
        if (chunks > 1) {
            IntStream.range(0, chunks).parallel().forEach(c -> fill(table, rec, c * CHUNK, Math.min(table.count, (c + 1) * CHUNK)));
        } else {
            fill(table, rec, 0, table.count);
        }
        return rec;
    }

    /** Leaves a task of the parallel {@link #build} fills. */
    private static final int CHUNK = 4096;

    /**
     * The records of {@code after}, an edit of {@code before} (whose records are {@code old}) in the
     * patches {@code edited}: only those patches' leaves are computed ({@link EditedLeafData}).
     */
    static float[] edited(float[] old, SubPatchTable before, SubPatchTable after, int[] edited) {
        return EditedLeafData.of(old, before, after, edited, STRIDE, NewtonLeafRecords::fill);
    }

    /** The records of leaves {@code from .. to-1}. */
    private static void fill(SubPatchTable table, float[] rec, int from, int to) {
        double[] frame = new double[STRIDE];
        float[] box = table.boxes;
        for (int s = from; s < to; s++) {
            frame(table.nets, table.netOffset[s], table.degreeU[s], table.degreeV[s],
                    table.patchDim[table.parent[s]] != 3, frame, 0);
            store(frame, box[4 * s], box[4 * s + 1] - box[4 * s], box[4 * s + 2], box[4 * s + 3] - box[4 * s + 2],
                    rec, STRIDE * s);
        }
    }

    /** The record of a whole net, in its own parameters (box {@code [0,1]²}), from its {@link #frame}. */
    static float[] leaf(double[] frame) {
        float[] rec = new float[STRIDE];
        store(frame, 0, 1, 0, 1, rec, 0);
        return rec;
    }

    static void store(double[] frame, double u0, double du, double v0, double dv, float[] rec, int o) {
        rec[o + U0] = (float) u0;
        rec[o + DU] = (float) du;
        rec[o + V0] = (float) v0;
        rec[o + DV] = (float) dv;
        double dc = round(frame, rec, o, C), da = round(frame, rec, o, A), db = round(frame, rec, o, B);
        rec[o + RA] = up(frame[RA] + da);
        rec[o + RB] = up(frame[RB] + db);
        rec[o + R] = up(frame[R] + dc + 0.5 * (da + db));
    }

    /** Rounds the vector at {@code frame[at..at+3)} to floats into {@code rec[o+at..]}; returns the rounding's length. */
    private static double round(double[] frame, float[] rec, int o, int at) {
        double sq = 0;
        for (int c = 0; c < 3; c++) {
            rec[o + at + c] = (float) frame[at + c];
            double d = rec[o + at + c] - frame[at + c];
            sq += d * d;
        }
        return Math.sqrt(sq);
    }

    /** The smallest float at least {@code x}, a little more for the rounding of the sum that made it. */
    private static float up(double x) {
        return Math.nextUp((float) (x * (1 + 1e-12)));
    }

    /**
     * Writes C, A, B, RA, RB and R of the degree {@code n}×{@code m} net at {@code net[off..]} to
     * {@code rec[o + C .. o + R]} (the box entries are left alone); for a {@code rational} leaf
     * (its control points' Euclidean positions, positive weights) R is the convex-hull bound alone.
     */
    static void frame(double[] net, int off, int n, int m, boolean rational, double[] rec, int o) {
        int row = 3 * (n + 1);
        int p00 = off, pn0 = off + 3 * n, p0m = off + row * m, pnm = p0m + 3 * n;
        midRanges(net, off, n, m, rec, o);
        for (int c = 0; c < 3; c++) {
            rec[o + C + c] = 0.25 * (net[p00 + c] + net[pn0 + c] + net[p0m + c] + net[pnm + c]);
        }
        // The largest squared distances, then one square root each (the root is monotone, so the
        // root of the largest square is the largest root, to the bit)
        double ra = 0, rb = 0;
        for (int j = 0; j <= m; j++) {
            for (int i = 0, p = off + j * row; i <= n; i++, p += 3) {
                if (i < n) {
                    ra = Math.max(ra, squaredDistance(net, p, p + 3, n, rec, o + A));
                }
                if (j < m) {
                    rb = Math.max(rb, squaredDistance(net, p, p + row, m, rec, o + B));
                }
            }
        }
        ra = Math.sqrt(ra);
        rb = Math.sqrt(rb);
        double ex = rec[o + C] - 0.5 * (rec[o + A] + rec[o + B]) - net[p00];
        double ey = rec[o + C + 1] - 0.5 * (rec[o + A + 1] + rec[o + B + 1]) - net[p00 + 1];
        double ez = rec[o + C + 2] - 0.5 * (rec[o + A + 2] + rec[o + B + 2]) - net[p00 + 2];
        rec[o + RA] = ra;
        rec[o + RB] = rb;
        double hull = hullReach(net, off, n, m, rec, o);
        rec[o + R] = rational ? hull : Math.min(hull, Math.sqrt(ex * ex + ey * ey + ez * ez) + ra + rb);
    }

    /**
     * The largest distance of a control point {@code P[i][j]} of the net at {@code net[off..]}
     * from the parallelogram point {@code C + (i/n − ½)A + (j/m − ½)B} of {@code rec[o..]}.
     */
    private static double hullReach(double[] net, int off, int n, int m, double[] rec, int o) {
        int row = 3 * (n + 1);
        double reach = 0;
        for (int j = 0; j <= m; j++) {
            double t = (double) j / m - 0.5;
            for (int i = 0, p = off + j * row; i <= n; i++, p += 3) {
                double s = (double) i / n - 0.5, sq = 0;
                for (int c = 0; c < 3; c++) {
                    double d = net[p + c] - (rec[o + C + c] + s * rec[o + A + c] + t * rec[o + B + c]);
                    sq += d * d;
                }
                reach = Math.max(reach, sq);
            }
        }
        return Math.sqrt(reach);
    }

    /**
     * A and B into {@code rec[o + A ..]}, {@code rec[o + B ..]}: per coordinate, the middle of the
     * range of {@code n·(P[i+1][j] − P[i][j])} (along u) and of {@code m·(P[i][j+1] − P[i][j])}
     * (along v) over the net at {@code net[off..]}.
     */
    private static void midRanges(double[] net, int off, int n, int m, double[] rec, int o) {
        int row = 3 * (n + 1);
        midRange(net, off, row, n, m + 1, 3, n, rec, o + A);
        midRange(net, off, row, n + 1, m, row, m, rec, o + B);
    }

    /**
     * Per coordinate, the middle of the range of {@code deg·(net[p + step] − net[p])} over the
     * {@code columns × rows} points {@code p} from {@code net[off]} (rows {@code row} doubles apart), into
     * {@code rec[at .. at+3)}, in one pass. (Comparisons, not Math.min and Math.max: the net is
     * finite, and the two differ only on NaN and on the order of ±0.)
     */
    private static void midRange(double[] net, int off, int row, int columns, int rows, int step, int deg,
                                 double[] rec, int at) {
        double lx = Double.POSITIVE_INFINITY, ly = lx, lz = lx, hx = Double.NEGATIVE_INFINITY, hy = hx, hz = hx;
        for (int j = 0; j < rows; j++) {
            for (int i = 0, p = off + j * row; i < columns; i++, p += 3) {
                double x = deg * (net[p + step] - net[p]), y = deg * (net[p + step + 1] - net[p + 1]);
                double z = deg * (net[p + step + 2] - net[p + 2]);
                if (x < lx) lx = x;
                if (x > hx) hx = x;
                if (y < ly) ly = y;
                if (y > hy) hy = y;
                if (z < lz) lz = z;
                if (z > hz) hz = z;
            }
        }
        rec[at] = 0.5 * (lx + hx);
        rec[at + 1] = 0.5 * (ly + hy);
        rec[at + 2] = 0.5 * (lz + hz);
    }

    /** {@code |deg·(net[q] − net[p]) − rec[axis..axis+3)|²}. */
    private static double squaredDistance(double[] net, int p, int q, int deg, double[] rec, int axis) {
        double x = deg * (net[q] - net[p]) - rec[axis], y = deg * (net[q + 1] - net[p + 1]) - rec[axis + 1];
        double z = deg * (net[q + 2] - net[p + 2]) - rec[axis + 2];
        return x * x + y * y + z * z;
    }
}
