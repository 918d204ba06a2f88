package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;
import java.util.function.DoubleFunction;

import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimPiece;

/**
 * A trim piece in a surface's parameters made from a 3-D edge curve that lies on the surface,
 * for faces whose edges carry no parameter-space curve (STEP edges without a {@code PCURVE},
 * IGES 142 curves without a parameter-space curve).
 *
 * <p>Point inversion (Piegl &amp; Tiller, <i>The NURBS Book</i>, 2nd ed., 1997, §6.1): the start is
 * the nearest of a grid of about 32 × 32 surface points on the knot spans (the nearest
 * sub-patch; the 32 nearest in turn until one converges, then those of a 256 × 256 grid when
 * none does),
 * or the previous sample's parameters along the curve; from there Newton's iteration on
 * {@code S(u,v) − P} in its Gauss–Newton form ({@code (JᵀJ)Δ = Jᵀ(P − S)}, which converges
 * quadratically for a point on the surface), a step halved until it gets nearer, clamped to the range, the Jacobian by central
 * differences. The curve is sampled adaptively: a parameter span is halved (at least 3 times,
 * at most 16) until the parameters of the surface point at its middle lie within
 * {@link #TOLERANCE} of the middle of its chord in (u, v). The piece is the polyline (a degree-1
 * B-spline) through the samples, in loop order; samples on one iso-parameter line (a parallel or a
 * meridian of a surface of revolution, a line along a parameter) give that line exactly, from
 * the first sample to the last. Not thread-safe (one per face).
 */
final class EdgeProjection {

    /** Largest distance in (u, v) between the projected curve and its polyline, relative to the range's larger side. */
    static final double TOLERANCE = 1e-6;

    /** Largest spread of the samples' u (or v), relative to the range's larger side, for an iso-parameter line. */
    static final double ISO = 1e-9;

    /** Largest distance of an edge curve from its surface, relative to the surface's size. */
    static final double ON_SURFACE = 1e-6;

    private static final int GRID = 32, FINE_GRID = 256, STARTS = 32;
    private static final int MIN_DEPTH = 3, MAX_DEPTH = 16;

    /** The surface's parameters of a 3-D point, starting near {@code guess} (null: anywhere); {@code u, v, distance}. */
    interface Inverse {
        double[] uv(double[] p, double[] guess);
    }

    private final Inverse inverse;
    private final double tolUv, tolIso, tolXyz;

    EdgeProjection(Inverse inverse, double[] range, double size) {
        this.inverse = inverse;
        this.tolUv = TOLERANCE * Math.max(range[1] - range[0], range[3] - range[2]);
        this.tolIso = ISO * Math.max(range[1] - range[0], range[3] - range[2]);
        this.tolXyz = ON_SURFACE * Math.max(size, Double.MIN_NORMAL);
    }

    /** Projection onto the B-spline {@code s} over {@code range}. */
    static EdgeProjection onto(SplinePoint s, double[] range) {
        Newton n = new Newton(s, range);
        return new EdgeProjection(n::uv, range, n.size);
    }

    /**
     * The piece of {@code curve} from {@code ta} to {@code tb} (either order) in (u, v).
     *
     * @throws IgesEntities.Skip when the curve leaves the surface or its image jumps (a seam)
     */
    TrimPiece project(DoubleFunction<double[]> curve, double ta, double tb) {
        return project(curve, ta, tb, null);
    }

    /**
     * {@link #project(DoubleFunction, double, double)}, the first sample's inversion started at
     * {@code start} (the previous piece's end in a loop: on a closed surface, the seam's side it
     * continues from), or anywhere when null.
     */
    TrimPiece project(DoubleFunction<double[]> curve, double ta, double tb, double[] start) {
        List<double[]> uv = new ArrayList<>();
        double[] a = at(curve, ta, start);
        uv.add(a);
        // the first 2^MIN_DEPTH spans in order, each sample guessed from the one before (an angle's turn follows)
        int spans = 1 << MIN_DEPTH;
        for (int k = 1; k <= spans; k++) {
            double t0 = ta + (tb - ta) * (k - 1) / spans, t1 = k == spans ? tb : ta + (tb - ta) * k / spans;
            double[] b = at(curve, t1, a);
            refine(curve, t0, t1, a, b, MIN_DEPTH, uv);
            a = b;
        }
        isoLine(uv);
        int n = uv.size();
        double[] pts = new double[2 * n], knots = new double[n + 2];
        for (int k = 0; k < n; k++) {
            pts[2 * k] = uv.get(k)[0];
            pts[2 * k + 1] = uv.get(k)[1];
            knots[k + 1] = k;
        }
        knots[n + 1] = n - 1;
        return new TrimPiece(new TrimCurve(SplineBasis.BSPLINE, 1, knots, pts, null), 0, n - 1);
    }

    /**
     * The exact image where there is one: samples that all share their u (a meridian of a surface
     * of revolution, a line along v) or their v (a parallel) to within {@link #ISO} of the range
     * are that iso-parameter line, two points at the first sample's u (v), instead of a polyline.
     */
    private void isoLine(List<double[]> uv) {
        for (int axis = 0; axis < 2; axis++) {
            double first = uv.get(0)[axis];
            boolean iso = true;
            for (int k = 1; k < uv.size() && iso; k++) {
                iso = Math.abs(uv.get(k)[axis] - first) <= tolIso;
            }
            if (iso) {
                double[] a = uv.get(0), b = uv.get(uv.size() - 1).clone();
                b[axis] = first;
                uv.clear();
                uv.add(a);
                uv.add(b);
                return;
            }
        }
    }

    private void refine(DoubleFunction<double[]> curve, double t0, double t1, double[] a, double[] b, int depth,
                        List<double[]> out) {
        double tm = (t0 + t1) / 2;
        double[] m = at(curve, tm, a);
        double du = m[0] - (a[0] + b[0]) / 2, dv = m[1] - (a[1] + b[1]) / 2;
        boolean far = Math.hypot(du, dv) > tolUv;
        if (depth < MIN_DEPTH || (far && depth < MAX_DEPTH)) {
            refine(curve, t0, tm, a, m, depth + 1, out);
            refine(curve, tm, t1, m, b, depth + 1, out);
            return;
        }
        if (far && Math.hypot(du, dv) > 1000 * tolUv) {
            throw new IgesEntities.Skip("with an edge curve whose image on its surface jumps (it crosses a seam)");
        }
        out.add(b);
    }

    private double[] at(DoubleFunction<double[]> curve, double t, double[] guess) {
        double[] p = curve.apply(t);
        double[] uv = inverse.uv(p, guess);
        if (!(uv[2] <= tolXyz)) {
            throw new IgesEntities.Skip("with an edge curve that does not lie on its surface (" + uv[2] + " away)");
        }
        return uv;
    }

    /** The point at {@code t} of a rational 3-D B-spline (de Boor, Piegl &amp; Tiller A4.1). */
    static double[] point(IgesCurve c, double t) {
        int n = c.count(), d = c.degree();
        double[] knots = c.knots(), pts = c.points(), w = c.weights();
        int s = SplinePoint.span(knots, d, n, t);
        double[] basis = SplinePoint.basis(knots, d, s, t);
        double x = 0, y = 0, z = 0, ws = 0;
        for (int i = 0; i <= d; i++) {
            int k = s - d + i;
            double bw = basis[i] * (w == null ? 1 : w[k]);
            x += bw * pts[3 * k];
            y += bw * pts[3 * k + 1];
            z += bw * pts[3 * k + 2];
            ws += bw;
        }
        return new double[] {x / ws, y / ws, z / ws};
    }

    /** Point inversion on a B-spline surface: grid start, then Gauss–Newton. */
    private static final class Newton {
        private final SplinePoint s;
        private final double[] range;
        private final double[][] coarse;
        private double[][] fine;
        final double size;

        Newton(SplinePoint s, double[] range) {
            this.s = s;
            this.range = range.clone();
            coarse = grid(GRID);
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (double x : coarse[1]) {
                lo = Math.min(lo, x);
                hi = Math.max(hi, x);
            }
            size = Math.max(hi - lo, Math.max(Math.abs(lo), Math.abs(hi)) * 1e-3);
        }

        /** Parameters and points of {@code perSpan × perSpan} samples inside every knot span. */
        private double[][] grid(int perSpan) {
            double[] us = samples(s.knotsU(), range[0], range[1], perSpan);
            double[] vs = samples(s.knotsV(), range[2], range[3], perSpan);
            double[] uv = new double[2 * us.length * vs.length], xyz = new double[3 * us.length * vs.length];
            int k = 0;
            for (double u : us) {
                for (double v : vs) {
                    uv[2 * k] = u;
                    uv[2 * k + 1] = v;
                    System.arraycopy(s.at(u, v), 0, xyz, 3 * k, 3);
                    k++;
                }
            }
            return new double[][] {uv, xyz};
        }

        /**
         * About {@code total} parameters over the range: the breaks of its knot spans (every
         * k-th when there are more than {@code total / 2}) and equal steps between.
         */
        private static double[] samples(double[] knots, double from, double to, int total) {
            List<Double> breaks = new ArrayList<>();
            breaks.add(from);
            for (double x : knots) {
                if (x > breaks.get(breaks.size() - 1) && x < to) {
                    breaks.add(x);
                }
            }
            breaks.add(to);
            int spans = breaks.size() - 1, step = Math.max(1, (2 * spans + total - 1) / total);
            int perSpan = Math.max(2, total / ((spans + step - 1) / step));
            List<Double> out = new ArrayList<>();
            for (int b = 0; b < spans; b += step) {
                double a = breaks.get(b), e = breaks.get(Math.min(spans, b + step));
                for (int k = 0; k < perSpan; k++) {
                    out.add(a + (e - a) * k / perSpan);
                }
            }
            out.add(to);
            return out.stream().mapToDouble(Double::doubleValue).toArray();
        }

        double[] uv(double[] p, double[] guess) {
            if (guess != null) {
                double[] r = newton(p, guess[0], guess[1]);
                if (r[2] <= 1e-9 * size) {
                    return r;
                }
                guess = r;
            }
            double[] best = starts(p, guess, coarse);
            if (!(best[2] <= 1e-9 * size)) {
                if (fine == null) {
                    fine = grid(FINE_GRID); // a surface that folds fast: a finer grid of starts, made once
                }
                best = starts(p, best, fine);
            }
            return best;
        }

        /** Newton from the {@value STARTS} nearest points of {@code grid} in turn, until one converges; the best. */
        private double[] starts(double[] p, double[] best, double[][] grid) {
            double[] gridUv = grid[0], gridXyz = grid[1];
            int n = gridXyz.length / 3;
            double[] d2 = new double[n];
            Integer[] order = new Integer[n];
            for (int k = 0; k < n; k++) {
                double dx = gridXyz[3 * k] - p[0], dy = gridXyz[3 * k + 1] - p[1], dz = gridXyz[3 * k + 2] - p[2];
                d2[k] = dx * dx + dy * dy + dz * dz;
                order[k] = k;
            }
            java.util.Arrays.sort(order, (a, b) -> Double.compare(d2[a], d2[b]));
            for (int k = 0; k < Math.min(n, STARTS) && (best == null || best[2] > 1e-9 * size); k++) {
                double[] r = newton(p, gridUv[2 * order[k]], gridUv[2 * order[k] + 1]);
                if (best == null || r[2] < best[2]) {
                    best = r;
                }
            }
            return best;
        }

        private double[] newton(double[] p, double u, double v) {
            double hu = 1e-7 * (range[1] - range[0]), hv = 1e-7 * (range[3] - range[2]);
            double[] q = s.at(u, v);
            double dist = distance(p, q);
            for (int it = 0; it < 50 && dist > 0; it++) {
                double[] su = diff(u, v, hu, true), sv = diff(u, v, hv, false);
                double[] r = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
                double a = dot(su, su), b = dot(su, sv), c = dot(sv, sv), ru = dot(su, r), rv = dot(sv, r);
                double det = a * c - b * b;
                if (!(Math.abs(det) > 1e-300)) {
                    break;
                }
                double du = (c * ru - b * rv) / det, dv = (a * rv - b * ru) / det;
                double nu = u, nv = v, nd = dist;
                double[] nq = q;
                for (int half = 0; half < 30 && !(nd < dist); half++, du /= 2, dv /= 2) {
                    nu = Math.max(range[0], Math.min(range[1], u + du)); // a step too long is halved
                    nv = Math.max(range[2], Math.min(range[3], v + dv));
                    nq = s.at(nu, nv);
                    nd = distance(p, nq);
                }
                if (!(nd < dist)) {
                    break; // no more progress: rounding reached (or a step out of the range)
                }
                u = nu;
                v = nv;
                q = nq;
                dist = nd;
            }
            return new double[] {u, v, dist};
        }

        /** dS/du (or dS/dv) by central differences, one-sided at the range's edge. */
        private double[] diff(double u, double v, double h, boolean alongU) {
            double lo = alongU ? range[0] : range[2], hi = alongU ? range[1] : range[3], x = alongU ? u : v;
            double a = Math.max(lo, x - h), b = Math.min(hi, x + h);
            double[] pa = alongU ? s.at(a, v) : s.at(u, a), pb = alongU ? s.at(b, v) : s.at(u, b);
            return new double[] {(pb[0] - pa[0]) / (b - a), (pb[1] - pa[1]) / (b - a), (pb[2] - pa[2]) / (b - a)};
        }

        private static double dot(double[] a, double[] b) {
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        }

        private static double distance(double[] a, double[] b) {
            return Math.sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
        }
    }
}
