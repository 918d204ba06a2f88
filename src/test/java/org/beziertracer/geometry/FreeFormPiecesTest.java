package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.math.KnotVector;
import org.beziertracer.math.SplineReference;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.SplineBasis;
import org.junit.jupiter.api.Test;

/** Knot insertion turns B-spline and NURBS surfaces into Bézier pieces that reproduce them. */
class FreeFormPiecesTest {

    /** Pieces against the Cox–de Boor surface, relative to the largest control coordinate. */
    private static final double REPRODUCTION_REL = org.beziertracer.Tolerances.ROUNDING;
    private static final int SURFACES = 40;
    private static final int SAMPLES_PER_SURFACE = 25; // 1,000 (u,v) in all

    @Test
    void piecesReproduceRandomBSplineAndNurbsSurfacesAtAThousandPoints() {
        Random rnd = new Random(31);
        int checked = 0;
        for (int s = 0; s < SURFACES; s++) {
            int p = 1 + rnd.nextInt(5), q = 1 + rnd.nextInt(5);
            int cu = p + 1 + rnd.nextInt(6), cv = q + 1 + rnd.nextInt(6);
            double[] ku = SplineReference.randomKnots(rnd, p, cu, rnd.nextBoolean());
            double[] kv = SplineReference.randomKnots(rnd, q, cv, rnd.nextBoolean());
            boolean rational = s % 2 == 1;
            double[] pts = TestNets.randomNet(rnd, cu - 1, cv - 1, 3, 10);
            double[] w = rational ? weights(rnd, cu * cv) : null;
            double[] range = {KnotVector.start(p, ku), KnotVector.end(p, ku), KnotVector.start(q, kv), KnotVector.end(q, kv)};
            FreeFormSurface surface = new FreeFormSurface(SplineBasis.BSPLINE, p, q, ku, kv, cu, cv, pts, w, range, null);
            List<BezierPatch> pieces = surface.toPatches();
            double[] homogeneous = homogeneous(pts, w);
            for (int k = 0; k < SAMPLES_PER_SURFACE; k++) {
                double u = SplineReference.inside(rnd, range[0], range[1]);
                double v = SplineReference.inside(rnd, range[2], range[3]);
                double[] h = SplineReference.surface(ku, p, kv, q, cu, cv, homogeneous, 4, u, v);
                Vec3 actual = at(pieces, u, v);
                double err = Math.max(Math.abs(actual.x() - h[0] / h[3]),
                        Math.max(Math.abs(actual.y() - h[1] / h[3]), Math.abs(actual.z() - h[2] / h[3])));
                int ss = s;
                assertTrue(err <= REPRODUCTION_REL * 10, () -> "surface " + ss + " degree " + p + "x" + q + " knots u "
                        + SplineReference.text(ku) + " v " + SplineReference.text(kv) + " at (" + u + "," + v + "): " + err);
                checked++;
            }
        }
        assertEquals(1000, checked);
    }

    @Test
    void piecesReportTheirBoxInTheKnotRangeAndTheirOrigin() {
        double[] ku = {0, 0, 0, 1, 2, 2, 2}, kv = {5, 5, 6, 6};
        double[] pts = TestNets.randomNet(new Random(32), 3, 1, 3, 1);
        FreeFormSurface s = new FreeFormSurface(SplineBasis.BSPLINE, 2, 1, ku, kv, 4, 2, pts, null,
                new double[] {0, 2, 5, 6}, null);
        List<BezierPatch> pieces = s.toPatches();
        assertEquals(2, pieces.size());
        assertEquals(new PatchDomain(0, 1, 5, 6, null), pieces.get(0).domain());
        assertEquals(new PatchDomain(1, 2, 5, 6, null), pieces.get(1).domain());
        assertSame(s, pieces.get(1).origin().surface());
        assertEquals(1, pieces.get(1).origin().piece());
        assertNull(pieces.get(0).weights());
    }

    @Test
    void aRationalSurfaceWithUnitWeightsGivesPolynomialPiecesBitForBit() {
        double[] parm = {0, 1};
        double[] pts = TestNets.randomNet(new Random(33), 3, 3, 3, 5);
        double[] ones = new double[16];
        java.util.Arrays.fill(ones, 1);
        FreeFormSurface rat = new FreeFormSurface(SplineBasis.BEZIER, 3, 3, parm, parm, 4, 4, pts, ones,
                new double[] {0, 1, 0, 1}, null);
        BezierPatch piece = rat.toPatches().get(0);
        assertEquals(new BezierPatch(3, 3, pts), piece);
        assertNull(piece.weights());
    }

    private static double[] weights(Random rnd, int count) {
        double[] w = new double[count];
        for (int k = 0; k < count; k++) {
            w[k] = 0.3 + 2 * rnd.nextDouble();
        }
        return w;
    }

    private static double[] homogeneous(double[] pts, double[] w) {
        int count = pts.length / 3;
        double[] h = new double[4 * count];
        for (int k = 0; k < count; k++) {
            double wk = w == null ? 1 : w[k];
            h[4 * k] = wk * pts[3 * k];
            h[4 * k + 1] = wk * pts[3 * k + 1];
            h[4 * k + 2] = wk * pts[3 * k + 2];
            h[4 * k + 3] = wk;
        }
        return h;
    }

    /** The surface point at surface parameters (u,v), from the piece whose domain holds them. */
    static Vec3 at(List<BezierPatch> pieces, double u, double v) {
        for (BezierPatch b : pieces) {
            PatchDomain d = b.domain();
            if (u >= d.u0() && u <= d.u1() && v >= d.v0() && v <= d.v1()) {
                return Patches.evaluate(b, (u - d.u0()) / (d.u1() - d.u0()), (v - d.v0()) / (d.v1() - d.v0()));
            }
        }
        throw new AssertionError("no piece holds (" + u + ", " + v + ")");
    }
}
