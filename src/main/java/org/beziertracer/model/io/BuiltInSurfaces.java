package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * The built-in free-form models, built from their exact NURBS descriptions (L. Piegl, W. Tiller,
 * <i>The NURBS Book</i>, 2nd ed., §7.5 for the circle and §8.5 for surfaces of revolution):
 * <ul>
 *   <li>{@code sphere} — the unit sphere about the origin as one rational biquadratic B-spline,
 *       9×5 points, {@code u ∈ [0,4]} around the z axis and {@code v ∈ [0,2]} from the south to
 *       the north pole: 8 rational Bézier pieces whose pole edges collapse to points;</li>
 *   <li>{@code torus} — major radius 1, minor radius {@value #TORUS_MINOR}, about the z axis, as
 *       one rational biquadratic B-spline of 9×9 points: 16 pieces;</li>
 *   <li>{@code trimmed-plate} — a gently curved bicubic plate over {@code [-1.5,1.5]²} trimmed by a
 *       rounded rectangle (4 lines and 4 rational arcs: several curves in one loop) with three
 *       holes: a circle (a rational B-spline, clockwise), a triangle (a polyline) and a closed
 *       uniform cubic B-spline (unclamped).</li>
 * </ul>
 * Every circle is the exact rational one: 4 quarter arcs with weights {@code 1, √2/2, 1}.
 */
final class BuiltInSurfaces {
    private BuiltInSurfaces() {}

    /** Minor radius of the built-in torus. */
    static final double TORUS_MINOR = 0.35;

    private static final double H = Math.sqrt(0.5);
    /** Control points of the unit circle from (1,0) counter-clockwise, 9 points (the last = the first). */
    private static final double[] CIRCLE = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
    private static final double[] CIRCLE_KNOTS = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};

    private static double circleWeight(int k) {
        return k % 2 == 0 ? 1 : H;
    }

    static List<BezierPatch> sphere() {
        // the half circle from the south pole (0,-1) to the north pole (0,1) in the (radius, z) plane
        double[] profile = {0, -1, 1, -1, 1, 0, 1, 1, 0, 1};
        double[] profileWeights = {1, H, 1, H, 1};
        return revolve(profile, profileWeights, new double[] {0, 0, 0, 1, 1, 2, 2, 2}, 5);
    }

    static List<BezierPatch> torus() {
        double[] profile = new double[18];
        double[] weights = new double[9];
        for (int j = 0; j < 9; j++) {
            profile[2 * j] = 1 + TORUS_MINOR * CIRCLE[2 * j];
            profile[2 * j + 1] = TORUS_MINOR * CIRCLE[2 * j + 1];
            weights[j] = circleWeight(j);
        }
        return revolve(profile, weights, CIRCLE_KNOTS, 9);
    }

    /**
     * The surface of revolution about the z axis of a rational quadratic profile
     * {@code (radius, z)}: {@code P_ij = (r_j·c_i, r_j·s_i, z_j)}, {@code w_ij = w_i·w_j} with
     * {@code (c_i, s_i, w_i)} the unit circle.
     */
    private static List<BezierPatch> revolve(double[] profile, double[] profileWeights, double[] knotsV, int countV) {
        double[] pts = new double[3 * 9 * countV];
        double[] w = new double[9 * countV];
        for (int j = 0; j < countV; j++) {
            for (int i = 0; i < 9; i++) {
                int k = j * 9 + i;
                pts[3 * k] = profile[2 * j] * CIRCLE[2 * i];
                pts[3 * k + 1] = profile[2 * j] * CIRCLE[2 * i + 1];
                pts[3 * k + 2] = profile[2 * j + 1];
                w[k] = circleWeight(i) * profileWeights[j];
            }
        }
        double vEnd = knotsV[knotsV.length - 1];
        return new FreeFormSurface(SplineBasis.BSPLINE, 2, 2, CIRCLE_KNOTS, knotsV, 9, countV, pts, w,
                new double[] {0, 4, 0, vEnd}, null).toPatches();
    }

    static List<BezierPatch> trimmedPlate() {
        double[] pts = new double[48];
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                int k = 3 * (4 * j + i);
                double x = -1.5 + i, y = -1.5 + j;
                pts[k] = x;
                pts[k + 1] = y;
                pts[k + 2] = 0.12 * (x * x - 0.5 * y * y) + 0.1 * x * y;
            }
        }
        TrimRegion trim = new TrimRegion(List.of(roundedRectangle(0.04, 0.96, 0.12)),
                List.of(TrimLoop.circle(0.3, 0.68, 0.16, false), TrimLoop.polygon(0.62, 0.55, 0.86, 0.6, 0.7, 0.86),
                        blob()));
        double[] parm = {0, 1};
        return new FreeFormSurface(SplineBasis.BEZIER, 3, 3, parm, parm, 4, 4, pts, null,
                new double[] {0, 1, 0, 1}, trim).toPatches();
    }

    /** The square {@code [lo,hi]²} with corners rounded to radius {@code r}: 4 lines and 4 rational arcs. */
    private static TrimLoop roundedRectangle(double lo, double hi, double r) {
        double a = lo + r, b = hi - r;
        List<TrimPiece> pieces = new ArrayList<>();
        pieces.add(line(a, lo, b, lo));
        pieces.add(arc(b, lo, hi, lo, hi, a));
        pieces.add(line(hi, a, hi, b));
        pieces.add(arc(hi, b, hi, hi, b, hi));
        pieces.add(line(b, hi, a, hi));
        pieces.add(arc(a, hi, lo, hi, lo, b));
        pieces.add(line(lo, b, lo, a));
        pieces.add(arc(lo, a, lo, lo, a, lo));
        return new TrimLoop(pieces);
    }

    private static TrimPiece line(double u0, double v0, double u1, double v1) {
        return new TrimPiece(new TrimCurve(SplineBasis.BEZIER, 1, new double[] {0, 1},
                new double[] {u0, v0, u1, v1}, null), 0, 1);
    }

    /** A quarter circle as a rational quadratic Bézier curve with the given corner point. */
    private static TrimPiece arc(double u0, double v0, double cu, double cv, double u1, double v1) {
        return new TrimPiece(new TrimCurve(SplineBasis.BEZIER, 2, new double[] {0, 1},
                new double[] {u0, v0, cu, cv, u1, v1}, new double[] {1, H, 1}), 0, 1);
    }

    /** A closed uniform (unclamped) cubic B-spline: 6 points, the first 3 repeated at the end. */
    private static TrimLoop blob() {
        double[] ring = {0.5, 0.18, 0.72, 0.2, 0.8, 0.34, 0.62, 0.44, 0.42, 0.4, 0.36, 0.26};
        int count = ring.length / 2 + 3;
        double[] pts = new double[2 * count];
        for (int k = 0; k < count; k++) {
            pts[2 * k] = ring[(2 * k) % ring.length];
            pts[2 * k + 1] = ring[(2 * k + 1) % ring.length];
        }
        double[] knots = new double[count + 4];
        for (int k = 0; k < knots.length; k++) {
            knots[k] = k;
        }
        return new TrimLoop(List.of(new TrimPiece(new TrimCurve(SplineBasis.BSPLINE, 3, knots, pts, null), 3, count)));
    }
}
