package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

class TrimCurvesTest {

    private final double[] scratch = new double[TrimCurves.SCRATCH_LENGTH];

    /** Square [0.1,0.9]² with a circular hole (centre (0.5,0.5), radius 0.2) and a triangular hole. */
    private static TrimRegion plate(boolean ccw) {
        TrimLoop outer = ccw ? TrimShapes.polygon(0.1, 0.1, 0.9, 0.1, 0.9, 0.9, 0.1, 0.9)
                : TrimShapes.polygon(0.1, 0.1, 0.1, 0.9, 0.9, 0.9, 0.9, 0.1);
        TrimLoop triangle = ccw ? TrimShapes.polygonOfEdges(0.15, 0.15, 0.3, 0.15, 0.15, 0.3)
                : TrimShapes.polygonOfEdges(0.15, 0.15, 0.15, 0.3, 0.3, 0.15);
        return new TrimRegion(List.of(outer), List.of(TrimShapes.circle(0.5, 0.5, 0.2, ccw), triangle));
    }

    private static boolean expected(double u, double v) {
        boolean inSquare = u > 0.1 && u < 0.9 && v > 0.1 && v < 0.9;
        boolean inCircle = Math.hypot(u - 0.5, v - 0.5) < 0.2;
        boolean inTriangle = u > 0.15 && v > 0.15 && u + v < 0.45;
        return inSquare && !inCircle && !inTriangle;
    }

    @Test
    void randomPointsAgreeWithTheExactShapesWhateverTheOrientation() {
        TrimCurves ccw = TrimCurves.of(plate(true)), cw = TrimCurves.of(plate(false));
        Random rnd = new Random(41);
        for (int k = 0; k < 20_000; k++) {
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            boolean want = expected(u, v);
            assertEquals(want, ccw.contains(u, v, scratch), "ccw at (" + u + ", " + v + ")");
            assertEquals(want, cw.contains(u, v, scratch), "cw at (" + u + ", " + v + ")");
        }
    }

    @Test
    void pointsWithinAFewTimes1e10OfTheCircleDecideAsTheExactCircleDoes() {
        TrimCurves t = TrimCurves.of(plate(true));
        Random rnd = new Random(42);
        for (int k = 0; k < 5_000; k++) {
            double angle = 2 * Math.PI * rnd.nextDouble();
            double offset = (rnd.nextBoolean() ? 1 : -1) * (2e-10 + 8e-10 * rnd.nextDouble());
            double r = 0.2 + offset;
            double u = 0.5 + r * Math.cos(angle), v = 0.5 + r * Math.sin(angle);
            boolean outsideHole = Math.hypot(u - 0.5, v - 0.5) > 0.2;
            assertEquals(outsideHole, t.contains(u, v, scratch), "at angle " + angle + ", offset " + offset);
        }
    }

    @Test
    void pointsWithin1e9OfAStraightEdgeDecideAsTheEdgeDoes() {
        TrimCurves t = TrimCurves.of(plate(true));
        for (double s = 0.2; s < 0.85; s += 0.01) {
            assertTrue(t.contains(0.9 - 1e-9, s, scratch), "just inside the right edge at v=" + s);
            assertFalse(t.contains(0.9 + 1e-9, s, scratch), "just outside the right edge at v=" + s);
            assertTrue(t.contains(s, 0.1 + 1e-9, scratch) || expected(s, 0.1 + 1e-9) == false);
        }
    }

    @Test
    void aLoopOfSeveralCurvesRunBackwardsIsTheSameLoop() {
        // the circle as two half arcs, both run from their end to their start (clockwise)
        TrimLoop whole = TrimShapes.circle(0.5, 0.5, 0.3, true);
        TrimCurve c = whole.pieces().get(0).curve();
        TrimLoop halves = new TrimLoop(List.of(new TrimPiece(c, 2, 0), new TrimPiece(c, 4, 2)));
        TrimCurves a = TrimCurves.of(new TrimRegion(List.of(whole), List.of()));
        TrimCurves b = TrimCurves.of(new TrimRegion(List.of(halves), List.of()));
        Random rnd = new Random(43);
        for (int k = 0; k < 2_000; k++) {
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            assertEquals(a.contains(u, v, scratch), b.contains(u, v, scratch), "at (" + u + ", " + v + ")");
        }
    }

    @Test
    void boxesAreClassifiedConservatively() {
        TrimCurves t = TrimCurves.of(plate(true));
        assertEquals(TrimCurves.OUTSIDE, t.classify(0, 0.05, 0, 0.05, scratch));
        assertEquals(TrimCurves.OUTSIDE, t.classify(0.45, 0.55, 0.45, 0.55, scratch)); // inside the hole
        assertEquals(TrimCurves.INSIDE, t.classify(0.75, 0.85, 0.2, 0.3, scratch));
        assertEquals(TrimCurves.MIXED, t.classify(0.6, 0.8, 0.4, 0.6, scratch)); // the circle crosses it
        Random rnd = new Random(44);
        int decided = 0;
        for (int k = 0; k < 2_000; k++) {
            double u0 = rnd.nextDouble(), v0 = rnd.nextDouble(), size = 0.2 * rnd.nextDouble();
            int c = t.classify(u0, u0 + size, v0, v0 + size, scratch);
            if (c == TrimCurves.MIXED) {
                continue;
            }
            decided++;
            for (int s = 0; s < 50; s++) {
                double u = u0 + size * rnd.nextDouble(), v = v0 + size * rnd.nextDouble();
                assertEquals(c == TrimCurves.INSIDE, expected(u, v), "box at (" + u0 + ", " + v0 + ") size " + size);
            }
        }
        assertTrue(decided > 500, "most small boxes are decided, got " + decided);
    }

    @Test
    void withoutOuterLoopsTheWholeDomainMinusTheHolesIsKept() {
        TrimCurves t = TrimCurves.of(new TrimRegion(List.of(), List.of(TrimShapes.circle(0, 0, 1, false))));
        assertFalse(t.contains(0.5, 0.5, scratch));
        assertTrue(t.contains(1.5, 0.5, scratch));
        assertTrue(t.contains(-7, 3, scratch));
    }

    @Test
    void aRationalBezierQuarterArcKeepsItsExactShape() {
        // a quarter disc: two straight edges and the rational quadratic arc from (1,0) to (0,1)
        TrimCurve arc = new TrimCurve(SplineBasis.BEZIER, 2, new double[] {0, 1}, new double[] {1, 0, 1, 1, 0, 1},
                new double[] {1, TrimShapes.H, 1});
        TrimCurve edges = new TrimCurve(SplineBasis.BSPLINE, 1, new double[] {0, 0, 1, 2, 2},
                new double[] {0, 1, 0, 0, 1, 0}, null);
        TrimCurves t = TrimCurves.of(new TrimRegion(List.of(new TrimLoop(
                List.of(new TrimPiece(arc, 0, 1), new TrimPiece(edges, 0, 2)))), List.of()));
        Random rnd = new Random(45);
        for (int k = 0; k < 5_000; k++) {
            double angle = 0.5 * Math.PI * rnd.nextDouble(), r = 1 + (rnd.nextBoolean() ? 1 : -1) * 1e-9;
            assertEquals(r < 1, t.contains(r * Math.cos(angle), r * Math.sin(angle), scratch), "angle " + angle);
        }
    }

    @Test
    void aPointOnACurveIsDecidedAsThePointAStepTowardTheChosenSide() {
        // the square [0,1]² as the loop (the domain's border), with a curved edge on top for the subdivision path
        TrimCurves square = TrimCurves.of(new TrimRegion(List.of(TrimShapes.polygon(0, 0, 1, 0, 1, 1, 0, 1)), List.of()));
        TrimCurves circle = TrimCurves.of(new TrimRegion(List.of(TrimShapes.circle(0.5, 0.5, 0.5, true)), List.of()));
        Random rnd = new Random(43);
        for (int r = 0; r < 200; r++) {
            double f = 0.01 + 0.98 * rnd.nextDouble();
            String at = " at " + f;
            // left and bottom edges: inside a step toward +u / +v (the default), outside a step back
            assertTrue(square.contains(0, f, scratch), "left edge" + at);
            assertFalse(square.contains(0, f, true, false, scratch), "left edge, a step toward -u" + at);
            assertTrue(square.contains(f, 0, scratch), "bottom edge" + at);
            assertFalse(square.contains(f, 0, false, true, scratch), "bottom edge, a step toward -v" + at);
            // right and top edges: outside by default, inside a step back
            assertFalse(square.contains(1, f, scratch), "right edge" + at);
            assertTrue(square.contains(1, f, true, false, scratch), "right edge, a step toward -u" + at);
            assertFalse(square.contains(f, 1, scratch), "top edge" + at);
            assertTrue(square.contains(f, 1, false, true, scratch), "top edge, a step toward -v" + at);
        }
        // corners: (1,1) belongs to the square only a step toward -u and -v
        assertTrue(square.contains(1, 1, true, true, scratch));
        assertFalse(square.contains(1, 1, true, false, scratch));
        assertFalse(square.contains(1, 1, false, true, scratch));
        // the circle's rightmost and topmost points (exact in its control points)
        assertFalse(circle.contains(1, 0.5, scratch));
        assertTrue(circle.contains(1, 0.5, true, false, scratch));
        assertFalse(circle.contains(0.5, 1, scratch));
        assertTrue(circle.contains(0.5, 1, false, true, scratch));
    }
}
