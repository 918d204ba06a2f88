package org.beziertracer.model.io;

import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimPiece;

/**
 * Trim pieces of STEP faces in parameter space ({@link StepFaces}): lines and circles cut at the
 * parameters of their edge's vertices (on a periodic parameter, the period nearest the previous
 * edge's end), a line's end on a B-spline surface found by projecting its vertex, iso-parameter
 * pieces mapped onto the arcs of an angle ({@link StepSurface#angleParam}), and pieces with u and
 * v swapped for a reversed face. Stateless.
 *
 * <p>Projection: the line sampled inside the surface's range, the best sample refined by
 * golden-section search (Kiefer, "Sequential minimax search for a maximum", Proc. AMS 4, 1953).
 */
final class StepTrims {
    private StepTrims() {}

    /** {@code x} moved by whole periods to lie nearest {@code ref}. */
    static double nearest(double x, double ref, double period) {
        return period > 0 ? x + period * Math.rint((ref - x) / period) : x;
    }

    /** A line from loop-start parameters {@code a} to loop-end {@code b}, along the line when {@code forward}. */
    static TrimPiece linePiece(StepGeometry.ParamCurve c, double[] a, double[] b, boolean forward, StepSurface s,
                               double[] previous, boolean closed) {
        double[] p0 = c.p0(), d = c.d();
        int ax = Math.abs(d[0]) >= Math.abs(d[1]) ? 0 : 1;
        double period = ax == 0 ? s.periodU() : s.periodV();
        double ref = previous != null ? previous[2 + ax] : p0[ax];
        double start = nearest(a[ax], ref, period), end = nearest(b[ax], start, period);
        double ts = (start - p0[ax]) / d[ax], te = (end - p0[ax]) / d[ax];
        if (period > 0) {
            double per = period / Math.abs(d[ax]), tiny = 1e-9 * per;
            if (closed) {
                te = ts + (forward ? per : -per);
            }
            for (int k = 0; k < 3 && (forward ? te <= ts + tiny : te >= ts - tiny); k++) {
                te += forward ? per : -per; // at most a period away (more only when rounding swallows a period)
            }
        }
        if (forward ? !(te > ts) : !(te < ts)) {
            throw new IgesEntities.Skip("with a trim line whose vertices run against its direction");
        }
        IgesCurve curve = c.over(Math.min(ts, te), Math.max(ts, te));
        return curve.toTrimPiece(!forward);
    }

    /** A circle (on a plane) from loop-start parameters {@code a} to loop-end {@code b}. */
    static TrimPiece circlePiece(StepGeometry.ParamCurve c, double[] a, double[] b, boolean forward,
                                 boolean closed) {
        double[] from = forward ? a : b, to = forward ? b : a; // along the circle (counter-clockwise)
        double t0 = angle(c, from), t1 = closed ? t0 + 2 * Math.PI : angle(c, to);
        while (t1 <= t0 + 1e-12) {
            t1 += 2 * Math.PI;
        }
        return IgesCurve.arc(c.c(), c.x(), c.y(), t0, t1).toTrimPiece(!forward);
    }

    static double angle(StepGeometry.ParamCurve c, double[] uv) {
        double du = uv[0] - c.c()[0], dv = uv[1] - c.c()[1];
        return Math.atan2(du * c.y()[0] + dv * c.y()[1], du * c.x()[0] + dv * c.x()[1]);
    }

    /**
     * The parameter of the point of the line {@code c} (in a B-spline surface's parameters) whose
     * surface point is nearest {@code p}: the line inside the surface's range sampled, then the
     * best sample refined by golden-section search; an end within 1e-9 of the range's edge is put
     * on it. A vertex farther than 1e-6 of the surface's size from the line is a skip.
     */
    static double projected(StepGeometry.ParamCurve c, double[] p, IgesSurface s) {
        double[] r = s.range(), p0 = c.p0(), d = c.d();
        double lo = Double.NEGATIVE_INFINITY, hi = Double.POSITIVE_INFINITY;
        for (int a = 0; a < 2; a++) {
            double from = r[2 * a], to = r[2 * a + 1];
            if (d[a] != 0) {
                double t0 = (from - p0[a]) / d[a], t1 = (to - p0[a]) / d[a];
                lo = Math.max(lo, Math.min(t0, t1));
                hi = Math.min(hi, Math.max(t0, t1));
            } else if (p0[a] < from || p0[a] > to) {
                throw new IgesEntities.Skip("with a trim line outside its surface's parameter range");
            }
        }
        if (!(hi > lo)) {
            throw new IgesEntities.Skip("with a trim line outside its surface's parameter range");
        }
        SplinePoint at = SplinePoint.of(s);
        double t = minimum(x -> distance(at, c, x, p, r), lo, hi, 64, 80);
        double size = 0;
        double[] q = s.points();
        for (int k = 3; k < q.length; k++) {
            size = Math.max(size, Math.abs(q[k] - q[k % 3]));
        }
        if (!(distance(at, c, t, p, r) <= 1e-6 * Math.max(1, size))) {
            throw new IgesEntities.Skip("with a trim line whose vertex is not on its surface");
        }
        // an end that lands within rounding of the range's edge is put on it
        int ax = Math.abs(d[0]) >= Math.abs(d[1]) ? 0 : 1;
        double x = snap(p0[ax] + t * d[ax], r[2 * ax], r[2 * ax + 1]);
        return (x - p0[ax]) / d[ax];
    }

    /**
     * Where {@code f} is least on {@code [lo, hi]}: the best of {@code samples + 1} equal steps,
     * refined by golden-section search between its neighbours ({@code iterations} at most).
     */
    static double minimum(java.util.function.DoubleUnaryOperator f, double lo, double hi, int samples,
                          int iterations) {
        double best = lo, bestValue = Double.POSITIVE_INFINITY;
        for (int k = 0; k <= samples; k++) {
            double t = lo + (hi - lo) * k / samples, value = f.applyAsDouble(t);
            if (value < bestValue) {
                bestValue = value;
                best = t;
            }
        }
        double a = Math.max(lo, best - (hi - lo) / samples), b = Math.min(hi, best + (hi - lo) / samples);
        double g = (Math.sqrt(5) - 1) / 2;
        for (int k = 0; k < iterations && b - a > 1e-15 * Math.max(1, Math.abs(a)); k++) {
            double x1 = b - g * (b - a), x2 = a + g * (b - a);
            if (f.applyAsDouble(x1) <= f.applyAsDouble(x2)) {
                b = x2;
            } else {
                a = x1;
            }
        }
        return (a + b) / 2;
    }

    static double distance(SplinePoint at, StepGeometry.ParamCurve c, double t, double[] p, double[] r) {
        double[] uv = c.at(t);
        double[] q = at.at(Math.max(r[0], Math.min(r[1], uv[0])), Math.max(r[2], Math.min(r[3], uv[1])));
        return Math.sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
    }

    /** {@code x} put on {@code lo} or {@code hi} when within 1e-9 of the interval's length of it. */
    static double snap(double x, double lo, double hi) {
        double tol = 1e-9 * (hi - lo);
        return Math.abs(x - lo) <= tol ? lo : Math.abs(x - hi) <= tol ? hi : x;
    }

    /** An iso-parameter trim piece mapped into the B-spline's parameters (exact as a set of points). */
    static TrimPiece mapped(TrimPiece p, StepSurface s, double[] box) {
        TrimCurve c = p.curve();
        double[] pts = c.points();
        boolean uConst = true, vConst = true;
        for (int k = 2; k < pts.length; k += 2) {
            uConst &= pts[k] == pts[0];
            vConst &= pts[k + 1] == pts[1];
        }
        boolean full = Math.min(p.from(), p.to()) == c.start() && Math.max(p.from(), p.to()) == c.end();
        boolean ok = full && ((uConst && (!s.angleV() || monotone(pts, 1))) || (vConst && (!s.angleU() || monotone(pts, 0))));
        if (!ok) {
            throw new IgesEntities.Skip("on a " + s.kind.name().toLowerCase(java.util.Locale.ROOT)
                    + " trimmed across an angle by a curve that is not an iso-parameter line (no exact rational map)");
        }
        double[] out = new double[pts.length];
        for (int k = 0; k < pts.length; k += 2) {
            // vertices found by inversion land within rounding of the box's edges: put them on them
            out[k] = s.mapU(snap(pts[k], box[0], box[1]), box[0], box[1]);
            out[k + 1] = s.mapV(snap(pts[k + 1], box[2], box[3]), box[2], box[3]);
        }
        return new TrimPiece(new TrimCurve(c.basis(), c.degree(), c.parm(), out, c.weights()), p.from(), p.to());
    }

    /**
     * A projected polyline (degree 1) mapped into the B-spline's parameters vertex by vertex: each
     * vertex exactly (angles by {@link StepSurface#angleParam}), the segments between them within
     * the projection's tolerance; an iso-parameter line is mapped exactly as a set.
     */
    static TrimPiece mappedPoints(TrimPiece p, StepSurface s, double[] box) {
        TrimCurve c = p.curve();
        if (c.degree() != 1) {
            return mapped(p, s, box);
        }
        double[] pts = c.points(), out = new double[pts.length];
        for (int k = 0; k < pts.length; k += 2) {
            out[k] = s.mapU(snap(pts[k], box[0], box[1]), box[0], box[1]);
            out[k + 1] = s.mapV(snap(pts[k + 1], box[2], box[3]), box[2], box[3]);
        }
        return new TrimPiece(new TrimCurve(c.basis(), c.degree(), c.parm(), out, c.weights()), p.from(), p.to());
    }

    /** {@code p} moved by {@code (du, dv)} in the parameters. */
    static TrimPiece moved(TrimPiece p, double du, double dv) {
        TrimCurve c = p.curve();
        double[] pts = c.points().clone();
        for (int k = 0; k < pts.length; k += 2) {
            pts[k] += du;
            pts[k + 1] += dv;
        }
        return new TrimPiece(new TrimCurve(c.basis(), c.degree(), c.parm(), pts, c.weights()), p.from(), p.to());
    }

    static boolean monotone(double[] pts, int axis) {
        boolean up = true, down = true;
        for (int k = 2 + axis; k < pts.length; k += 2) {
            up &= pts[k] >= pts[k - 2];
            down &= pts[k] <= pts[k - 2];
        }
        return up || down;
    }

    static TrimPiece swapped(TrimPiece p) {
        TrimCurve c = p.curve();
        double[] pts = c.points();
        for (int k = 0; k < pts.length; k += 2) {
            double u = pts[k];
            pts[k] = pts[k + 1];
            pts[k + 1] = u;
        }
        return new TrimPiece(new TrimCurve(c.basis(), c.degree(), c.parm(), pts, c.weights()), p.from(), p.to());
    }
}
