package org.beziertracer.model.io;

import java.util.List;

import org.beziertracer.model.BezierPatch;

/**
 * The geometry entities of a STEP file (ISO 10303-42 as AP203/AP214/AP242 use it) as exact
 * rational B-splines: points, directions and axis placements; curves ({@code LINE},
 * {@code CIRCLE}, {@code B_SPLINE_CURVE_WITH_KNOTS} and its rational complex form,
 * {@code TRIMMED_CURVE}) in 2-D (a pcurve's parameter space, {@code z = 0}) or 3-D; B-spline
 * surfaces ({@code B_SPLINE_SURFACE_WITH_KNOTS} and the complex form with
 * {@code RATIONAL_B_SPLINE_SURFACE}). Stateless apart from the file it reads.
 *
 * <p>Knots with multiplicities expand to the full knot vector (ISO 10303-42 §4.3.4); circles
 * follow Piegl &amp; Tiller, <i>The NURBS Book</i> (1997), §7.5, through {@link IgesCurve#arc}.
 */
final class StepGeometry {

    /** A curve with its parameter: a B-spline (bounded), a line {@code p0 + t·d} or a circle {@code c + cos t·x + sin t·y}. */
    record ParamCurve(IgesCurve spline, double[] p0, double[] d, double[] c, double[] x, double[] y) {

        boolean line() { return p0 != null; }

        boolean circle() { return c != null; }

        double[] at(double t) {
            if (line()) {
                return new double[] {p0[0] + t * d[0], p0[1] + t * d[1], p0[2] + t * d[2]};
            }
            double cos = Math.cos(t), sin = Math.sin(t);
            return new double[] {c[0] + cos * x[0] + sin * y[0], c[1] + cos * x[1] + sin * y[1],
                    c[2] + cos * x[2] + sin * y[2]};
        }

        /** The part {@code [t0, t1]} as an exact B-spline (a circle's parameter becomes its arcs' {@code [0, arcs]}). */
        IgesCurve over(double t0, double t1) {
            if (spline != null) {
                return spline;
            }
            if (line()) {
                double[] a = at(t0), b = at(t1);
                return new IgesCurve(1, new double[] {t0, t0, t1, t1}, new double[] {a[0], a[1], a[2], b[0], b[1], b[2]},
                        null, t0, t1);
            }
            return IgesCurve.arc(c, x, y, t0, t1);
        }
    }

    final StepFile file;

    StepGeometry(StepFile file) {
        this.file = file;
    }

    StepArgs args(StepFile.Entity e, String type) {
        return StepArgs.of(file, e, type);
    }

    /** A CARTESIAN_POINT's 2 or 3 coordinates, as {@code x y z} ({@code z = 0} in 2-D). */
    double[] point(StepFile.Entity e) {
        StepArgs a = args(e, "CARTESIAN_POINT").require(2, "name, coordinates");
        double[] xyz = a.reals(a.raw(1), "coordinates");
        if (xyz.length < 1 || xyz.length > 3) {
            throw a.error("expected 1 to 3 coordinates, found " + xyz.length);
        }
        return new double[] {xyz[0], xyz.length > 1 ? xyz[1] : 0, xyz.length > 2 ? xyz[2] : 0};
    }

    /** A DIRECTION, normalised; a zero direction is an error. */
    double[] direction(StepFile.Entity e) {
        StepArgs a = args(e, "DIRECTION").require(2, "name, direction_ratios");
        double[] r = a.reals(a.raw(1), "direction_ratios");
        if (r.length < 2 || r.length > 3) {
            throw a.error("expected 2 or 3 direction ratios, found " + r.length);
        }
        double[] d = {r[0], r[1], r.length > 2 ? r[2] : 0};
        double len = Math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (!(len > 0) || !Double.isFinite(len)) {
            throw a.error("a direction of length " + len);
        }
        return new double[] {d[0] / len, d[1] / len, d[2] / len};
    }

    /** A VECTOR: its direction times its magnitude. */
    double[] vector(StepFile.Entity e) {
        StepArgs a = args(e, "VECTOR").require(3, "name, orientation, magnitude");
        double[] d = direction(a.ref(1, "orientation", "DIRECTION"));
        double m = a.real(2, "magnitude");
        return new double[] {d[0] * m, d[1] * m, d[2] * m};
    }

    /**
     * An AXIS2_PLACEMENT_3D (or _2D, in its plane) as its frame {@code origin, x, y, z} (12
     * numbers): z the axis, x the reference direction made perpendicular to it (ISO 10303-42
     * §4.4.19 build_axes; defaults (0, 0, 1) and (1, 0, 0)).
     */
    double[] placement(StepFile.Entity e) {
        if (e.is("AXIS2_PLACEMENT_2D")) {
            StepArgs a = args(e, "AXIS2_PLACEMENT_2D").require(3, "name, location, ref_direction");
            double[] o = point(a.ref(1, "location", "CARTESIAN_POINT"));
            double[] x = a.raw(2) == StepFile.UNSET ? new double[] {1, 0, 0}
                    : direction(a.ref(2, "ref_direction", "DIRECTION"));
            return new double[] {o[0], o[1], 0, x[0], x[1], 0, -x[1], x[0], 0, 0, 0, 1};
        }
        StepArgs a = args(e, "AXIS2_PLACEMENT_3D").require(4, "name, location, axis, ref_direction");
        double[] o = point(a.ref(1, "location", "CARTESIAN_POINT"));
        double[] z = a.raw(2) == StepFile.UNSET ? new double[] {0, 0, 1} : direction(a.ref(2, "axis", "DIRECTION"));
        double[] r = a.raw(3) == StepFile.UNSET ? null : direction(a.ref(3, "ref_direction", "DIRECTION"));
        if (r == null || Math.abs(dot(r, z)) > 1 - 1e-12) {
            r = Math.abs(z[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 0, 1};
        }
        double rz = dot(r, z);
        double[] x = unit(new double[] {r[0] - rz * z[0], r[1] - rz * z[1], r[2] - rz * z[2]});
        double[] y = cross(z, x);
        return new double[] {o[0], o[1], o[2], x[0], x[1], x[2], y[0], y[1], y[2], z[0], z[1], z[2]};
    }

    /** The map from a placement's frame to the file's space. */
    static IgesMatrix frameMatrix(double[] f) {
        return new IgesMatrix(new double[] {f[3], f[6], f[9], f[0], f[4], f[7], f[10], f[1], f[5], f[8], f[11], f[2]});
    }

    /** The curve entity {@code e}, in 2-D or 3-D. */
    ParamCurve curve(StepFile.Entity e) {
        if (e.is("LINE")) {
            StepArgs a = args(e, "LINE").require(3, "name, pnt, dir");
            double[] p = point(a.ref(1, "pnt", "CARTESIAN_POINT"));
            double[] d = vector(a.ref(2, "dir", "VECTOR"));
            if (!(Math.abs(d[0]) + Math.abs(d[1]) + Math.abs(d[2]) > 0)) {
                throw a.error("a line whose vector has magnitude 0");
            }
            return new ParamCurve(null, p, d, null, null, null);
        }
        if (e.is("CIRCLE")) {
            StepArgs a = args(e, "CIRCLE").require(3, "name, position, radius");
            double[] f = placement(a.ref(1, "position", "AXIS2_PLACEMENT_2D", "AXIS2_PLACEMENT_3D"));
            double r = a.real(2, "radius");
            if (!(r > 0) || !Double.isFinite(r)) {
                throw a.error("a circle of radius " + r);
            }
            return new ParamCurve(null, null, null, new double[] {f[0], f[1], f[2]},
                    new double[] {r * f[3], r * f[4], r * f[5]}, new double[] {r * f[6], r * f[7], r * f[8]});
        }
        if (e.is("B_SPLINE_CURVE_WITH_KNOTS")) {
            return new ParamCurve(spline(e), null, null, null, null, null);
        }
        throw new IgesEntities.Skip("with a " + kind(e) + " trim or swept curve");
    }

    /** A short name of what {@code e} is, for the skipped summary. */
    static String kind(StepFile.Entity e) {
        String t = e.type();
        return t.length() > 60 ? t.substring(0, 60) + "…" : t;
    }

    /** B_SPLINE_CURVE_WITH_KNOTS, simple or in the complex form with RATIONAL_B_SPLINE_CURVE, of degree 1..15. */
    IgesCurve spline(StepFile.Entity e) {
        return spline(e, BezierPatch.MAX_DEGREE);
    }

    /**
     * The same of degree 1..{@code maxDegree}: a 3-D edge curve may pass a trim's limit (the
     * exact image of a cubic trim on a bicubic surface is of degree 18, {@link CurveOnSurface}).
     */
    IgesCurve spline(StepFile.Entity e, int maxDegree) {
        StepArgs b, k;
        int at;
        if (e.complex()) {
            b = args(e, "B_SPLINE_CURVE").require(5, "degree, control_points_list, curve_form, closed_curve, self_intersect");
            k = args(e, "B_SPLINE_CURVE_WITH_KNOTS").require(3, "knot_multiplicities, knots, knot_spec");
            at = 0;
        } else {
            b = args(e, "B_SPLINE_CURVE_WITH_KNOTS").require(9, "name, degree, control_points_list, curve_form, "
                    + "closed_curve, self_intersect, knot_multiplicities, knots, knot_spec");
            k = b;
            at = 1;
        }
        int degree = b.integer(at, "degree");
        List<?> refs = b.list(at + 1, "control_points_list");
        int n = refs.size();
        if (degree < 1 || degree > maxDegree || n < 2 || n > 1_000_000) {
            throw b.error("expected degree 1.." + maxDegree + " and 2 to 1,000,000 control points, found degree "
                    + degree + " and " + n + " points");
        }
        double[] pts = new double[3 * n];
        for (int i = 0; i < n; i++) {
            System.arraycopy(point(b.target(refs.get(i), "control point " + (i + 1), "CARTESIAN_POINT")), 0, pts, 3 * i, 3);
        }
        int kAt = e.complex() ? 0 : 6;
        double[] knots = knots(k, k.raw(kAt), k.raw(kAt + 1), degree, n, "");
        double[] w = null;
        if (e.is("RATIONAL_B_SPLINE_CURVE")) {
            StepArgs r = args(e, "RATIONAL_B_SPLINE_CURVE").require(1, "weights_data");
            w = r.reals(r.raw(0), "weights_data");
            if (w.length != n) {
                throw r.error("expected " + n + " weights, found " + w.length);
            }
        }
        return new IgesCurve(degree, knots, pts, w, knots[degree], knots[n]);
    }

    /** The full knot vector from distinct knots and their multiplicities; it must hold {@code count + degree + 1}. */
    static double[] knots(StepArgs a, Object multiplicities, Object values, int degree, int count, String direction) {
        int[] m = a.integers(multiplicities, direction + "knot_multiplicities");
        double[] k = a.reals(values, direction + "knots");
        if (m.length != k.length) {
            throw a.error("expected as many " + direction + "knot multiplicities as knots, found " + m.length + " and "
                    + k.length);
        }
        long total = 0;
        for (int x : m) {
            total += x;
        }
        if (total != (long) count + degree + 1) {
            throw a.error("expected " + direction + "knot multiplicities adding up to " + ((long) count + degree + 1)
                    + " (control points + degree + 1), found " + total);
        }
        double[] out = new double[(int) total];
        int at = 0;
        for (int i = 0; i < m.length; i++) {
            for (int j = 0; j < m[i]; j++) {
                out[at++] = k[i];
            }
        }
        return out;
    }

    /** B_SPLINE_SURFACE_WITH_KNOTS, simple or in the complex form with RATIONAL_B_SPLINE_SURFACE; u the first index. */
    IgesSurface bsplineSurface(StepFile.Entity e) {
        StepArgs b, k;
        int at;
        if (e.complex()) {
            b = args(e, "B_SPLINE_SURFACE").require(7, "u_degree, v_degree, control_points_list, surface_form, "
                    + "u_closed, v_closed, self_intersect");
            k = args(e, "B_SPLINE_SURFACE_WITH_KNOTS").require(5, "u_multiplicities, v_multiplicities, u_knots, "
                    + "v_knots, knot_spec");
            at = 0;
        } else {
            b = args(e, "B_SPLINE_SURFACE_WITH_KNOTS").require(13, "name, u_degree, v_degree, control_points_list, "
                    + "surface_form, u_closed, v_closed, self_intersect, u_multiplicities, v_multiplicities, u_knots, "
                    + "v_knots, knot_spec");
            k = b;
            at = 1;
        }
        int p = b.integer(at, "u_degree"), q = b.integer(at + 1, "v_degree");
        List<?> rows = b.list(at + 2, "control_points_list");
        int nu = rows.size(), nv = nu == 0 ? 0 : b.list(rows.get(0), "control_points_list row 1").size();
        int max = BezierPatch.MAX_DEGREE;
        if (p < 1 || q < 1 || p > max || q > max || nu < 2 || nv < 2 || (long) nu * nv > 4_000_000) {
            throw b.error("expected degrees 1.." + max + " and 2 × 2 to 4,000,000 control points, found degrees " + p
                    + ", " + q + " and " + nu + " × " + nv + " points");
        }
        double[] pts = new double[3 * nu * nv];
        for (int i = 0; i < nu; i++) {
            List<?> row = b.list(rows.get(i), "control_points_list row " + (i + 1));
            if (row.size() != nv) {
                throw b.error("expected " + nv + " control points in every row, found " + row.size() + " in row " + (i + 1));
            }
            for (int j = 0; j < nv; j++) {
                double[] xyz = point(b.target(row.get(j), "control point (" + (i + 1) + ", " + (j + 1) + ")",
                        "CARTESIAN_POINT"));
                System.arraycopy(xyz, 0, pts, 3 * (j * nu + i), 3);
            }
        }
        int kAt = e.complex() ? 0 : 8;
        double[] ku = knots(k, k.raw(kAt), k.raw(kAt + 2), p, nu, "u ");
        double[] kv = knots(k, k.raw(kAt + 1), k.raw(kAt + 3), q, nv, "v ");
        double[] w = null;
        if (e.is("RATIONAL_B_SPLINE_SURFACE")) {
            StepArgs r = args(e, "RATIONAL_B_SPLINE_SURFACE").require(1, "weights_data");
            List<?> wr = r.list(0, "weights_data");
            if (wr.size() != nu) {
                throw r.error("expected " + nu + " rows of weights, found " + wr.size());
            }
            w = new double[nu * nv];
            for (int i = 0; i < nu; i++) {
                double[] row = r.reals(wr.get(i), "weights_data row " + (i + 1));
                if (row.length != nv) {
                    throw r.error("expected " + nv + " weights in every row, found " + row.length + " in row " + (i + 1));
                }
                for (int j = 0; j < nv; j++) {
                    w[j * nu + i] = row[j];
                }
            }
        }
        return new IgesSurface(p, q, ku, kv, nu, nv, pts, w, new double[] {ku[p], ku[nu], kv[q], kv[nv]}, true);
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    static double[] unit(double[] v) {
        double l = Math.sqrt(dot(v, v));
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }
}
