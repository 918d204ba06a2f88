package org.beziertracer.model.io;

/**
 * The surface of a STEP face in the file's own parameters {@code (u, v)}, and its exact rational
 * B-spline over a parameter box. B-spline surfaces are kept as they are. {@code PLANE}
 * {@code o + u·x + v·y} becomes a bilinear patch. {@code CYLINDRICAL_}, {@code CONICAL_},
 * {@code SPHERICAL_}, {@code TOROIDAL_SURFACE} and {@code SURFACE_OF_REVOLUTION} are profiles
 * turned about their axis, u the angle (ISO 10303-42 §4.4.31–§4.4.36, §4.4.42): u becomes
 * quarter arcs (Piegl &amp; Tiller, <i>The NURBS Book</i>, 1997, §8.5, algorithm A8.1), so the
 * angle maps to the arcs' parameter by {@link #angleParam} — exact for the rational quadratic arc
 * of weights {@code 1, cos α, 1}, whose parameter t runs linearly in {@code tan(φ/2)}, φ measured
 * from the arc's middle (Piegl &amp; Tiller §7.5). {@code SURFACE_OF_LINEAR_EXTRUSION} sweeps its
 * curve along its vector, v linear.
 *
 * <p>Since only an angle's endpoints map exactly, a trim curve can follow an angle direction
 * only as an iso-parameter line (see {@link StepFaces}).
 */
final class StepSurface {

    enum Kind { BSPLINE, PLANE, CYLINDER, CONE, SPHERE, TORUS, REVOLUTION, EXTRUSION }

    final Kind kind;
    /** The placement frame {@code origin, x, y, z} (analytic surfaces and planes), the axis for a revolution. */
    final double[] frame;
    /** Radius (cylinder, cone, sphere), major radius (torus); then the cone's semi-angle, the torus' minor radius. */
    final double a, b;
    final IgesSurface spline;
    final StepGeometry.ParamCurve swept;
    final double[] vector;

    StepSurface(Kind kind, double[] frame, double a, double b, IgesSurface spline, StepGeometry.ParamCurve swept,
                double[] vector) {
        this.kind = kind;
        this.frame = frame;
        this.a = a;
        this.b = b;
        this.spline = spline;
        this.swept = swept;
        this.vector = vector;
    }

    /** Reads the surface entity {@code e}; {@code angleUnit} is the size of the file's plane angle unit in radians. */
    static StepSurface of(StepGeometry g, StepFile.Entity e, double angleUnit) {
        if (e.is("B_SPLINE_SURFACE_WITH_KNOTS")) {
            return new StepSurface(Kind.BSPLINE, null, 0, 0, g.bsplineSurface(e), null, null);
        }
        String type = e.complex() ? "" : e.type();
        switch (type) {
            case "PLANE", "CYLINDRICAL_SURFACE", "CONICAL_SURFACE", "SPHERICAL_SURFACE", "TOROIDAL_SURFACE" -> {
                StepArgs args = g.args(e, type).require(2, "name, position");
                double[] f = g.placement(args.ref(1, "position", "AXIS2_PLACEMENT_3D"));
                return switch (type) {
                    case "PLANE" -> new StepSurface(Kind.PLANE, f, 0, 0, null, null, null);
                    case "CYLINDRICAL_SURFACE" -> new StepSurface(Kind.CYLINDER, f, radius(args, 2, "radius"), 0, null, null, null);
                    case "SPHERICAL_SURFACE" -> new StepSurface(Kind.SPHERE, f, radius(args, 2, "radius"), 0, null, null, null);
                    case "CONICAL_SURFACE" -> {
                        args.require(4, "name, position, radius, semi_angle");
                        double r = args.real(2, "radius"), semi = args.real(3, "semi_angle") * angleUnit;
                        if (!(r >= 0) || !(Math.abs(semi) < Math.PI / 2) || semi == 0) {
                            throw args.error("expected a radius ≥ 0 and a semi-angle between 0 and 90°, found " + r
                                    + " and " + semi + " rad");
                        }
                        yield new StepSurface(Kind.CONE, f, r, semi, null, null, null);
                    }
                    default -> {
                        args.require(4, "name, position, major_radius, minor_radius");
                        yield new StepSurface(Kind.TORUS, f, radius(args, 2, "major_radius"),
                                radius(args, 3, "minor_radius"), null, null, null);
                    }
                };
            }
            case "SURFACE_OF_REVOLUTION" -> {
                StepArgs args = g.args(e, type).require(3, "name, swept_curve, axis_position");
                StepGeometry.ParamCurve c = g.curve(args.ref(1, "swept_curve"));
                StepArgs axis = g.args(args.ref(2, "axis_position", "AXIS1_PLACEMENT"), "AXIS1_PLACEMENT")
                        .require(3, "name, location, axis");
                double[] o = g.point(axis.ref(1, "location", "CARTESIAN_POINT"));
                double[] z = axis.raw(2) == StepFile.UNSET ? new double[] {0, 0, 1}
                        : g.direction(axis.ref(2, "axis", "DIRECTION"));
                return new StepSurface(Kind.REVOLUTION, new double[] {o[0], o[1], o[2], 0, 0, 0, 0, 0, 0, z[0], z[1], z[2]},
                        0, 0, null, c, null);
            }
            case "SURFACE_OF_LINEAR_EXTRUSION" -> {
                StepArgs args = g.args(e, type).require(3, "name, swept_curve, extrusion_axis");
                StepGeometry.ParamCurve c = g.curve(args.ref(1, "swept_curve"));
                return new StepSurface(Kind.EXTRUSION, null, 0, 0, null, c, g.vector(args.ref(2, "extrusion_axis", "VECTOR")));
            }
            default -> throw new IgesEntities.Skip("on a " + StepGeometry.kind(e));
        }
    }

    private static double radius(StepArgs args, int k, String name) {
        double r = args.real(k, name);
        if (!(r > 0) || !Double.isFinite(r)) {
            throw args.error("expected a positive " + name + ", found " + r);
        }
        return r;
    }

    /** Whether the file's u (v) is an angle: periodic, and not a linear parameter of the B-spline. */
    boolean angleU() {
        return kind == Kind.CYLINDER || kind == Kind.CONE || kind == Kind.SPHERE || kind == Kind.TORUS
                || kind == Kind.REVOLUTION || (kind == Kind.EXTRUSION && swept.circle());
    }

    boolean angleV() {
        return kind == Kind.SPHERE || kind == Kind.TORUS || (kind == Kind.REVOLUTION && swept.circle());
    }

    /** The period of u (v) in the file's parameters, 0 when not periodic. */
    double periodU() { return angleU() ? 2 * Math.PI : 0; }

    double periodV() { return kind == Kind.TORUS || (angleV() && kind == Kind.REVOLUTION) ? 2 * Math.PI : 0; }

    /** Whether the parameters of a point can be computed ({@link #inverse}). */
    boolean invertible() {
        return kind != Kind.BSPLINE && kind != Kind.REVOLUTION && kind != Kind.EXTRUSION;
    }

    /** The file's {@code (u, v)} of a point on the surface (u an angle in (−π, π]). */
    double[] inverse(double[] p) {
        double[] f = frame;
        double dx = p[0] - f[0], dy = p[1] - f[1], dz = p[2] - f[2];
        double x = dx * f[3] + dy * f[4] + dz * f[5], y = dx * f[6] + dy * f[7] + dz * f[8];
        double z = dx * f[9] + dy * f[10] + dz * f[11];
        return switch (kind) {
            case PLANE -> new double[] {x, y};
            case CYLINDER, CONE -> new double[] {Math.atan2(y, x), z};
            case SPHERE -> new double[] {Math.atan2(y, x), Math.atan2(z, Math.hypot(x, y))};
            case TORUS -> new double[] {Math.atan2(y, x), Math.atan2(z, Math.hypot(x, y) - a)};
            default -> throw new IllegalStateException(kind + " has no inverse");
        };
    }

    /**
     * The exact B-spline over the file's parameter box {@code [u0, u1] × [v0, v1]} (ignored for a
     * B-spline surface, which keeps its knots), in the file's space.
     */
    IgesSurface over(double u0, double u1, double v0, double v1) {
        double[] f = frame;
        switch (kind) {
            case BSPLINE -> {
                return spline;
            }
            case PLANE -> {
                double[] pts = new double[12];
                double[][] corners = {{u0, v0}, {u1, v0}, {u0, v1}, {u1, v1}};
                for (int k = 0; k < 4; k++) {
                    for (int q = 0; q < 3; q++) {
                        pts[3 * k + q] = f[q] + corners[k][0] * f[3 + q] + corners[k][1] * f[6 + q];
                    }
                }
                return new IgesSurface(1, 1, new double[] {u0, u0, u1, u1}, new double[] {v0, v0, v1, v1}, 2, 2, pts,
                        null, new double[] {u0, u1, v0, v1}, true);
            }
            case CYLINDER, CONE -> {
                double t = kind == Kind.CONE ? Math.tan(b) : 0;
                double[] p0 = inFrame(a + v0 * t, v0), p1 = inFrame(a + v1 * t, v1);
                IgesCurve profile = new IgesCurve(1, new double[] {v0, v0, v1, v1},
                        new double[] {p0[0], p0[1], p0[2], p1[0], p1[1], p1[2]}, null, v0, v1);
                return revolve(profile, u0, u1);
            }
            case SPHERE, TORUS -> {
                double r = kind == Kind.SPHERE ? a : b;
                double[] c = kind == Kind.SPHERE ? new double[] {f[0], f[1], f[2]} : inFrame(a, 0);
                IgesCurve profile = IgesCurve.arc(c, new double[] {r * f[3], r * f[4], r * f[5]},
                        new double[] {r * f[9], r * f[10], r * f[11]}, v0, v1);
                return revolve(profile, u0, u1);
            }
            case REVOLUTION -> {
                return revolve(swept.over(v0, v1), u0, u1);
            }
            default -> {
                IgesCurve c = swept.over(u0, u1);
                int n = c.count();
                double[] pts = new double[6 * n], w = c.weights() == null ? null : new double[2 * n];
                for (int k = 0; k < n; k++) {
                    for (int q = 0; q < 3; q++) {
                        pts[3 * k + q] = c.points()[3 * k + q] + v0 * vector[q];
                        pts[3 * (n + k) + q] = c.points()[3 * k + q] + v1 * vector[q];
                    }
                    if (w != null) {
                        w[k] = c.weights()[k];
                        w[n + k] = c.weights()[k];
                    }
                }
                return new IgesSurface(c.degree(), 1, c.knots(), new double[] {v0, v0, v1, v1}, n, 2, pts, w,
                        new double[] {c.t0(), c.t1(), v0, v1}, true);
            }
        }
    }

    /** The point {@code origin + ρ·x + h·z} of the frame. */
    private double[] inFrame(double rho, double h) {
        double[] f = frame;
        return new double[] {f[0] + rho * f[3] + h * f[9], f[1] + rho * f[4] + h * f[10], f[2] + rho * f[5] + h * f[11]};
    }

    /** {@code profile} (v) turned about the frame's axis from angle {@code u0} to {@code u1} (u), angle 0 where it lies. */
    private IgesSurface revolve(IgesCurve profile, double u0, double u1) {
        double[] o = {frame[0], frame[1], frame[2]}, d = {frame[9], frame[10], frame[11]};
        IgesCurve unit = IgesCurve.arc(new double[3], new double[] {1, 0, 0}, new double[] {0, 1, 0}, u0, u1);
        int m = unit.count(), n = profile.count();
        double[] c = profile.points(), arc = unit.points(), pts = new double[3 * n * m], w = new double[n * m];
        for (int k = 0; k < n; k++) {
            double px = c[3 * k] - o[0], py = c[3 * k + 1] - o[1], pz = c[3 * k + 2] - o[2];
            double along = px * d[0] + py * d[1] + pz * d[2];
            double[] q = {o[0] + along * d[0], o[1] + along * d[1], o[2] + along * d[2]};
            double[] x = {c[3 * k] - q[0], c[3 * k + 1] - q[1], c[3 * k + 2] - q[2]};
            double[] y = StepGeometry.cross(d, x);
            double wk = profile.weights() == null ? 1 : profile.weights()[k];
            for (int j = 0; j < m; j++) {
                int at = k * m + j; // u (the angle) fastest
                double cos = arc[3 * j], sin = arc[3 * j + 1];
                for (int r = 0; r < 3; r++) {
                    pts[3 * at + r] = q[r] + cos * x[r] + sin * y[r];
                }
                w[at] = wk * unit.weights()[j];
            }
        }
        return new IgesSurface(2, profile.degree(), unit.knots(), profile.knots(), m, n, pts, w,
                new double[] {unit.t0(), unit.t1(), profile.t0(), profile.t1()}, true);
    }

    /**
     * The parameter of the arcs {@link IgesCurve#arc}{@code (…, from, to)} at angle {@code theta}:
     * on arc k of half-angle α, {@code t = (tan(φ/2) / tan(α/2) + 1) / 2}, φ measured from the
     * arc's middle.
     */
    static double angleParam(double theta, double from, double to) {
        int arcs = Math.max(1, (int) Math.ceil((to - from) / (Math.PI / 2) - 1e-12));
        double step = (to - from) / arcs;
        if (theta <= from) {
            return 0;
        }
        if (theta >= to) {
            return arcs;
        }
        int k = Math.min(arcs - 1, (int) Math.floor((theta - from) / step));
        double phi = theta - (from + k * step + step / 2);
        double t = (Math.tan(phi / 2) / Math.tan(step / 4) + 1) / 2;
        return k + Math.max(0, Math.min(1, t));
    }

    /** The B-spline's u for the file's u. */
    double mapU(double u, double u0, double u1) {
        return angleU() ? angleParam(u, u0, u1) : u;
    }

    /** The B-spline's v for the file's v. */
    double mapV(double v, double v0, double v1) {
        return angleV() ? angleParam(v, v0, v1) : v;
    }
}
