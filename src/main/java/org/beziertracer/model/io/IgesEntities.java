package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * Turns the curve, surface, trim and transformation entities of an IGES file into exact
 * rational B-splines (IGES 5.3 §4): 100 circular arc, 110 line, 102 composite curve, 126
 * rational B-spline curve, 128 rational B-spline surface, 120 surface of revolution, 122
 * tabulated cylinder, 108 bounded plane, 142 curve on a parametric surface (its parameter-space
 * curve), 141/143 boundary and bounded surface, 144 trimmed surface, 124 transformation matrix.
 * Pointers are checked (an entry of the wrong type, a missing or cyclic one is one line naming
 * the file and the line). A face that cannot be drawn exactly throws {@link Skip} with the reason.
 */
final class IgesEntities {

    /** Why a face is left out, for the summary line ({@code "trimmed by model-space curves only"}). */
    static final class Skip extends RuntimeException {
        Skip(String reason) {
            super(reason, null, false, false);
        }
    }

    /** Largest trim-loop gap closed by a straight piece, relative to the size of the parameter range. */
    static final double LOOP_GAP = 1e-5;

    private final IgesSections file;
    private final Map<Integer, IgesMatrix> matrices = new HashMap<>();
    private final Set<Integer> resolving = new HashSet<>();

    IgesEntities(IgesSections file) {
        this.file = file;
    }

    /** The entry {@code pointer} refers to, required to be one of {@code types}. */
    IgesSections.Entry entry(int pointer, IgesParams from, String role, int... types) {
        IgesSections.Entry e = file.entries.get(pointer);
        if (e == null) {
            throw from.error(role + " points to directory entry " + pointer + ", which does not exist");
        }
        for (int t : types) {
            if (e.type() == t) {
                return e;
            }
        }
        throw from.error(role + " points to entity " + e.type() + " (directory line " + pointer
                + "), expected entity " + join(types));
    }

    private static String join(int[] types) {
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < types.length; k++) {
            sb.append(k == 0 ? "" : k == types.length - 1 ? " or " : ", ").append(types[k]);
        }
        return sb.toString();
    }

    /** The matrix of {@code e}'s directory entry (field 7), composed with the matrices it points to in turn. */
    IgesMatrix matrix(IgesSections.Entry e) {
        if (e.transform() == 0) {
            return IgesMatrix.IDENTITY;
        }
        IgesMatrix known = matrices.get(e.transform());
        if (known != null) {
            return known;
        }
        IgesSections.Entry t = file.entries.get(e.transform());
        if (t == null || t.type() != 124) {
            throw file.source.error(e.line(), "entity " + e.type() + " (directory line " + e.sequence()
                    + "): its transformation matrix pointer " + e.transform() + " is not an entity 124");
        }
        if (!resolving.add(t.sequence())) {
            throw file.source.error(t.line(), "transformation matrices point to each other in a cycle");
        }
        IgesParams p = file.params(t);
        p.require(13, "R11 R12 R13 T1 R21 R22 R23 T2 R31 R32 R33 T3");
        IgesMatrix own = new IgesMatrix(p.reals(1, 12));
        IgesMatrix m = matrix(t).after(own);
        resolving.remove(t.sequence());
        matrices.put(e.transform(), m);
        return m;
    }

    /** The curve entity {@code e} as its pieces (one, or a composite's), each in its own matrix. */
    List<IgesCurve> curve(IgesSections.Entry e, int depth) {
        if (depth > 16) {
            throw file.source.error(e.line(), "composite curves nested more than 16 deep (a cycle?)");
        }
        IgesParams p = file.params(e);
        List<IgesCurve> out = new ArrayList<>();
        switch (e.type()) {
            case 110 -> {
                p.require(7, "X1 Y1 Z1 X2 Y2 Z2");
                out.add(IgesCurve.line(p.reals(1, 3), p.reals(4, 3)));
            }
            case 100 -> out.add(arc(p));
            case 126 -> out.add(spline(p));
            case 102 -> {
                int n = p.integer(1);
                if (n < 1 || n > p.size() - 2) {
                    throw p.error("expected the count of its curves and as many pointers, found a count of " + n);
                }
                for (int k = 0; k < n; k++) {
                    IgesSections.Entry c = entry(p.pointer(2 + k), p, "curve " + (k + 1), 100, 102, 110, 126);
                    out.addAll(curve(c, depth + 1));
                }
                return mapped(out, matrix(e));
            }
            default -> throw p.error("is not a curve this reader knows (100, 102, 110 or 126)");
        }
        return mapped(out, matrix(e));
    }

    private static List<IgesCurve> mapped(List<IgesCurve> curves, IgesMatrix m) {
        return m.identity() ? curves : curves.stream().map(c -> c.mapped(m)).toList();
    }

    private static IgesCurve arc(IgesParams p) {
        p.require(8, "ZT X1 Y1 X2 Y2 X3 Y3");
        double z = p.real(1), cx = p.real(2), cy = p.real(3), sx = p.real(4) - cx, sy = p.real(5) - cy;
        double ex = p.real(6) - cx, ey = p.real(7) - cy;
        double r = Math.hypot(sx, sy);
        if (!(r > 0)) {
            throw p.error("an arc of radius 0 (its start point is its centre)");
        }
        double from = Math.atan2(sy, sx), to = Math.atan2(ey, ex);
        while (to <= from) {
            to += 2 * Math.PI; // counter-clockwise; the same start and end make a full circle
        }
        return IgesCurve.arc(new double[] {cx, cy, z}, new double[] {r, 0, 0}, new double[] {0, r, 0}, from, to);
    }

    private static IgesCurve spline(IgesParams p) {
        p.require(7, "K M PROP1 PROP2 PROP3 PROP4");
        int k = p.integer(1), m = p.integer(2);
        if (k < 1 || m < 1 || k < m - 1 || (long) k + 1 > 1_000_000) {
            throw p.error("expected 1 ≤ degree M ≤ K + 1 with K + 1 control points, found K " + k + ", M " + m);
        }
        boolean polynomial = p.integer(5) == 1;
        int knots = k + m + 2, count = k + 1, at = 7;
        p.require(at + knots + count * 4 + 2, "the knots, weights, points and parameter range");
        double[] t = p.reals(at, knots);
        double[] w = p.reals(at + knots, count);
        double[] pts = p.reals(at + knots + count, 3 * count);
        int end = at + knots + 4 * count;
        double t0 = p.real(end), t1 = p.real(end + 1);
        return new IgesCurve(m, t, pts, polynomial ? null : w, t0, t1);
    }

    /** Entity 128 (Piegl &amp; Tiller's rational B-spline surface as IGES 5.3 §4.24 lays it out). */
    IgesSurface bspline(IgesParams p) {
        p.require(10, "K1 K2 M1 M2 PROP1 … PROP5");
        int k1 = p.integer(1), k2 = p.integer(2), m1 = p.integer(3), m2 = p.integer(4);
        if (k1 < 1 || k2 < 1 || m1 < 1 || m2 < 1 || k1 < m1 - 1 || k2 < m2 - 1 || (long) (k1 + 1) * (k2 + 1) > 4_000_000) {
            throw p.error("expected degrees 1 ≤ M ≤ K + 1 with (K1 + 1)·(K2 + 1) control points, found K1 " + k1
                    + ", K2 " + k2 + ", M1 " + m1 + ", M2 " + m2);
        }
        boolean polynomial = p.integer(7) == 1;
        int nu = k1 + m1 + 2, nv = k2 + m2 + 2, count = (k1 + 1) * (k2 + 1), at = 10;
        p.require(at + nu + nv + 4 * count + 4, "the knots, weights, points and parameter range");
        double[] s = p.reals(at, nu), t = p.reals(at + nu, nv);
        double[] w = p.reals(at + nu + nv, count);
        double[] pts = p.reals(at + nu + nv + count, 3 * count);
        double[] range = p.reals(at + nu + nv + 4 * count, 4);
        clamp(range, 0, s[m1], s[nu - 1 - m1]);
        clamp(range, 2, t[m2], t[nv - 1 - m2]);
        return new IgesSurface(m1, m2, s, t, k1 + 1, k2 + 1, pts, polynomial ? null : w, range, true);
    }

    /** A parameter range that CAD tools round just outside the knot range, moved onto it. */
    private static void clamp(double[] range, int at, double start, double end) {
        double tol = 1e-9 * Math.max(1, Math.max(Math.abs(start), Math.abs(end)));
        if (range[at] < start && range[at] > start - tol) {
            range[at] = start;
        }
        if (range[at + 1] > end && range[at + 1] < end + tol) {
            range[at + 1] = end;
        }
    }

    /** The untrimmed surface entity {@code e} (128, 120, 122) in its own matrix's frame (not yet mapped). */
    IgesSurface surface(IgesSections.Entry e) {
        IgesParams p = file.params(e);
        return switch (e.type()) {
            case 128 -> bspline(p);
            case 122 -> {
                p.require(5, "DE LX LY LZ");
                IgesCurve c = single(entry(p.pointer(1), p, "the directrix", 100, 102, 110, 126));
                double[] start = c.end(false), l = p.reals(2, 3);
                yield IgesSurface.tabulated(c, new double[] {l[0] - start[0], l[1] - start[1], l[2] - start[2]});
            }
            case 120 -> {
                p.require(5, "L C SA TA");
                IgesSections.Entry axisEntry = entry(p.pointer(1), p, "the axis", 110);
                IgesParams axis = file.params(axisEntry);
                axis.require(7, "X1 Y1 Z1 X2 Y2 Z2");
                double[] ends = matrix(axisEntry).apply(new double[] {axis.real(1), axis.real(2), axis.real(3),
                        axis.real(4), axis.real(5), axis.real(6)});
                double[] d = {ends[3] - ends[0], ends[4] - ends[1], ends[5] - ends[2]};
                double len = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (!(len > 0)) {
                    throw p.error("its axis line has length 0");
                }
                double sa = p.real(3), ta = p.real(4);
                if (!(ta > sa) || ta - sa > 2 * Math.PI + 1e-9) {
                    throw p.error("expected start and end angles SA < TA ≤ SA + 2π, found " + sa + " and " + ta);
                }
                IgesCurve c = single(entry(p.pointer(2), p, "the generatrix", 100, 102, 110, 126));
                yield IgesSurface.revolution(c, ends, new double[] {d[0] / len, d[1] / len, d[2] / len}, sa,
                        Math.min(ta, sa + 2 * Math.PI));
            }
            default -> throw new Skip("entity " + e.type() + " as a base surface");
        };
    }

    private IgesCurve single(IgesSections.Entry e) {
        List<IgesCurve> pieces = curve(e, 0);
        if (pieces.size() != 1) {
            throw new Skip("a swept composite curve of " + pieces.size() + " pieces");
        }
        return pieces.get(0);
    }

    /**
     * The trim loop of a 142 (curve on a parametric surface): its parameter-space curve's pieces,
     * in order, gaps up to {@link #LOOP_GAP} of the range closed by straight pieces.
     */
    TrimLoop loopOf142(IgesSections.Entry e, IgesSurface base) {
        IgesParams p = file.params(e);
        p.require(6, "CRTN SPTR BPTR CPTR PREF");
        if (p.pointer(3) == 0 || (!base.trimmable() && p.pointer(4) != 0)) {
            return projectedLoop(p, base); // on a surface of revolution the model-space curve maps exactly, its angle's curve does not
        }
        if (!base.trimmable()) {
            throw new Skip("a trimmed surface of revolution without model-space trim curves (its angle has no exact"
                    + " rational parameter)");
        }
        IgesSections.Entry b = entry(p.pointer(3), p, "its parameter-space curve", 100, 102, 110, 126);
        List<TrimPiece> pieces = new ArrayList<>();
        for (IgesCurve c : curve(b, 0)) {
            pieces.add(c.toTrimPiece(false));
        }
        return loop(pieces, base, p);
    }

    /**
     * A 142 without a parameter-space curve: its model-space curve (CPTR) projected onto the base
     * surface, piece by piece ({@link EdgeProjection}). The curve is taken in the surface's frame,
     * so a base surface with its own transformation matrix is skipped.
     */
    private TrimLoop projectedLoop(IgesParams p, IgesSurface base) {
        if (p.pointer(4) == 0) {
            throw p.error("a curve on a surface with neither a parameter-space nor a model-space curve");
        }
        IgesSections.Entry surfaceEntry = entry(p.pointer(2), p, "its surface", 128, 120, 122, 108, 143, 144);
        if (!matrix(surfaceEntry).identity()) {
            throw new Skip("trimmed by model-space curves only, on a surface with its own transformation matrix");
        }
        IgesSections.Entry c = entry(p.pointer(4), p, "its model-space curve", 100, 102, 110, 126);
        EdgeProjection projection = EdgeProjection.onto(SplinePoint.of(base), base.range());
        List<TrimPiece> pieces = new ArrayList<>();
        double[] end = null;
        for (IgesCurve piece : curve(c, 0)) {
            TrimPiece t = projection.project(x -> EdgeProjection.point(piece, x), piece.t0(), piece.t1(), end);
            pieces.add(t);
            double[] ends = TrimLoop.ends(t);
            end = new double[] {ends[2], ends[3]};
        }
        // a projected loop that does not close went round a closed surface (a parallel of a whole turn): skipped
        return closedLoop(pieces, base.range(), detail -> new Skip("trimmed by model-space curves whose image does not"
                + " close in its parameters (" + detail + ")"));
    }

    /** A loop of {@code pieces}, small gaps closed by straight pieces; a large gap is an error. */
    TrimLoop loop(List<TrimPiece> pieces, IgesSurface base, IgesParams p) {
        return closedLoop(pieces, base.range(), p::error);
    }

    /**
     * A loop of {@code pieces} on a surface of parameter range {@code r}: gaps up to
     * {@link #LOOP_GAP} of the range closed by straight pieces; a larger gap is {@code gapError}
     * of its description.
     */
    static TrimLoop closedLoop(List<TrimPiece> pieces, double[] r, java.util.function.Function<String, RuntimeException> gapError) {
        double size = Math.max(r[1] - r[0], r[3] - r[2]);
        List<TrimPiece> closed = new ArrayList<>();
        for (int k = 0; k < pieces.size(); k++) {
            TrimPiece a = pieces.get(k), b = pieces.get((k + 1) % pieces.size());
            closed.add(a);
            double[] ea = TrimLoop.ends(a), eb = TrimLoop.ends(b);
            double gap = Math.hypot(eb[0] - ea[2], eb[1] - ea[3]);
            double scale = Math.max(1, Math.max(Math.abs(ea[2]), Math.abs(ea[3])));
            if (gap > TrimLoop.CLOSURE_TOLERANCE * scale) {
                if (!(gap <= LOOP_GAP * size)) {
                    throw gapError.apply("its trim loop has a gap of " + gap + " in (u, v) between curve " + (k + 1)
                            + " and curve " + ((k + 1) % pieces.size() + 1));
                }
                closed.add(IgesCurve.line(new double[] {ea[2], ea[3], 0}, new double[] {eb[0], eb[1], 0})
                        .toTrimPiece(false));
            }
        }
        return new TrimLoop(closed);
    }

    /** The trim region of a 144 on {@code base}: outer loop (or the whole range) and holes. */
    TrimRegion region144(IgesParams p, IgesSurface base) {
        p.require(5, "PTS N1 N2 PTO");
        int n1 = p.integer(2), n2 = p.integer(3);
        if (n2 < 0 || n2 > p.size() - 5) {
            throw p.error("expected N2 inner boundaries and as many pointers, found N2 = " + n2);
        }
        List<TrimLoop> outer = new ArrayList<>(), holes = new ArrayList<>();
        if (n1 != 0) {
            outer.add(loopOf142(entry(p.pointer(4), p, "the outer boundary", 142), base));
        }
        for (int k = 0; k < n2; k++) {
            holes.add(loopOf142(entry(p.pointer(5 + k), p, "inner boundary " + (k + 1), 142), base));
        }
        return outer.isEmpty() && holes.isEmpty() ? null : new TrimRegion(outer, holes);
    }

    /** The trim region of a 143 (bounded surface) on {@code base}: its first boundary outer, the rest holes. */
    TrimRegion region143(IgesParams p, IgesSurface base) {
        p.require(4, "TYPE SPTR N");
        if (p.integer(1) != 1) {
            throw new Skip("a bounded surface with model-space boundaries only");
        }
        if (!base.trimmable()) {
            throw new Skip("a trimmed surface of revolution (its angle has no exact rational parameter)");
        }
        int n = p.integer(3);
        List<TrimLoop> outer = new ArrayList<>(), holes = new ArrayList<>();
        for (int k = 0; k < n; k++) {
            IgesSections.Entry b = entry(p.pointer(4 + k), p, "boundary " + (k + 1), 141);
            IgesParams q = file.params(b);
            q.require(5, "TYPE PREF SPTR N");
            int curves = q.integer(4), at = 5;
            List<TrimPiece> pieces = new ArrayList<>();
            for (int c = 0; c < curves; c++) {
                boolean reversed = q.integer(at + 1) == 2;
                int count = q.integer(at + 2);
                if (count < 1) {
                    throw new Skip("a boundary curve without a parameter-space curve");
                }
                List<TrimPiece> own = new ArrayList<>();
                for (int s = 0; s < count; s++) {
                    IgesSections.Entry pc = entry(q.pointer(at + 3 + s), q, "parameter-space curve", 100, 102, 110, 126);
                    for (IgesCurve piece : curve(pc, 0)) {
                        own.add(piece.toTrimPiece(reversed));
                    }
                }
                if (reversed) {
                    java.util.Collections.reverse(own);
                }
                pieces.addAll(own);
                at += 3 + count;
            }
            (k == 0 ? outer : holes).add(loop(pieces, base, q));
        }
        return new TrimRegion(outer, holes);
    }
}
