package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * A bounded plane (IGES entity 108, form 1: {@code Ax + By + Cz = D} inside a closed curve) as a
 * bilinear B-spline surface over the boundary's bounding rectangle in an orthonormal frame of
 * the plane, trimmed by the boundary mapped into that frame. The map from the plane to the frame
 * is affine, so the trim curve is the boundary exactly (to rounding).
 */
record IgesPlane(IgesSurface surface, TrimRegion trim) {

    static IgesPlane of(IgesParams p, int form, IgesEntities entities) {
        p.require(6, "A B C D PTR");
        if (form == 0 || p.pointer(5) == 0) {
            throw new IgesEntities.Skip("an unbounded plane");
        }
        if (form == -1) {
            throw new IgesEntities.Skip("a plane marked as a hole (form −1)");
        }
        double a = p.real(1), b = p.real(2), c = p.real(3), d = p.real(4);
        double len = Math.sqrt(a * a + b * b + c * c);
        if (!(len > 0)) {
            throw p.error("a plane with the normal (0, 0, 0)");
        }
        double[] n = {a / len, b / len, c / len};
        double[] origin = {n[0] * d / len, n[1] * d / len, n[2] * d / len};
        // e1 ⟂ n from the axis least aligned with n, e2 = n × e1
        double[] axis = Math.abs(n[0]) <= Math.abs(n[1]) && Math.abs(n[0]) <= Math.abs(n[2]) ? new double[] {1, 0, 0}
                : Math.abs(n[1]) <= Math.abs(n[2]) ? new double[] {0, 1, 0} : new double[] {0, 0, 1};
        double[] e1 = unit(cross(axis, n)), e2 = cross(n, e1);
        IgesSections.Entry boundary = entities.entry(p.pointer(5), p, "the boundary", 100, 102, 110, 126);
        List<IgesCurve> inPlane = new ArrayList<>();
        double s0 = Double.POSITIVE_INFINITY, s1 = Double.NEGATIVE_INFINITY, t0 = s0, t1 = s1;
        for (IgesCurve curve : entities.curve(boundary, 0)) {
            double[] q = curve.points(), st = new double[q.length];
            for (int k = 0; k < q.length; k += 3) {
                double x = q[k] - origin[0], y = q[k + 1] - origin[1], z = q[k + 2] - origin[2];
                st[k] = x * e1[0] + y * e1[1] + z * e1[2];
                st[k + 1] = x * e2[0] + y * e2[1] + z * e2[2];
                s0 = Math.min(s0, st[k]);
                s1 = Math.max(s1, st[k]);
                t0 = Math.min(t0, st[k + 1]);
                t1 = Math.max(t1, st[k + 1]);
            }
            inPlane.add(new IgesCurve(curve.degree(), curve.knots(), st, curve.weights(), curve.t0(), curve.t1()));
        }
        if (!(s1 > s0 && t1 > t0)) {
            throw p.error("its boundary encloses no area");
        }
        double[] pts = new double[12];
        double[][] corners = {{s0, t0}, {s1, t0}, {s0, t1}, {s1, t1}};
        for (int k = 0; k < 4; k++) {
            for (int q = 0; q < 3; q++) {
                pts[3 * k + q] = origin[q] + corners[k][0] * e1[q] + corners[k][1] * e2[q];
            }
        }
        IgesSurface surface = new IgesSurface(1, 1, new double[] {s0, s0, s1, s1}, new double[] {t0, t0, t1, t1}, 2, 2,
                pts, null, new double[] {s0, s1, t0, t1}, true);
        List<TrimPiece> pieces = new ArrayList<>();
        for (IgesCurve curve : inPlane) {
            pieces.add(curve.toTrimPiece(false));
        }
        return new IgesPlane(surface, new TrimRegion(List.of(entities.loop(pieces, surface, p)), List.of()));
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] unit(double[] v) {
        double l = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / l, v[1] / l, v[2] / l};
    }
}
