package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * One STEP face ({@code ADVANCED_FACE} or {@code FACE_SURFACE}) as an exact rational B-spline
 * surface trimmed in its parameters: the bounds ({@code FACE_OUTER_BOUND} outer,
 * {@code FACE_BOUND} holes) are {@code EDGE_LOOP}s of {@code ORIENTED_EDGE}s whose
 * {@code EDGE_CURVE} carries a {@code PCURVE} on the face's surface (directly, or in a
 * {@code SURFACE_CURVE} / {@code SEAM_CURVE}), whose {@code DEFINITIONAL_REPRESENTATION} holds
 * the parameter-space curve. An edge runs along its curve when its orientation agrees with the
 * edge curve's {@code same_sense}. Lines and circles get their ends from the edge's vertices,
 * mapped into the surface's parameters (planes and the analytic surfaces, whose inverse is
 * closed-form); on a periodic parameter the line is followed from the previous edge's end. A
 * face whose surface is reversed ({@code same_sense .F.}) is transposed (u and v swapped), which
 * turns its normal exactly.
 *
 * <p>An edge without a parameter-space curve on the face's surface has its 3-D curve projected
 * onto the surface ({@link EdgeProjection}, {@link EdgeCurve3}): by point inversion on a B-spline
 * surface, in closed form on a plane, an analytic surface or a surface of revolution
 * ({@link SurfaceInverse}); a projected polyline is mapped into the B-spline's parameters point
 * by point, a parallel or meridian (an iso-parameter line) exactly.
 *
 * <p>A face is skipped ({@link IgesEntities.Skip}, with the reason) when an edge has no
 * parameter-space curve on an extrusion (or a revolution of a curve outside a plane through its
 * axis), when a line or
 * circle trim lies on a surface without a closed-form inverse, when a trim across an angle
 * parameter is not an iso-parameter line (the angle has no exact rational map), or when a loop
 * does not close in the parameters. A B-spline face bounded by exactly one outer loop of four
 * lines along its parameter directions is that rectangle as its parameter range, untrimmed (the
 * form {@link StepWriter} gives a surface's range).
 *
 * <p>Reference: ISO 10303-42 (topology §5.4: face, loop, oriented edge; §4.4.51 pcurve).
 */
final class StepFaces {

    /**
     * A trim piece in the file's parameters, whether it came from a {@code LINE}, and whether it
     * is a projected 3-D curve (a polyline, or an exact iso-parameter line).
     */
    private record Raw(TrimPiece piece, boolean line, boolean projected) {
        Raw(TrimPiece piece, boolean line) {
            this(piece, line, false);
        }
    }

    private final StepGeometry g;
    private final double angleUnit;

    StepFaces(StepGeometry g, double angleUnit) {
        this.g = g;
        this.angleUnit = angleUnit;
    }

    /** The face's surface and trims, in the file's space (not yet placed). */
    IgesSurface.Trimmed face(StepFile.Entity face) {
        String type = face.is("ADVANCED_FACE") ? "ADVANCED_FACE" : "FACE_SURFACE";
        StepArgs a = g.args(face, type).require(4, "name, bounds, face_geometry, same_sense");
        StepFile.Entity surfaceEntity = a.ref(2, "face_geometry");
        StepSurface s = StepSurface.of(g, surfaceEntity, angleUnit);
        boolean sameSense = a.bool(3, "same_sense", true);
        List<List<Raw>> outer = new ArrayList<>(), holes = new ArrayList<>();
        for (Object b : a.list(1, "bounds")) {
            StepFile.Entity bound = a.target(b, "a bound", "FACE_OUTER_BOUND", "FACE_BOUND");
            StepArgs ba = g.args(bound, bound.is("FACE_OUTER_BOUND") ? "FACE_OUTER_BOUND" : "FACE_BOUND")
                    .require(3, "name, bound, orientation");
            StepFile.Entity loop = ba.ref(1, "bound");
            if (loop.is("VERTEX_LOOP")) {
                continue; // a loop of one vertex (a cone's apex) bounds no area
            }
            if (!loop.is("EDGE_LOOP")) {
                throw new IgesEntities.Skip("bounded by a " + StepGeometry.kind(loop));
            }
            (bound.is("FACE_OUTER_BOUND") ? outer : holes).add(edges(loop, s, surfaceEntity.id()));
        }
        if (outer.isEmpty() && !holes.isEmpty()) {
            pickOuter(outer, holes);
        }
        alignTurns(outer, holes, s);
        double[] box;
        IgesSurface surface;
        if (s.kind == StepSurface.Kind.BSPLINE) {
            surface = s.spline;
            double[] rect = outer.size() == 1 ? rectangle(outer.get(0), surface.range()) : null;
            if (rect != null) {
                outer.clear();
                surface = new IgesSurface(surface.degreeU(), surface.degreeV(), surface.knotsU(), surface.knotsV(),
                        surface.countU(), surface.countV(), surface.points(), surface.weights(), rect, true);
            }
            box = surface.range();
        } else {
            if (outer.isEmpty() && holes.isEmpty()) {
                throw new IgesEntities.Skip("without bounds on a " + s.kind.name().toLowerCase(java.util.Locale.ROOT));
            }
            box = box(outer, holes);
            if (!(box[1] > box[0] && box[3] > box[2])) {
                throw new IgesEntities.Skip("whose trims enclose no area");
            }
            if ((s.angleU() && !(box[1] - box[0] <= 2 * Math.PI * (1 + 1e-9)))
                    || (s.angleV() && !(box[3] - box[2] <= 2 * Math.PI * (1 + 1e-9)))) {
                throw new IgesEntities.Skip("going round an angle more than once");
            }
            if (s.kind == StepSurface.Kind.EXTRUSION && s.swept.circle() || s.kind == StepSurface.Kind.REVOLUTION
                    && s.swept.circle()) {
                double span = s.kind == StepSurface.Kind.EXTRUSION ? box[1] - box[0] : box[3] - box[2];
                if (!(span <= 2 * Math.PI * (1 + 1e-9))) {
                    throw new IgesEntities.Skip("going round an angle more than once");
                }
            }
            surface = s.over(box[0], box[1], box[2], box[3]);
        }
        List<TrimLoop> outerLoops = new ArrayList<>(), holeLoops = new ArrayList<>();
        for (List<Raw> loop : outer) {
            outerLoops.add(loop(loop, s, box, surface.range(), sameSense));
        }
        for (List<Raw> loop : holes) {
            holeLoops.add(loop(loop, s, box, surface.range(), sameSense));
        }
        TrimRegion trim = outerLoops.isEmpty() && holeLoops.isEmpty() ? null : new TrimRegion(outerLoops, holeLoops);
        return new IgesSurface.Trimmed(sameSense ? surface : transposed(surface), trim);
    }

    /**
     * Loops with projected pieces moved by whole turns of a periodic parameter to lie nearest the
     * first outer loop: a projected loop's first angle is taken in (−π, π], so a hole at 250° of a
     * face that runs from 0° to 360° would otherwise sit at −110°, outside the face's box. Exact:
     * the surface repeats by the period.
     */
    private static void alignTurns(List<List<Raw>> outer, List<List<Raw>> holes, StepSurface s) {
        double pu = s.periodU(), pv = s.periodV();
        if (outer.isEmpty() || (pu == 0 && pv == 0)) {
            return;
        }
        double[] ref = box(List.of(outer.get(0)), List.of());
        for (List<List<Raw>> loops : List.of(outer, holes)) {
            for (int k = loops == outer ? 1 : 0; k < loops.size(); k++) {
                List<Raw> loop = loops.get(k);
                if (loop.stream().noneMatch(Raw::projected)) {
                    continue;
                }
                double[] b = box(List.of(loop), List.of());
                double du = turns(ref[0] + ref[1], b[0] + b[1], pu), dv = turns(ref[2] + ref[3], b[2] + b[3], pv);
                if (du != 0 || dv != 0) {
                    loops.set(k, loop.stream().map(r -> new Raw(StepTrims.moved(r.piece(), du, dv), r.line(), r.projected()))
                            .toList());
                }
            }
        }
    }

    /** The whole periods that move the middle {@code twiceMid / 2} nearest {@code twiceRef / 2} (0 when not periodic). */
    private static double turns(double twiceRef, double twiceMid, double period) {
        return period > 0 ? period * Math.rint((twiceRef - twiceMid) / (2 * period)) : 0;
    }

    /** Without an outer bound: the loop whose box holds every other is outer; else all are. */
    private static void pickOuter(List<List<Raw>> outer, List<List<Raw>> holes) {
        for (int k = 0; k < holes.size(); k++) {
            double[] b = box(List.of(holes.get(k)), List.of());
            boolean holdsAll = true;
            for (int j = 0; j < holes.size() && holdsAll; j++) {
                double[] o = box(List.of(holes.get(j)), List.of());
                holdsAll = j == k || (o[0] >= b[0] && o[1] <= b[1] && o[2] >= b[2] && o[3] <= b[3]);
            }
            if (holdsAll) {
                outer.add(holes.remove(k));
                return;
            }
        }
        outer.addAll(holes);
        holes.clear();
    }

    /** The box of the loops' control points (which holds the curves) in the file's parameters. */
    private static double[] box(List<List<Raw>> a, List<List<Raw>> b) {
        double[] box = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY};
        for (List<List<Raw>> loops : List.of(a, b)) {
            for (List<Raw> loop : loops) {
                for (Raw r : loop) {
                    double[] p = r.piece().curve().points();
                    for (int k = 0; k < p.length; k += 2) {
                        box[0] = Math.min(box[0], p[k]);
                        box[1] = Math.max(box[1], p[k]);
                        box[2] = Math.min(box[2], p[k + 1]);
                        box[3] = Math.max(box[3], p[k + 1]);
                    }
                }
            }
        }
        return box;
    }

    /** The rectangle of four lines along the parameter directions inside {@code knotRange}, or null. */
    private static double[] rectangle(List<Raw> loop, double[] knotRange) {
        if (loop.size() != 4) {
            return null;
        }
        for (Raw r : loop) {
            double[] e = TrimLoop.ends(r.piece());
            if (!r.line() || (e[0] != e[2] && e[1] != e[3])) {
                return null;
            }
        }
        double[] box = box(List.of(loop), List.of());
        for (Raw r : loop) {
            double[] e = TrimLoop.ends(r.piece());
            for (int k = 0; k < 4; k += 2) {
                boolean onU = e[k] == box[0] || e[k] == box[1], onV = e[k + 1] == box[2] || e[k + 1] == box[3];
                if (!onU || !onV) {
                    return null;
                }
            }
        }
        boolean inside = box[0] < box[1] && box[2] < box[3] && box[0] >= knotRange[0] && box[1] <= knotRange[1]
                && box[2] >= knotRange[2] && box[3] <= knotRange[3];
        return inside ? box : null;
    }

    /** The pieces of an EDGE_LOOP in the file's parameters, in loop order. */
    private List<Raw> edges(StepFile.Entity loop, StepSurface s, int surfaceId) {
        StepArgs la = g.args(loop, "EDGE_LOOP").require(2, "name, edge_list");
        List<Raw> out = new ArrayList<>();
        double[] previous = null;
        for (Object o : la.list(1, "edge_list")) {
            StepFile.Entity oe = la.target(o, "an edge", "ORIENTED_EDGE");
            StepArgs oa = g.args(oe, "ORIENTED_EDGE").require(5, "name, edge_start, edge_end, edge_element, orientation");
            StepFile.Entity ec = oa.ref(3, "edge_element", "EDGE_CURVE");
            StepArgs ea = g.args(ec, "EDGE_CURVE").require(5, "name, edge_start, edge_end, edge_geometry, same_sense");
            boolean sameSense = ea.bool(4, "same_sense", true);
            boolean forward = oa.bool(4, "orientation", true) == sameSense;
            boolean loopStartIsEdgeStart = oa.bool(4, "orientation", true);
            StepFile.Entity geometry = ea.ref(3, "edge_geometry");
            List<StepFile.Entity> pcurves = pcurves(geometry, surfaceId);
            if (pcurves.isEmpty()) {
                Raw r = new Raw(projected(geometry, ea, loopStartIsEdgeStart, forward, s, previous), false, true);
                out.add(r);
                previous = TrimLoop.ends(r.piece());
                continue;
            }
            Raw best = null;
            double bestGap = Double.POSITIVE_INFINITY;
            for (StepFile.Entity pc : pcurves) {
                Raw r = piece(pc, ea, loopStartIsEdgeStart, forward, s, previous);
                double gap = previous == null ? 0 : gap(previous, TrimLoop.ends(r.piece()));
                if (best == null || gap < bestGap) {
                    best = r;
                    bestGap = gap;
                }
            }
            out.add(best);
            previous = TrimLoop.ends(best.piece());
        }
        if (out.isEmpty()) {
            throw new IgesEntities.Skip("with an empty edge loop");
        }
        return out;
    }

    private static double gap(double[] previousEnds, double[] ends) {
        return Math.hypot(ends[0] - previousEnds[2], ends[1] - previousEnds[3]);
    }

    /** The PCURVEs on surface {@code surfaceId} an edge geometry carries. */
    private List<StepFile.Entity> pcurves(StepFile.Entity geometry, int surfaceId) {
        List<StepFile.Entity> out = new ArrayList<>();
        if (geometry.is("PCURVE")) {
            addIfOn(geometry, surfaceId, out);
        } else if (geometry.is("SURFACE_CURVE") || geometry.is("SEAM_CURVE") || geometry.is("BOUNDED_SURFACE_CURVE")
                || geometry.is("INTERSECTION_CURVE")) {
            StepArgs sa = StepArgs.of(g.file, geometry, geometry.parts().get(0).type())
                    .require(3, "name, curve_3d, associated_geometry");
            for (Object o : sa.list(2, "associated_geometry")) {
                StepFile.Entity pc = sa.target(o, "associated_geometry");
                if (pc.is("PCURVE")) {
                    addIfOn(pc, surfaceId, out);
                }
            }
        }
        return out;
    }

    /**
     * An edge without a pcurve on the face's surface: its 3-D curve (the edge geometry, or a
     * surface curve's {@code curve_3d}) between its vertices, projected onto the surface
     * ({@link EdgeProjection}) from the loop's start vertex to its end vertex.
     */
    private TrimPiece projected(StepFile.Entity geometry, StepArgs edge, boolean loopStartIsEdgeStart, boolean forward,
                                StepSurface s, double[] previous) {
        SurfaceInverse inverse = s.kind == StepSurface.Kind.BSPLINE ? null : SurfaceInverse.of(s);
        StepFile.Entity curveEntity = geometry;
        if (!geometry.is("LINE") && !geometry.is("CIRCLE") && !geometry.is("B_SPLINE_CURVE_WITH_KNOTS")
                && !geometry.is("TRIMMED_CURVE")) {
            StepArgs sa = StepArgs.of(g.file, geometry, geometry.parts().get(0).type()).require(2, "name, curve_3d");
            curveEntity = sa.ref(1, "curve_3d");
        }
        StepFile.Entity v0 = edge.ref(1, "edge_start", "VERTEX_POINT"), v1 = edge.ref(2, "edge_end", "VERTEX_POINT");
        double[] start = vertex(loopStartIsEdgeStart ? v0 : v1), end = vertex(loopStartIsEdgeStart ? v1 : v0);
        EdgeCurve3 c = EdgeCurve3.of(g, curveEntity, angleUnit, start, end, v0.id() == v1.id(), forward);
        if (inverse != null) {
            return inverse.project(c, previous); // closed-form parameters: planes, analytic surfaces, revolutions
        }
        return EdgeProjection.onto(SplinePoint.of(s.spline), s.spline.range()).project(c::at, c.ta(), c.tb());
    }

    private void addIfOn(StepFile.Entity pcurve, int surfaceId, List<StepFile.Entity> out) {
        StepArgs pa = g.args(pcurve, "PCURVE").require(3, "name, basis_surface, reference_to_curve");
        Object s = pa.raw(1);
        if (s instanceof StepFile.Ref r && r.id() == surfaceId) {
            out.add(pcurve);
        }
    }

    /** One edge's piece in loop order; {@code previous} is the previous piece's ends (null for the first). */
    private Raw piece(StepFile.Entity pcurve, StepArgs edge, boolean loopStartIsEdgeStart, boolean forward,
                      StepSurface s, double[] previous) {
        StepArgs pa = g.args(pcurve, "PCURVE");
        StepFile.Entity rep = pa.ref(2, "reference_to_curve", "DEFINITIONAL_REPRESENTATION");
        StepArgs ra = g.args(rep, "DEFINITIONAL_REPRESENTATION").require(2, "name, items");
        List<?> items = ra.list(1, "items");
        if (items.isEmpty()) {
            throw ra.error("a definitional representation without a curve");
        }
        StepFile.Entity curve = ra.target(items.get(0), "items");
        if (curve.is("TRIMMED_CURVE")) {
            return trimmed(curve, forward);
        }
        StepGeometry.ParamCurve c = g.curve(curve);
        if (c.spline() != null) {
            IgesCurve sp = c.spline();
            return new Raw(sp.toTrimPiece(!forward), false);
        }
        StepFile.Entity v0 = edge.ref(1, "edge_start", "VERTEX_POINT"), v1 = edge.ref(2, "edge_end", "VERTEX_POINT");
        boolean closed = v0.id() == v1.id();
        if (s.kind == StepSurface.Kind.BSPLINE && c.line() && !closed) {
            double ta = StepTrims.projected(c, vertex(loopStartIsEdgeStart ? v0 : v1), s.spline);
            double tb = StepTrims.projected(c, vertex(loopStartIsEdgeStart ? v1 : v0), s.spline);
            if (forward ? !(tb > ta) : !(tb < ta)) {
                throw new IgesEntities.Skip("with a trim line whose vertices run against its direction");
            }
            return new Raw(c.over(Math.min(ta, tb), Math.max(ta, tb)).toTrimPiece(!forward), true);
        }
        if (!s.invertible()) {
            throw new IgesEntities.Skip("with a " + (c.line() ? "closed LINE" : "CIRCLE") + " trim curve on a "
                    + s.kind.name().toLowerCase(java.util.Locale.ROOT) + " surface (its ends need a projection, a later step)");
        }
        double[] a = s.inverse(vertex(loopStartIsEdgeStart ? v0 : v1)), b = s.inverse(vertex(loopStartIsEdgeStart ? v1 : v0));
        if (c.line()) {
            return new Raw(StepTrims.linePiece(c, a, b, forward, s, previous, closed), true);
        }
        return new Raw(StepTrims.circlePiece(c, a, b, forward, closed), false);
    }

    private double[] vertex(StepFile.Entity v) {
        StepArgs va = g.args(v, "VERTEX_POINT").require(2, "name, vertex_geometry");
        return g.point(va.ref(1, "vertex_geometry", "CARTESIAN_POINT"));
    }

    /** A TRIMMED_CURVE by parameter values (B-spline, line or circle basis). */
    private Raw trimmed(StepFile.Entity e, boolean forward) {
        StepArgs ta = g.args(e, "TRIMMED_CURVE").require(5, "name, basis_curve, trim_1, trim_2, sense_agreement");
        StepGeometry.ParamCurve c = g.curve(ta.ref(1, "basis_curve"));
        double t1 = parameterValue(ta, 2, "trim_1"), t2 = parameterValue(ta, 3, "trim_2");
        boolean sense = ta.bool(4, "sense_agreement", true);
        if (c.circle()) {
            t1 *= angleUnit;
            t2 *= angleUnit;
        }
        if (sense ? !(t2 > t1) : !(t2 < t1)) {
            throw new IgesEntities.Skip("with a trimmed curve across its basis curve's period");
        }
        double lo = Math.min(t1, t2), hi = Math.max(t1, t2);
        if (c.circle() && !(hi - lo <= 2 * Math.PI * (1 + 1e-9))) {
            throw new IgesEntities.Skip("with a trimmed circle going round more than once");
        }
        IgesCurve curve = c.over(lo, hi);
        double from = c.circle() ? curve.t0() : lo, to = c.circle() ? curve.t1() : hi;
        if (c.spline() != null && (lo < curve.t0() || hi > curve.t1())) {
            throw ta.error("trims " + t1 + " and " + t2 + " outside the basis curve's range [" + curve.t0() + ", "
                    + curve.t1() + "]");
        }
        boolean alongBasis = sense == forward;
        TrimPiece p = alongBasis ? new TrimPiece(curve.toTrimPiece(false).curve(), from, to)
                : new TrimPiece(curve.toTrimPiece(false).curve(), to, from);
        return new Raw(p, c.line());
    }

    private static double parameterValue(StepArgs a, int k, String name) {
        for (Object o : a.list(k, name)) {
            if (o instanceof StepFile.Typed t && t.type().equals("PARAMETER_VALUE")) {
                return a.real(t.value(), name);
            }
        }
        throw new IgesEntities.Skip("with a trimmed curve trimmed by points only");
    }

    /** A loop in the B-spline's parameters: pieces mapped (angles by {@link StepSurface#angleParam}), gaps closed. */
    private static TrimLoop loop(List<Raw> raw, StepSurface s, double[] box, double[] range, boolean sameSense) {
        List<TrimPiece> pieces = new ArrayList<>();
        for (Raw r : raw) {
            TrimPiece p = r.piece();
            if (s.angleU() || s.angleV()) {
                p = r.projected() ? StepTrims.mappedPoints(p, s, box) : StepTrims.mapped(p, s, box);
            }
            pieces.add(sameSense ? p : StepTrims.swapped(p));
        }
        double[] rr = sameSense ? range : new double[] {range[2], range[3], range[0], range[1]};
        return IgesEntities.closedLoop(pieces, rr, detail -> new IgesEntities.Skip("whose loop does not close: "
                + detail));
    }

    /** The surface with u and v swapped: the same points, the normal turned. */
    static IgesSurface transposed(IgesSurface s) {
        int nu = s.countU(), nv = s.countV();
        double[] p = s.points(), pts = new double[p.length], w = s.weights() == null ? null : new double[nu * nv];
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                System.arraycopy(p, 3 * (j * nu + i), pts, 3 * (i * nv + j), 3);
                if (w != null) {
                    w[i * nv + j] = s.weights()[j * nu + i];
                }
            }
        }
        double[] r = s.range();
        return new IgesSurface(s.degreeV(), s.degreeU(), s.knotsV(), s.knotsU(), nv, nu, pts, w,
                new double[] {r[2], r[3], r[0], r[1]}, s.trimmable());
    }
}
