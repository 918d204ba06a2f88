package org.beziertracer.model.io;

import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimPiece;

/**
 * The file's parameters {@code (u, v)} of a point on a STEP face's surface in closed form, and
 * the projection of a 3-D edge curve onto it ({@link EdgeProjection}) in those parameters: a
 * {@code PLANE} ({@code o + u·x + v·y}), the {@code CYLINDRICAL_}, {@code CONICAL_},
 * {@code SPHERICAL_} and {@code TOROIDAL_SURFACE} (u the angle about the axis, v the height or the
 * latitude) and a {@code SURFACE_OF_REVOLUTION} whose curve lies in a plane through its axis (u
 * the angle turned from the curve, v the curve's parameter at the point's distance from the axis
 * and height along it: closed-form for a line or a circle, the nearest of the curve's points by
 * sampling and golden-section search for a B-spline — Kiefer 1953, as in {@link StepTrims}).
 * Parametrisations: ISO 10303-42 §4.4.31–§4.4.36 and §4.4.42.
 *
 * <p>An angle (and a periodic v) is taken by whole turns nearest the previous sample, so a curve
 * round the axis has a continuous image; the projection samples in parameters scaled to lengths
 * (u by about the radius, v by about the surface's speed along v, each a power of two so the
 * scaling is exact), so its tolerance is one in model space. A
 * parallel or a meridian comes out as its exact iso-parameter line. Immutable.
 */
final class SurfaceInverse {

    private static final double TURN = 2 * Math.PI;

    private final StepSurface s;
    /** Revolution: the axis' origin and direction, the curve's radial direction {@code x̂} and {@code ŷ = d × x̂}. */
    private final double[] o, d, x, y;

    private SurfaceInverse(StepSurface s, double[] o, double[] d, double[] x, double[] y) {
        this.s = s;
        this.o = o;
        this.d = d;
        this.x = x;
        this.y = y;
    }

    /**
     * The inverse of {@code s}.
     *
     * @throws IgesEntities.Skip for a surface without one here (a B-spline, an extrusion, a
     *                           revolution of a curve outside a plane through its axis)
     */
    static SurfaceInverse of(StepSurface s) {
        switch (s.kind) {
            case PLANE, CYLINDER, CONE, SPHERE, TORUS -> {
                return new SurfaceInverse(s, null, null, null, null);
            }
            case REVOLUTION -> {
                return revolution(s);
            }
            default -> throw new IgesEntities.Skip("trimmed by model-space curves only on "
                    + (s.kind == StepSurface.Kind.EXTRUSION ? "an extrusion" : "a " + s.kind.name().toLowerCase(java.util.Locale.ROOT))
                    + " surface (projected onto B-spline, plane, analytic and revolution surfaces)");
        }
    }

    private static SurfaceInverse revolution(StepSurface s) {
        double[] f = s.frame, o = {f[0], f[1], f[2]}, d = {f[9], f[10], f[11]};
        StepGeometry.ParamCurve c = s.swept;
        double[][] pts;
        if (c.line()) {
            pts = new double[][] {c.p0(), add(c.p0(), c.d(), 1)};
        } else if (c.circle()) {
            pts = new double[][] {c.c(), add(c.c(), c.x(), 1), add(c.c(), c.y(), 1)};
        } else {
            double[] p = c.spline().points();
            pts = new double[p.length / 3][];
            for (int k = 0; k < pts.length; k++) {
                pts[k] = new double[] {p[3 * k], p[3 * k + 1], p[3 * k + 2]};
            }
        }
        double[] x = null;
        double best = 0, size = 0;
        for (double[] p : pts) {
            double[] r = radial(p, o, d);
            double len = norm(r);
            size = Math.max(size, norm(sub(p, o)));
            if (len > best) {
                best = len;
                x = new double[] {r[0] / len, r[1] / len, r[2] / len};
            }
        }
        if (x == null) {
            throw new IgesEntities.Skip("trimmed by model-space curves only on a surface of revolution whose curve lies on its axis");
        }
        double[] y = StepGeometry.cross(d, x);
        for (double[] p : pts) {
            if (!(Math.abs(dot(sub(p, o), y)) <= 1e-9 * Math.max(size, Double.MIN_NORMAL))) {
                throw new IgesEntities.Skip("trimmed by model-space curves only on a surface of revolution whose curve"
                        + " is not in a plane through its axis (no closed-form inverse)");
            }
        }
        return new SurfaceInverse(s, o, d, x, y);
    }

    /** The file's {@code (u, v)} of {@code p}; an angle (a periodic v) by whole turns nearest {@code ref}'s (null: u in (−π, π]). */
    double[] uv(double[] p, double[] ref) {
        double[] uv = s.kind == StepSurface.Kind.REVOLUTION ? revolutionUv(p, ref) : s.inverse(p);
        if (ref != null) {
            if (s.angleU()) {
                double[] f = s.frame;
                boolean onAxis = s.kind != StepSurface.Kind.PLANE && norm(radial(p, new double[] {f[0], f[1], f[2]},
                        new double[] {f[9], f[10], f[11]})) <= 1e-12 * Math.max(1, norm(p));
                uv[0] = onAxis ? ref[0] : StepTrims.nearest(uv[0], ref[0], TURN); // a pole keeps the previous angle
            }
            uv[1] = StepTrims.nearest(uv[1], ref[1], s.periodV());
        }
        return uv;
    }

    /** The point of the surface at the file's {@code (u, v)}. */
    double[] point(double u, double v) {
        double[] f = s.frame;
        if (s.kind == StepSurface.Kind.PLANE) {
            return new double[] {f[0] + u * f[3] + v * f[6], f[1] + u * f[4] + v * f[7], f[2] + u * f[5] + v * f[8]};
        }
        double rho, h;
        double[] ax = {f[3], f[4], f[5]}, ay = {f[6], f[7], f[8]}, az = {f[9], f[10], f[11]}, at = {f[0], f[1], f[2]};
        switch (s.kind) {
            case CYLINDER -> { rho = s.a; h = v; }
            case CONE -> { rho = s.a + v * Math.tan(s.b); h = v; }
            case SPHERE -> { rho = s.a * Math.cos(v); h = s.a * Math.sin(v); }
            case TORUS -> { rho = s.a + s.b * Math.cos(v); h = s.b * Math.sin(v); }
            default -> {
                double[] q = profileAt(v);
                rho = q[0];
                h = q[1];
                ax = x;
                ay = y;
                az = d;
                at = o;
            }
        }
        double cos = Math.cos(u), sin = Math.sin(u);
        double[] out = new double[3];
        for (int k = 0; k < 3; k++) {
            out[k] = at[k] + rho * (cos * ax[k] + sin * ay[k]) + h * az[k];
        }
        return out;
    }

    /**
     * The piece of {@code c} in the file's parameters, in loop order; {@code previous} is the
     * previous edge's ends in the loop (null for the first), whose end fixes the turn of the angle.
     *
     * @throws IgesEntities.Skip when the curve leaves the surface or its image jumps
     */
    TrimPiece project(EdgeCurve3 c, double[] previous) {
        // the curve's extent, and the surface's speeds along u and v where it runs: lengths per parameter
        double extent = 0, su = 0, sv = 0;
        double[] first = c.at(c.ta()), ref = previous == null ? null : new double[] {previous[2], previous[3]};
        for (int k = 0; k <= 16; k++) {
            double[] q = c.at(c.ta() + (c.tb() - c.ta()) * k / 16);
            extent = Math.max(extent, norm(sub(q, first)));
            double[] uv = uv(q, ref);
            double h = 1e-6;
            su = Math.max(su, norm(sub(point(uv[0] + h, uv[1]), point(uv[0] - h, uv[1]))) / (2 * h));
            sv = Math.max(sv, norm(sub(point(uv[0], uv[1] + h), point(uv[0], uv[1] - h))) / (2 * h));
        }
        double size = Math.max(extent, Math.max(su, sv));
        // powers of two, so scaling and unscaling give the parameters back to the bit
        double scaleU = powerOfTwo(Math.max(su, 1e-6 * size)), scaleV = powerOfTwo(Math.max(sv, 1e-6 * size));
        double[] from = ref;
        EdgeProjection projection = new EdgeProjection((p, guess) -> {
            double[] at = guess == null ? from : new double[] {guess[0] / scaleU, guess[1] / scaleV};
            double[] uv = uv(p, at);
            return new double[] {uv[0] * scaleU, uv[1] * scaleV, norm(sub(p, point(uv[0], uv[1])))};
        }, new double[] {0, Math.max(extent, 1e-6 * size), 0, 0}, size); // a point-like edge: no tolerance below rounding
        TrimPiece piece = projection.project(c::at, c.ta(), c.tb());
        double[] pts = piece.curve().points().clone();
        for (int k = 0; k < pts.length; k += 2) {
            pts[k] /= scaleU;
            pts[k + 1] /= scaleV;
        }
        TrimCurve t = piece.curve();
        return new TrimPiece(new TrimCurve(t.basis(), t.degree(), t.parm(), pts, t.weights()), piece.from(), piece.to());
    }

    private static double powerOfTwo(double x) {
        return x > 0 && Double.isFinite(x) ? Math.scalb(1.0, Math.getExponent(x)) : 1;
    }

    /** Revolution: the angle turned from the curve and the curve's parameter at {@code p}'s distance from the axis and height. */
    private double[] revolutionUv(double[] p, double[] ref) {
        double[] r = radial(p, o, d);
        double rho = norm(r), h = dot(sub(p, o), d);
        double u = Math.atan2(dot(r, y), dot(r, x));
        double[] a = profileParameter(rho, h, ref == null ? Double.NaN : ref[1]);
        double[] b = profileParameter(-rho, h, ref == null ? Double.NaN : ref[1]); // the curve's side across the axis
        return b[1] < a[1] ? new double[] {u + (u > 0 ? -Math.PI : Math.PI), b[0]} : new double[] {u, a[0]};
    }

    /** The curve's parameter nearest the point {@code (rho, h)} of its plane, and that distance; {@code near}: a periodic v's turn. */
    private double[] profileParameter(double rho, double h, double near) {
        StepGeometry.ParamCurve c = s.swept;
        double t;
        if (c.line()) {
            double[] p0 = planar(c.p0(), true), dir = planar(c.d(), false);
            t = ((rho - p0[0]) * dir[0] + (h - p0[1]) * dir[1]) / (dir[0] * dir[0] + dir[1] * dir[1]);
        } else if (c.circle()) {
            double[] cc = planar(c.c(), true), cx = planar(c.x(), false), cy = planar(c.y(), false);
            double dr = rho - cc[0], dh = h - cc[1];
            t = Math.atan2(dr * cy[0] + dh * cy[1], dr * cx[0] + dh * cx[1]);
            if (!Double.isNaN(near)) {
                t = StepTrims.nearest(t, near, TURN);
            }
        } else {
            IgesCurve sp = c.spline();
            t = StepTrims.minimum(q -> distance(profileAt(q), rho, h), sp.t0(), sp.t1(), 256, 100);
        }
        return new double[] {t, distance(profileAt(t), rho, h)};
    }

    /** The curve's point at {@code t} in its plane: signed distance from the axis along {@code x̂}, height along {@code d}. */
    private double[] profileAt(double t) {
        StepGeometry.ParamCurve c = s.swept;
        double[] p = c.spline() != null ? EdgeProjection.point(c.spline(), t) : c.at(t);
        return planar(p, true);
    }

    /** A point ({@code offset}) or a direction in the curve's plane coordinates {@code (along x̂, along d)}. */
    private double[] planar(double[] p, boolean offset) {
        double[] q = offset ? sub(p, o) : p;
        return new double[] {dot(q, x), dot(q, d)};
    }

    private static double distance(double[] a, double rho, double h) {
        return Math.hypot(a[0] - rho, a[1] - h);
    }

    private static double[] radial(double[] p, double[] o, double[] d) {
        double[] q = sub(p, o);
        double along = dot(q, d);
        return new double[] {q[0] - along * d[0], q[1] - along * d[1], q[2] - along * d[2]};
    }

    private static double[] add(double[] a, double[] b, double s) {
        return new double[] {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]};
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double norm(double[] a) {
        return Math.sqrt(dot(a, a));
    }
}
