package org.beziertracer.math;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

class BezierDecompositionTest {

    /** Bézier pieces against the Cox–de Boor sum, relative to the largest control coordinate. */
    private static final double REPRODUCTION_REL = org.beziertracer.Tolerances.ROUNDING;

    @Test
    void piecesReproduceRandomCurvesWithMultiplicitiesClampedOrNot() {
        Random rnd = new Random(11);
        for (int trial = 0; trial < 300; trial++) {
            int p = 1 + rnd.nextInt(7), count = p + 1 + rnd.nextInt(9), dim = 1 + rnd.nextInt(4);
            boolean clamped = rnd.nextBoolean();
            double[] knots = SplineReference.randomKnots(rnd, p, count, clamped);
            double[] points = randomPoints(rnd, count * dim);
            double lo = KnotVector.start(p, knots), hi = KnotVector.end(p, knots);
            BezierDecomposition.Segments s = BezierDecomposition.curve(p, knots, points, dim, lo, hi);
            assertEquals(lo, s.breaks()[0]);
            assertEquals(hi, s.breaks()[s.count()]);
            for (int sample = 0; sample < 20; sample++) {
                double t = SplineReference.inside(rnd, lo, hi);
                double[] expected = SplineReference.curve(knots, p, points, dim, t);
                double[] actual = bezierAt(s, t);
                int tr = trial;
                assertTrue(maxDiff(expected, actual) <= REPRODUCTION_REL * 10,
                        () -> "trial " + tr + " degree " + p + " knots " + SplineReference.text(knots) + " at " + t);
            }
        }
    }

    @Test
    void aSubRangeIsCutAtItsEnds() {
        Random rnd = new Random(12);
        for (int trial = 0; trial < 100; trial++) {
            int p = 1 + rnd.nextInt(5), count = p + 1 + rnd.nextInt(6);
            double[] knots = SplineReference.randomKnots(rnd, p, count, rnd.nextBoolean());
            double[] points = randomPoints(rnd, count * 2);
            double lo = KnotVector.start(p, knots), hi = KnotVector.end(p, knots);
            double a = SplineReference.inside(rnd, lo, hi), b = SplineReference.inside(rnd, a, hi);
            BezierDecomposition.Segments s = BezierDecomposition.curve(p, knots, points, 2, a, b);
            assertEquals(a, s.breaks()[0]);
            assertEquals(b, s.breaks()[s.count()]);
            double[] start = SplineReference.curve(knots, p, points, 2, a);
            assertArrayEquals(start, new double[] {s.points()[0], s.points()[1]}, REPRODUCTION_REL * 10);
        }
    }

    @Test
    void aBezierFormKnotVectorGivesItsPointsBackBitForBit() {
        double[] knots = {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2};
        double[] points = randomPoints(new Random(13), 7 * 3);
        BezierDecomposition.Segments s = BezierDecomposition.curve(3, knots, points, 3, 0, 2);
        assertEquals(2, s.count());
        assertArrayEquals(java.util.Arrays.copyOfRange(points, 0, 12), java.util.Arrays.copyOfRange(s.points(), 0, 12));
        assertArrayEquals(java.util.Arrays.copyOfRange(points, 9, 21), java.util.Arrays.copyOfRange(s.points(), 12, 24));
    }

    @Test
    void surfacePiecesAreOrderedUFastestWithTheirBreaks() {
        // bilinear B-spline, 3x2 points: two pieces in u, one in v
        double[] ku = {0, 0, 1, 2, 2}, kv = {0, 0, 1, 1};
        double[] pts = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1};
        BezierDecomposition.Patches p = BezierDecomposition.surface(1, 1, ku, kv, 3, 2, pts, 2, 0, 2, 0, 1);
        assertEquals(2, p.countU());
        assertEquals(1, p.countV());
        assertArrayEquals(new double[] {0, 0, 1, 0, 0, 1, 1, 1}, p.nets()[0]);
        assertArrayEquals(new double[] {1, 0, 2, 0, 1, 1, 2, 1}, p.nets()[1]);
    }

    @Test
    void aRangeOutsideTheKnotsIsRefused() {
        double[] knots = {0, 0, 1, 1};
        assertThrows(IllegalArgumentException.class,
                () -> BezierDecomposition.curve(1, knots, new double[] {0, 1}, 1, -0.5, 1));
    }

    @Test
    void knotVectorProblemsAreNamed() {
        assertNull(KnotVector.problem(2, new double[] {0, 0, 0, 1, 1, 1}, 3));
        assertTrue(KnotVector.problem(2, new double[] {0, 0, 0, 1, 1}, 3).startsWith("expected 6 knots"));
        assertTrue(KnotVector.problem(2, new double[] {0, 0, 1, 0.5, 1, 1}, 3).contains("never decrease"));
        assertTrue(KnotVector.problem(1, new double[] {0, 0, 0, 1}, 2).contains("at most degree + 1 = 2 times"));
        assertTrue(KnotVector.problem(1, new double[] {0, 1, 1, 2}, 2).contains("non-empty parameter range"));
    }

    private static double[] randomPoints(Random rnd, int length) {
        double[] p = new double[length];
        for (int k = 0; k < length; k++) {
            p[k] = 10 * rnd.nextDouble() - 5;
        }
        return p;
    }

    /** Evaluates the piece holding {@code t} by the Bernstein sum. */
    private static double[] bezierAt(BezierDecomposition.Segments s, double t) {
        int k = 0;
        while (k + 1 < s.count() && t >= s.breaks()[k + 1]) {
            k++;
        }
        double a = s.breaks()[k], b = s.breaks()[k + 1], x = (t - a) / (b - a);
        int p = s.degree(), dim = s.dim();
        double[] out = new double[dim];
        for (int i = 0; i <= p; i++) {
            double binom = 1;
            for (int r = 1; r <= i; r++) {
                binom = binom * (p - i + r) / r;
            }
            double bern = binom * Math.pow(x, i) * Math.pow(1 - x, p - i);
            for (int c = 0; c < dim; c++) {
                out[c] += bern * s.points()[s.offset(k) + i * dim + c];
            }
        }
        return out;
    }

    private static double maxDiff(double[] a, double[] b) {
        double d = 0;
        for (int k = 0; k < a.length; k++) {
            d = Math.max(d, Math.abs(a[k] - b[k]));
        }
        return d;
    }

    @Test
    void aSurfaceThatIsOneBezierNetComesBackAsItsOwnNetLikeTheInsertionsGive() {
        Random rnd = new Random(53);
        for (int n = 0; n < 200; n++) {
            int p = 1 + rnd.nextInt(9), q = 1 + rnd.nextInt(9), dim = 3 + rnd.nextInt(2);
            double u0 = rnd.nextGaussian(), u1 = u0 + 0.1 + rnd.nextDouble();
            double v0 = rnd.nextGaussian(), v1 = v0 + 0.1 + rnd.nextDouble();
            double[] ku = bezierKnots(p, u0, u1), kv = bezierKnots(q, v0, v1);
            double[] pts = new double[(p + 1) * (q + 1) * dim];
            for (int k = 0; k < pts.length; k++) {
                pts[k] = 10 * rnd.nextGaussian();
            }
            assertTrue(BezierDecomposition.onePiece(p, ku, p + 1, u0, u1));
            BezierDecomposition.Patches fast = BezierDecomposition.surface(p, q, ku, kv, p + 1, q + 1, pts, dim, u0, u1, v0, v1);
            BezierDecomposition.Patches slow = BezierDecomposition.byInsertion(p, q, ku, kv, p + 1, q + 1, pts, dim, u0, u1, v0, v1);
            assertEquals(1, fast.nets().length);
            assertArrayEquals(slow.nets()[0], fast.nets()[0]);
            assertArrayEquals(pts, fast.nets()[0]);
            assertArrayEquals(slow.breaksU(), fast.breaksU());
            assertArrayEquals(slow.breaksV(), fast.breaksV());
        }
    }

    @Test
    void onlyBezierKnotsOverTheWholeRangeAreOnePiece() {
        assertTrue(BezierDecomposition.onePiece(3, new double[] {0, 0, 0, 0, 1, 1, 1, 1}, 4, 0, 1));
        assertEquals(false, BezierDecomposition.onePiece(3, new double[] {0, 0, 0, 0, 1, 1, 1, 1}, 4, 0, 0.5));
        assertEquals(false, BezierDecomposition.onePiece(3, new double[] {0, 0, 0, 0.5, 1, 1, 1, 1}, 5, 0, 1));
        assertEquals(false, BezierDecomposition.onePiece(2, new double[] {0, 0, 0, 1, 1, 2}, 3, 0, 1));
    }

    private static double[] bezierKnots(int degree, double from, double to) {
        double[] k = new double[2 * degree + 2];
        for (int i = 0; i < k.length; i++) {
            k[i] = i <= degree ? from : to;
        }
        return k;
    }
}
