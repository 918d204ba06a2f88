package org.beziertracer.model.io;

/**
 * A STEP edge's 3-D curve between its vertices, with the parameters where the edge starts and
 * ends in loop order ({@code ta}, {@code tb}; {@code tb < ta} runs the curve backwards): a
 * {@code LINE} (the vertices' projections on it), a {@code CIRCLE} (their angles, the whole
 * turn for a closed edge), a {@code B_SPLINE_CURVE_WITH_KNOTS} (its ends when the vertices are
 * there, else their nearest points by sampling and golden-section search — Kiefer 1953, as in
 * {@link StepTrims}), any of them in a {@code TRIMMED_CURVE} by parameter values. For
 * {@link EdgeProjection}. Immutable.
 */
final class EdgeCurve3 {

    private final StepGeometry.ParamCurve curve;
    private final double ta, tb;

    private EdgeCurve3(StepGeometry.ParamCurve curve, double ta, double tb) {
        this.curve = curve;
        this.ta = ta;
        this.tb = tb;
    }

    double ta() { return ta; }

    double tb() { return tb; }

    double[] at(double t) {
        return curve.spline() != null ? EdgeProjection.point(curve.spline(), t) : curve.at(t);
    }

    /**
     * The curve {@code e} from the loop's {@code start} vertex to its {@code end}; {@code forward}
     * when the loop runs along the edge curve's own direction.
     */
    static EdgeCurve3 of(StepGeometry g, StepFile.Entity e, double angleUnit, double[] start, double[] end,
                         boolean closed, boolean forward) {
        boolean sense = true;
        double[] trims = null;
        StepFile.Entity basis = e;
        if (e.is("TRIMMED_CURVE")) {
            StepArgs a = g.args(e, "TRIMMED_CURVE").require(5, "name, basis_curve, trim_1, trim_2, sense_agreement");
            basis = a.ref(1, "basis_curve");
            sense = a.bool(4, "sense_agreement", true);
            trims = new double[] {parameter(a, 2, "trim_1"), parameter(a, 3, "trim_2")};
        }
        StepGeometry.ParamCurve c = basis.is("B_SPLINE_CURVE_WITH_KNOTS")
                ? new StepGeometry.ParamCurve(g.spline(basis, CurveOnSurface.MAX_DEGREE), null, null, null, null, null)
                : g.curve(basis);
        if (trims != null && c.circle()) {
            trims[0] *= angleUnit;
            trims[1] *= angleUnit;
        }
        boolean along = forward == sense; // the loop runs along the basis curve
        EdgeCurve3 out = new EdgeCurve3(c, 0, 0);
        double ta, tb;
        if (c.line()) {
            ta = out.lineParameter(start);
            tb = out.lineParameter(end);
        } else if (c.circle()) {
            ta = out.angle(start);
            tb = closed ? ta + (along ? 2 * Math.PI : -2 * Math.PI) : out.angle(end);
            while (along ? tb <= ta : tb >= ta) {
                tb += along ? 2 * Math.PI : -2 * Math.PI;
            }
        } else {
            IgesCurve sp = c.spline();
            double lo = trims == null ? sp.t0() : Math.max(sp.t0(), Math.min(trims[0], trims[1]));
            double hi = trims == null ? sp.t1() : Math.min(sp.t1(), Math.max(trims[0], trims[1]));
            if (closed) {
                ta = along ? lo : hi;
                tb = along ? hi : lo;
            } else {
                ta = out.splineParameter(start, lo, hi);
                tb = out.splineParameter(end, lo, hi);
            }
        }
        if (!(along ? tb > ta : tb < ta)) {
            throw new IgesEntities.Skip("with an edge whose vertices run against its 3-D curve");
        }
        return new EdgeCurve3(c, ta, tb);
    }

    private static double parameter(StepArgs a, int k, String name) {
        for (Object o : a.list(k, name)) {
            if (o instanceof StepFile.Typed t && t.type().equals("PARAMETER_VALUE")) {
                return a.real(t.value(), name);
            }
        }
        throw new IgesEntities.Skip("with a trimmed 3-D edge curve trimmed by points only");
    }

    private double lineParameter(double[] p) {
        double[] p0 = curve.p0(), d = curve.d();
        return ((p[0] - p0[0]) * d[0] + (p[1] - p0[1]) * d[1] + (p[2] - p0[2]) * d[2])
                / (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }

    private double angle(double[] p) {
        double[] c = curve.c(), x = curve.x(), y = curve.y();
        double dx = p[0] - c[0], dy = p[1] - c[1], dz = p[2] - c[2];
        return Math.atan2(dx * y[0] + dy * y[1] + dz * y[2], dx * x[0] + dy * x[1] + dz * x[2]);
    }

    /** The parameter in {@code [lo, hi]} of the curve point nearest {@code p}: an end when within rounding of it. */
    private double splineParameter(double[] p, double lo, double hi) {
        double scale = 0;
        for (double x : curve.spline().points()) {
            scale = Math.max(scale, Math.abs(x));
        }
        double tol = 1e-9 * Math.max(scale, Double.MIN_NORMAL);
        if (distance(at(lo), p) <= tol) {
            return lo;
        }
        if (distance(at(hi), p) <= tol) {
            return hi;
        }
        return StepTrims.minimum(t -> distance(at(t), p), lo, hi, 256, 100);
    }

    private static double distance(double[] a, double[] b) {
        return Math.sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }
}
