package org.beziertracer.intersect;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.HeapBytes;

/**
 * The four quarters of a leaf above bicubic, each with its own {@link NewtonLeafRecords} record
 * (the leaf's net split at {@code u = ½} and {@code v = ½} by de Casteljau): a second chance for
 * a ray that the leaf's own single-root test cannot settle. Such a ray usually passes near a fold
 * of the surface seen edge-on, where the leaf's derivatives spread too wide for the test; a
 * quarter's spread about half as far, so most quarters the ray meets pass it (or their enclosure
 * proves a miss), and Newton settles each, where the whole leaf would be clipped (clipping a
 * degree-9 leaf costs about as much as ten Newton solves).
 *
 * <p>The proof is the records' own, quarter by quarter: a quarter whose enclosure the ray misses
 * in {@code (tMin, tMax)} holds no root there; a quarter proven single-root whose Newton iteration
 * (confined to the quarter) converged holds that root and no other; a single-root quarter where it
 * did not converge, usually a quarter the ray passes beside, holds none when the image of its
 * border does not wind around the ray ({@link BoundaryWinding}: the record's proof makes the
 * ray-space map one-to-one on the quarter); when every quarter is settled so, the nearest of their
 * roots is the leaf's nearest. Anything else (a quarter not proven single-root, a failed Newton
 * attempt whose quarter the winding cannot prove empty) leaves the leaf to clipping, as before. The
 * idea is that of the clipping search's own split into halves (Nishita, Sederberg and Kakimoto
 * 1990), taken one level ahead with precomputed enclosures (K. Qin, M. Gong, G. Tong, "Fast ray
 * tracing NURBS surfaces", 1996).
 *
 * <p>Only polynomial leaves above bicubic get quarters, in tables of at most {@link #MOST_LEAVES}
 * leaves (a record is 64 bytes, so a leaf's quarters take 256): on bicubic leaves, whose clipping
 * costs far less, the teapot and the curved patch read only about 2 % faster with them. A leaf's quarters are made the first time a ray needs them, by the render
 * thread that needs them, and published with a release store of the leaf's flag (read with an
 * acquire load): two threads may make the same leaf's quarters at once and write the same values,
 * so what any thread reads is the one deterministic result, and an edit (a new table) costs
 * nothing until a ray needs a quarter.
 *
 * <p>Layout: {@link #STRIDE} floats a leaf, the records of quarters (u low, v low), (u high, v
 * low), (u low, v high), (u high, v high).
 */
final class LeafQuarters {

    /** Floats a leaf: four records. */
    static final int STRIDE = 4 * NewtonLeafRecords.STRIDE;
    /** Outcomes of {@link #solve}. */
    static final int UNDECIDED = -1, NO_ROOT = 0, ROOT = 1;

    private static final VarHandle MADE = MethodHandles.arrayElementVarHandle(int[].class);

    final float[] records;
    /** 1 where the leaf's quarters are made (release store after the records, acquire load before reading them). */
    private final int[] made;

    private LeafQuarters(int leaves) {
        this.records = new float[STRIDE * leaves];
        this.made = new int[leaves];
    }

    /** Most leaves a table may have to get quarters: 4 MB of them at most. */
    static final int MOST_LEAVES = 1 << 14;

    /**
     * Quarters for {@code table}'s leaves, none made yet; null when no leaf has any (no polynomial
     * patch above bicubic) or the table has more than {@link #MOST_LEAVES} leaves.
     */
    static LeafQuarters of(SubPatchTable table) {
        if (table.count > MOST_LEAVES) {
            return null;
        }
        for (int k = 0; k < table.patchCount(); k++) {
            if (has(table, k) && table.countOf(k) > 0) {
                return new LeafQuarters(table.count);
            }
        }
        return null;
    }

    /** True when the leaves of patch {@code k} get quarters. */
    static boolean has(SubPatchTable table, int k) {
        return table.patchDim[k] == 3 && table.patchDegreeU[k] + table.patchDegreeV[k] > 6;
    }

    long bytes() {
        return HeapBytes.of(records) + HeapBytes.of(made);
    }

    /**
     * Settles leaf {@code s} for the context's ray quarter by quarter: {@link #ROOT} with the
     * nearest root in {@code (tMin, tMax)} in {@code ctx.root*}, {@link #NO_ROOT}, or
     * {@link #UNDECIDED} when the leaf has no quarters or one could not be settled.
     */
    int solve(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tMax, double tolerance) {
        if (!has(tab, tab.parent[s])) {
            return UNDECIDED;
        }
        ensure(ctx, tab, s);
        int single = 0;
        for (int q = 0; q < 4; q++) {
            int kind = NewtonSolver.start(ctx, records, STRIDE * s + NewtonLeafRecords.STRIDE * q, tMin, tMax, tolerance);
            if (kind == NewtonSolver.MAYBE_SEVERAL) {
                return UNDECIDED;
            }
            if (kind == NewtonSolver.SINGLE_ROOT) {
                single |= 1 << q;
            }
        }
        boolean found = false, anyRoot = ctx.anyHit && tab.trimTest == null;
        double bestT = tMax, bestU = 0, bestV = 0;
        for (int q = 0; q < 4 && !(anyRoot && found); q++) {
            if ((single & (1 << q)) == 0) {
                continue;
            }
            int o = STRIDE * s + NewtonLeafRecords.STRIDE * q;
            double u0 = records[o + NewtonLeafRecords.U0], u1 = u0 + records[o + NewtonLeafRecords.DU];
            double v0 = records[o + NewtonLeafRecords.V0], v1 = v0 + records[o + NewtonLeafRecords.DV];
            if (s == ctx.originLeaf && OriginRoot.behindIn(ctx, tab, tab.parent[s], u0, u1, v0, v1, tMin, tolerance)) {
                // The quarter a shadow ray leaves from: its one root is the origin's point, behind the ray
                ctx.originQuarters++;
                continue;
            }
            NewtonSolver.start(ctx, records, o, tMin, tMax, tolerance); // the start again, into ctx.clip
            if (!BezierClipper.newtonIn(ctx, tab, tab.parent[s], u0, u1, v0, v1, ctx.clip[0], ctx.clip[1], tolerance)) {
                // Usually a quarter the ray passes beside, within its enclosure: the winding of its
                // border proves it empty, else the leaf is left to clipping
                if (holdsNoRoot(ctx, tab, s, q, tolerance)) {
                    continue;
                }
                return UNDECIDED;
            }
            if (ctx.rootT > tMin && ctx.rootT < bestT) {
                found = true;
                bestT = ctx.rootT;
                bestU = ctx.rootU;
                bestV = ctx.rootV;
            }
        }
        if (!found) {
            return NO_ROOT;
        }
        ctx.rootT = bestT;
        ctx.rootU = bestU;
        ctx.rootV = bestV;
        return ROOT;
    }

    /**
     * Quarter {@code q} of leaf {@code s}, proven single-root for the ray by its record, provably
     * holds no root: the image of its border does not wind around the ray ({@link BoundaryWinding};
     * the record's proof, that of {@link RootUniqueness} with the record's balls, makes the ray-space
     * map one-to-one on the quarter as it does on a leaf).
     */
    private static boolean holdsNoRoot(TraceContext ctx, SubPatchTable tab, int s, int q, double tolerance) {
        ctx.quarterWindings++;
        borders(tab, s, q, ctx.arena);
        return BoundaryWinding.bordersHoldNoRoot(ctx, ctx.arena, 0, BORDER, tab.degreeU[s], tab.degreeV[s],
                BezierClipper.windingMargin(ctx, tolerance));
    }

    /**
     * The border of quarter {@code q} of leaf {@code s} as {@link BoundaryWinding#bordersHoldNoRoot}
     * takes it, its curves at {@code out[k·BORDER]} ({@code v = v0}, {@code u = u1}, {@code v = v1},
     * {@code u = u0}); uses {@code out[0 .. 6·BORDER)}.
     */
    static void borders(SubPatchTable tab, int s, int q, double[] out) {
        int n = tab.degreeU[s], m = tab.degreeV[s], uHalf = q & 1, vHalf = q >> 1, net = tab.netOffset[s];
        // each the half of a leaf iso-curve at 0, ½ or 1
        border(tab.nets, net, n, m, true, vHalf, uHalf, out, 0);
        border(tab.nets, net, n, m, false, uHalf + 1, vHalf, out, BORDER);
        border(tab.nets, net, n, m, true, vHalf + 1, uHalf, out, 2 * BORDER);
        border(tab.nets, net, n, m, false, uHalf, vHalf, out, 3 * BORDER);
    }

    /** Doubles of one border curve in {@link #borders}' output. */
    static final int BORDER = 3 * 2 * DeCasteljau.MAX_ORDER;

    /**
     * Into {@code out[at..]} (3-D points, forwards): half {@code half} (0: the first, 1: the second)
     * of the leaf net's iso-curve {@code v = at2/2} along u ({@code alongU}) or {@code u = at2/2}
     * along v, {@code at2} = 0, 1 or 2. The curve at ½ is the Bernstein sum across the net
     * (weights {@code C(k, j)/2^k}: a convex combination, as de Casteljau's at ½, in {@code k + 1}
     * multiply-adds a point instead of {@code k(k+1)/2} averages); the half is split from the curve
     * by de Casteljau, in the arena past the four borders.
     */
    private static void border(double[] nets, int net, int n, int m, boolean alongU, int at2, int half,
                               double[] out, int at) {
        int deg = alongU ? n : m, across = alongU ? m : n;
        int step = alongU ? 3 : 3 * (n + 1), acrossStep = alongU ? 3 * (n + 1) : 3;
        int full = 4 * BORDER; // the whole iso-curve, then split into its halves
        int first = net + (at2 == 2 ? across * acrossStep : 0);
        for (int i = 0; i <= deg; i++) {
            int p = first + i * step, o = full + 3 * i;
            if (at2 == 1) {
                // w_j = C(across, j) / 2^across, exact in double (binomials of degree 15 and below)
                double x = 0, y = 0, z = 0, w = Math.scalb(1.0, -across);
                for (int j = 0, r = p; j <= across; j++, r += acrossStep) {
                    x += w * nets[r]; y += w * nets[r + 1]; z += w * nets[r + 2];
                    w = w * (across - j) / (j + 1);
                }
                out[o] = x; out[o + 1] = y; out[o + 2] = z;
            } else {
                out[o] = nets[p]; out[o + 1] = nets[p + 1]; out[o + 2] = nets[p + 2];
            }
        }
        DeCasteljau.splitU(out, full, deg, 0, 3, 0.5, out, half == 0 ? at : full + BORDER, out,
                half == 0 ? full + BORDER : at);
    }

    /** Makes leaf {@code s}'s quarters unless they are made (a leaf with quarters, {@link #has}). */
    void ensure(TraceContext ctx, SubPatchTable tab, int s) {
        if ((int) MADE.getAcquire(made, s) == 0) {
            make(ctx, tab, s);
            MADE.setRelease(made, s, 1);
        }
    }

    /** Makes leaf {@code s}'s four records, its nets split in the context's arena (slots 0..3, free before clipping). */
    private void make(TraceContext ctx, SubPatchTable tab, int s) {
        int n = tab.degreeU[s], m = tab.degreeV[s], len = TraceContext.NET_LENGTH;
        double[] arena = ctx.arena, frame = ctx.quarterFrame;
        float[] box = tab.boxes;
        double u0 = box[4 * s], du = 0.5 * (box[4 * s + 1] - u0), v0 = box[4 * s + 2], dv = 0.5 * (box[4 * s + 3] - v0);
        DeCasteljau.splitU(tab.nets, tab.netOffset[s], n, m, 3, 0.5, arena, 0, arena, len);
        for (int half = 0; half < 2; half++) {
            DeCasteljau.splitV(arena, half * len, n, m, 3, 0.5, arena, 2 * len, arena, 3 * len);
            for (int q = 0; q < 2; q++) {
                NewtonLeafRecords.frame(arena, (2 + q) * len, n, m, false, frame, 0);
                NewtonLeafRecords.store(frame, u0 + half * du, du, v0 + q * dv, dv, records,
                        STRIDE * s + NewtonLeafRecords.STRIDE * (half + 2 * q));
            }
        }
    }
}
