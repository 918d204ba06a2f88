package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.beziertracer.math.BezierDecomposition;
import org.beziertracer.model.TrimCurve;

/**
 * The exact 3-D image {@code S(c(t))} of a parameter-space curve {@code c(t) = (u(t), v(t))} on
 * a rational B-spline surface {@code S}, as a rational B-spline in the curve's own parameter
 * {@code t}: what the STEP writer gives an edge as its 3-D curve beside the pcurve.
 *
 * <p>Method: functional composition of Bézier pieces (T. DeRose, R. Goldman, H. Hagen, S. Mann,
 * "Functional composition algorithms via blossoming", ACM Transactions on Graphics 12(2), 1993,
 * 113–135), in the Bernstein product form of R. Farouki and V. Rajan, "Algorithms for polynomials
 * in Bernstein form", CAGD 5, 1988, 1–26. The curve is cut at its own knots and where it crosses
 * a knot line of the surface (the roots of {@code U(t) − k·W(t)} in Bernstein form, isolated by
 * subdivision and Descartes' rule of signs, then bisected to the last bit); on each cut piece of
 * homogeneous degree {@code d} lying in one Bézier patch of degrees {@code (p, q)} on
 * {@code [a,b] × [c,e]}, {@code W^p·B_i^p((u−a)/(b−a)) = C(p,i)·A^i·Ā^(p−i)} with
 * {@code A = (U − aW)/(b−a)}, {@code Ā = (bW − U)/(b−a)}, and the same in v, so the image is the
 * Bézier curve {@code Σ C(p,i)C(q,j) A^i Ā^(p−i) B^j B̄^(q−j) P^w_ij} of degree
 * {@code d·(p + q)} (a factor drops out when u or v is constant along the curve: an iso-parameter
 * line gives the iso-curve of degree {@code p} or {@code q}). The pieces are then lowered to
 * the least degree all of them have exactly (a polygon trim along iso-lines gives the surface's
 * degree) and join at knots of full multiplicity. Exact but for rounding (the crossing parameters are
 * rounded to the nearest double); polynomial when neither the surface nor the curve is rational.
 * Stateless.
 */
final class CurveOnSurface {
    private CurveOnSurface() {}

    /** Degrees above this are not composed (the caller fits instead): a cubic trim on a degree-5 surface is 30. */
    static final int MAX_DEGREE = 32;

    /** A B-spline curve in 3-D: {@code x y z} points, weights null when polynomial, clamped knots. */
    record Curve3(int degree, double[] knots, double[] points, double[] weights) {
        int count() { return points.length / 3; }
    }

    /** The surface's Bézier patches in homogeneous form {@code (wx, wy, wz, w)}, made once per surface. */
    record Patches(int p, int q, BezierDecomposition.Patches pieces, boolean rational) {
        static Patches of(SplinePoint s) {
            double[] h = SplinePoint.homogeneous(s.points(), s.weights());
            double[] ku = s.knotsU(), kv = s.knotsV();
            int p = s.p(), q = s.q();
            return new Patches(p, q, BezierDecomposition.surface(p, q, ku, kv, s.countU(), s.countV(), h, 4,
                    ku[p], ku[s.countU()], kv[q], kv[s.countV()]), s.weights() != null);
        }
    }

    /**
     * The image of {@code curve} over {@code [lo, hi]} (inside its range), or null when its
     * degree would pass {@link #MAX_DEGREE}.
     */
    static Curve3 compose(Patches s, TrimCurve curve, double lo, double hi) {
        int d = curve.degree();
        double[] uv = curve.points();
        boolean uVaries = false, vVaries = false;
        for (int k = 2; k < uv.length; k += 2) {
            uVaries |= uv[k] != uv[0];
            vVaries |= uv[k + 1] != uv[1];
        }
        int degree = d * ((uVaries ? s.p() : 0) + (vVaries ? s.q() : 0));
        if (degree > MAX_DEGREE || degree == 0) {
            return null;
        }
        BezierDecomposition.Segments seg = BezierDecomposition.curve(d, curve.knots(), curve.homogeneous(), 3, lo, hi);
        BezierDecomposition.Patches pieces = s.pieces();
        List<double[]> bez = new ArrayList<>();
        List<Double> breaks = new ArrayList<>();
        breaks.add(lo);
        for (int k = 0; k < seg.count(); k++) {
            double[] h = Arrays.copyOfRange(seg.points(), seg.offset(k), seg.offset(k + 1));
            double t0 = seg.breaks()[k], t1 = seg.breaks()[k + 1];
            double[] cuts = cuts(h, d, pieces.breaksU(), pieces.breaksV(), uVaries, vVaries);
            double from = 0;
            for (int c = 0; c <= cuts.length; c++) {
                double to = c < cuts.length ? cuts[c] : 1;
                double tTo = c < cuts.length ? t0 + (t1 - t0) * to : t1;
                if (!(tTo > breaks.get(breaks.size() - 1))) {
                    continue; // a cut that rounds onto the previous break: nothing between them
                }
                double[] part = part(h, d, from, to);
                if (!add(s, part, d, uv, uVaries, vVaries, degree, breaks.get(breaks.size() - 1), tTo, 0, bez,
                        breaks)) {
                    return null;
                }
                from = to;
            }
        }
        int reduced = Bernstein.reducedDegree(bez, degree);
        if (reduced < degree) {
            bez.replaceAll(h -> Bernstein.reduce(h, degree, reduced));
        }
        return join(reduced, bez, breaks, s.rational() || curve.rational());
    }

    /**
     * Adds the image of {@code part} (on {@code [tFrom, tTo]}): halved until every homogeneous
     * weight is positive (a control polygon overshooting its patch can give a weight ≤ 0 though
     * the curve has none); false when 12 halvings do not do it.
     */
    private static boolean add(Patches s, double[] part, int d, double[] uv, boolean uVaries, boolean vVaries,
                               int degree, double tFrom, double tTo, int depth, List<double[]> bez, List<Double> breaks) {
        double[] image = composePiece(s, part, d, uv[0], uv[1], uVaries, vVaries, degree);
        boolean positive = true;
        for (int k = 3; k < image.length; k += 4) {
            positive &= image[k] > 0 && Double.isFinite(image[k]);
        }
        if (positive) {
            bez.add(image);
            breaks.add(tTo);
            return true;
        }
        double tMid = (tFrom + tTo) / 2;
        if (depth >= 12 || !(tMid > tFrom && tMid < tTo)) {
            return false;
        }
        double[] left = part.clone(), right = new double[part.length];
        Bernstein.split(left, right, 3, d, 0.5);
        return add(s, left, d, uv, uVaries, vVaries, degree, tFrom, tMid, depth + 1, bez, breaks)
                && add(s, right, d, uv, uVaries, vVaries, degree, tMid, tTo, depth + 1, bez, breaks);
    }

    /** The parameters in (0, 1) where the Bézier piece {@code h} crosses an interior knot line, sorted. */
    private static double[] cuts(double[] h, int d, double[] breaksU, double[] breaksV, boolean uVaries, boolean vVaries) {
        List<Double> out = new ArrayList<>();
        double[] f = new double[d + 1];
        for (int axis = 0; axis < 2; axis++) {
            if (axis == 0 ? !uVaries : !vVaries) {
                continue;
            }
            double[] br = axis == 0 ? breaksU : breaksV;
            for (int b = 1; b + 1 < br.length; b++) {
                for (int i = 0; i <= d; i++) {
                    f[i] = h[3 * i + axis] - br[b] * h[3 * i + 2];
                }
                Bernstein.roots(f, 0, 1, 0, out);
            }
        }
        double[] s = out.stream().mapToDouble(Double::doubleValue).filter(x -> x > 1e-12 && x < 1 - 1e-12).sorted()
                .toArray();
        return s;
    }

    /** The Bézier piece of {@code h} (degree {@code d}, 3 doubles a point) on {@code [from, to] ⊂ [0, 1]}. */
    private static double[] part(double[] h, int d, double from, double to) {
        double[] out = h.clone();
        if (to < 1) {
            double[] right = new double[h.length];
            Bernstein.split(out, right, 3, d, to);
        }
        if (from > 0) {
            double[] left = out.clone(), right = new double[h.length];
            Bernstein.split(left, right, 3, d, from / to);
            out = right;
        }
        return out;
    }

    /** The image of one piece {@code h} (homogeneous {@code U V W}) lying in one Bézier patch, as 4-D Bézier points. */
    private static double[] composePiece(Patches s, double[] h, int d, double u0, double v0, boolean uVaries,
                                         boolean vVaries, int degree) {
        BezierDecomposition.Patches pieces = s.pieces();
        double[] mid = new double[3];
        for (int a = 0; a < 3; a++) {
            mid[a] = Bernstein.value(column(h, a, d), 0.5);
        }
        int a = index(pieces.breaksU(), mid[0] / mid[2]), b = index(pieces.breaksV(), mid[1] / mid[2]);
        double[] net = pieces.nets()[b * pieces.countU() + a];
        double[][] bu = factors(h, d, 0, s.p(), pieces.breaksU()[a], pieces.breaksU()[a + 1], uVaries, u0);
        double[][] bv = factors(h, d, 1, s.q(), pieces.breaksV()[b], pieces.breaksV()[b + 1], vVaries, v0);
        double[] out = new double[4 * (degree + 1)];
        int p = s.p();
        for (int j = 0; j <= s.q(); j++) {
            for (int i = 0; i <= p; i++) {
                double[] term = Bernstein.product(bu[i], bv[j]);
                int at = 4 * (j * (p + 1) + i);
                for (int k = 0; k <= degree; k++) {
                    for (int c = 0; c < 4; c++) {
                        out[4 * k + c] += term[k] * net[at + c];
                    }
                }
            }
        }
        return out;
    }

    /** Coordinate {@code a} of the homogeneous points {@code h}. */
    private static double[] column(double[] h, int a, int d) {
        double[] f = new double[d + 1];
        for (int i = 0; i <= d; i++) {
            f[i] = h[3 * i + a];
        }
        return f;
    }

    private static int index(double[] breaks, double x) {
        int k = 0;
        while (k + 2 < breaks.length && !(x < breaks[k + 1])) {
            k++;
        }
        return k;
    }

    /**
     * {@code C(p,i)·A^i·Ā^(p−i)} for {@code i = 0..p} as Bernstein coefficients: of degree
     * {@code p·d} when the coordinate varies, else constants (degree 0) at {@code x0}.
     */
    private static double[][] factors(double[] h, int d, int axis, int p, double lo, double hi, boolean varies,
                                      double x0) {
        double[] A, Abar;
        if (varies) {
            A = new double[d + 1];
            Abar = new double[d + 1];
            for (int i = 0; i <= d; i++) {
                A[i] = (h[3 * i + axis] - lo * h[3 * i + 2]) / (hi - lo);
                Abar[i] = (hi * h[3 * i + 2] - h[3 * i + axis]) / (hi - lo);
            }
        } else {
            A = new double[] {(x0 - lo) / (hi - lo)};
            Abar = new double[] {(hi - x0) / (hi - lo)};
        }
        double[][] powA = new double[p + 1][], powAbar = new double[p + 1][];
        powA[0] = new double[] {1};
        powAbar[0] = new double[] {1};
        for (int i = 1; i <= p; i++) {
            powA[i] = Bernstein.product(powA[i - 1], A);
            powAbar[i] = Bernstein.product(powAbar[i - 1], Abar);
        }
        double[][] out = new double[p + 1][];
        for (int i = 0; i <= p; i++) {
            out[i] = Bernstein.product(powA[i], powAbar[p - i]);
            double c = Bernstein.binomial(p, i);
            for (int k = 0; k < out[i].length; k++) {
                out[i][k] *= c;
            }
        }
        return out;
    }

    /**
     * The 4-D Bézier pieces joined into one clamped B-spline of degree {@code degree}, breaks as
     * knots of multiplicity {@code degree} where consecutive pieces meet (one shared point), of
     * {@code degree + 1} where they do not (a surface whose knot of multiplicity {@code p + 1}
     * makes it jump).
     */
    private static Curve3 join(int degree, List<double[]> bez, List<Double> breaks, boolean rational) {
        int pieces = bez.size();
        List<Double> knots = new ArrayList<>();
        List<double[]> pts = new ArrayList<>();
        for (int k = 0; k <= degree; k++) {
            knots.add(breaks.get(0));
        }
        for (int b = 0; b < pieces; b++) {
            double[] h = bez.get(b);
            boolean shared = b > 0 && meets(bez.get(b - 1), h, degree);
            if (b > 0) {
                for (int m = 0; m < (shared ? degree : degree + 1); m++) {
                    knots.add(breaks.get(b));
                }
            }
            for (int i = shared ? 1 : 0; i <= degree; i++) {
                pts.add(Arrays.copyOfRange(h, 4 * i, 4 * i + 4));
            }
        }
        for (int k = 0; k <= degree; k++) {
            knots.add(breaks.get(pieces));
        }
        int n = pts.size();
        double[] xyz = new double[3 * n], w = rational ? new double[n] : null;
        for (int k = 0; k < n; k++) {
            double[] h = pts.get(k);
            for (int a = 0; a < 3; a++) {
                xyz[3 * k + a] = h[a] / h[3];
            }
            if (w != null) {
                w[k] = h[3];
            }
        }
        return new Curve3(degree, knots.stream().mapToDouble(Double::doubleValue).toArray(), xyz, w);
    }

    /** Whether piece {@code a} ends where {@code b} starts, to rounding (1e-9 of the points' size). */
    private static boolean meets(double[] a, double[] b, int degree) {
        double scale = 0, gap = 0;
        for (int c = 0; c < 3; c++) {
            double x = a[4 * degree + c] / a[4 * degree + 3], y = b[c] / b[3];
            scale = Math.max(scale, Math.max(Math.abs(x), Math.abs(y)));
            gap = Math.max(gap, Math.abs(x - y));
        }
        return gap <= 1e-9 * Math.max(scale, Double.MIN_NORMAL);
    }

    /** Largest distance of a fitted curve from the true image, relative to the surface's control box diagonal. */
    static final double FIT_TOLERANCE = 1e-7;

    /**
     * The image of {@code curve} over {@code [lo, hi]} as a polyline (degree-1 B-spline in
     * {@code t}) through surface points, halving each span until the surface point at its middle
     * parameter lies within {@link #FIT_TOLERANCE} of the chord's middle (at most 2^16 spans):
     * for trims whose exact image would pass {@link #MAX_DEGREE}.
     */
    static Curve3 fit(SplinePoint s, TrimCurve curve, double lo, double hi) {
        double[] box = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double diag2 = 0;
        double[] pts = s.points();
        for (int a = 0; a < 3; a++) {
            box[0] = Double.POSITIVE_INFINITY;
            box[1] = Double.NEGATIVE_INFINITY;
            for (int k = a; k < pts.length; k += 3) {
                box[0] = Math.min(box[0], pts[k]);
                box[1] = Math.max(box[1], pts[k]);
            }
            diag2 += (box[1] - box[0]) * (box[1] - box[0]);
        }
        double tol = FIT_TOLERANCE * Math.max(Math.sqrt(diag2), Double.MIN_NORMAL);
        List<Double> ts = new ArrayList<>();
        List<double[]> ps = new ArrayList<>();
        double[] a = imageAt(s, curve, lo), b = imageAt(s, curve, hi);
        ts.add(lo);
        ps.add(a);
        refine(s, curve, lo, hi, a, b, tol, 0, ts, ps);
        int n = ts.size();
        double[] knots = new double[n + 2], xyz = new double[3 * n];
        for (int k = 0; k < n; k++) {
            knots[k + 1] = ts.get(k);
            System.arraycopy(ps.get(k), 0, xyz, 3 * k, 3);
        }
        knots[0] = lo;
        knots[n + 1] = hi;
        return new Curve3(1, knots, xyz, null);
    }

    private static void refine(SplinePoint s, TrimCurve curve, double t0, double t1, double[] a, double[] b,
                               double tol, int depth, List<Double> ts, List<double[]> ps) {
        double tm = (t0 + t1) / 2;
        double[] m = imageAt(s, curve, tm);
        double dx = m[0] - (a[0] + b[0]) / 2, dy = m[1] - (a[1] + b[1]) / 2, dz = m[2] - (a[2] + b[2]) / 2;
        if (depth < 16 && tm > t0 && tm < t1 && (depth < 2 || Math.sqrt(dx * dx + dy * dy + dz * dz) > tol)) {
            refine(s, curve, t0, tm, a, m, tol, depth + 1, ts, ps);
            refine(s, curve, tm, t1, m, b, tol, depth + 1, ts, ps);
            return;
        }
        ts.add(t1);
        ps.add(b);
    }

    /** {@code S(c(t))}. */
    static double[] imageAt(SplinePoint s, TrimCurve curve, double t) {
        double[] uv = SplinePoint.curve(curve.degree(), curve.knots(), curve.points(), curve.weights(), t);
        return s.at(uv[0], uv[1]);
    }
}
