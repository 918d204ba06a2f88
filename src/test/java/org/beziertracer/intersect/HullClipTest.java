package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * {@link HullClip#zeroInterval}: where the convex hull of the columns {@code (c/deg, [lo[c], hi[c]])}
 * meets the axis, against a brute force over every pair of control points.
 */
class HullClipTest {

    /**
     * The hull meets zero exactly on the smallest interval that holds every crossing of a
     * segment between two of its points of opposite sign (a column straddling zero crosses at
     * its own x): {@code {a, b}}, or null when no segment crosses.
     */
    static double[] bruteForce(double[] lo, double[] hi, int deg) {
        double a = Double.POSITIVE_INFINITY, b = Double.NEGATIVE_INFINITY;
        for (int c = 0; c <= 2 * deg + 1; c++) {
            for (int e = 0; e <= 2 * deg + 1; e++) {
                double yc = (c % 2 == 0 ? lo : hi)[c / 2], ye = (e % 2 == 0 ? lo : hi)[e / 2];
                if (yc > 0 && ye <= 0) {
                    double xc = (c / 2) / (double) deg, xe = (e / 2) / (double) deg;
                    double x = xc + (xe - xc) * (yc / (yc - ye));
                    a = Math.min(a, x);
                    b = Math.max(b, x);
                }
            }
        }
        return a <= b ? new double[] {a, b} : null;
    }

    /** Random columns: each a range around a random centre, a few forced to straddle zero. */
    static void randomColumns(Random rnd, int deg, double[] lo, double[] hi) {
        double shift = 2 * rnd.nextGaussian();
        for (int c = 0; c <= deg; c++) {
            double centre = shift + rnd.nextGaussian();
            double half = rnd.nextDouble() < 0.3 ? 0 : 0.5 * rnd.nextDouble();
            lo[c] = centre - half;
            hi[c] = centre + half;
        }
    }

    @Test
    void theIntervalIsWhereTheHullMeetsZero() {
        Random rnd = new Random(1990);
        double[] lo = new double[16], hi = new double[16], out = new double[2];
        int meets = 0, misses = 0;
        for (int trial = 0; trial < 20000; trial++) {
            int deg = 1 + rnd.nextInt(15);
            randomColumns(rnd, deg, lo, hi);
            double[] expected = bruteForce(lo, hi, deg);
            boolean got = HullClip.zeroInterval(lo, hi, deg, 0, out);
            String where = "deg " + deg + " lo " + Arrays.toString(Arrays.copyOf(lo, deg + 1)) + " hi "
                    + Arrays.toString(Arrays.copyOf(hi, deg + 1));
            assertEquals(expected != null, got, "meets zero: " + where);
            if (got) {
                meets++;
                assertEquals(expected[0], out[0], ROUNDING, "left end: " + where);
                assertEquals(expected[1], out[1], ROUNDING, "right end: " + where);
                assertTrue(0 <= out[0] && out[0] <= out[1] && out[1] <= 1, "inside [0,1]: " + where);
            } else {
                misses++;
            }
        }
        assertTrue(meets > 5000 && misses > 5000, "both outcomes exercised: " + meets + " meet, " + misses + " miss");
    }

    @Test
    void aColumnWithinEpsOfZeroTouchesIt() {
        double[] lo = {1, 1e-13, 1, 1}, hi = {2, 2e-13, 2, 2}, out = new double[2];
        assertFalse(HullClip.zeroInterval(lo, hi, 3, 0, out), "strictly above zero without eps");
        assertTrue(HullClip.zeroInterval(lo, hi, 3, 1e-12, out), "touching within eps");
        assertEquals(1 / 3.0, out[0], ROUNDING);
        assertEquals(1 / 3.0, out[1], ROUNDING);
    }

    @Test
    void aLineCrossingZeroIsClippedToItsRoot() {
        // Distances of a straight line 1 - 4x at x = 0, 1/3, 2/3, 1: the hull is the line itself
        double[] d = {1, 1 - 4 / 3.0, 1 - 8 / 3.0, -3}, out = new double[2];
        assertTrue(HullClip.zeroInterval(d, d, 3, 0, out));
        assertEquals(0.25, out[0], ROUNDING);
        assertEquals(0.25, out[1], ROUNDING);
    }

    @Test
    void theEndsComeFromBothSidesOfTheHull() {
        // Above zero at both ends, one column dipping below in the middle: two crossings
        double[] lo = {1, -1, 1}, hi = {1, -1, 1}, out = new double[2];
        assertTrue(HullClip.zeroInterval(lo, hi, 2, 0, out));
        assertEquals(0.25, out[0], ROUNDING);
        assertEquals(0.75, out[1], ROUNDING);
        // Below zero at the left end: the upper hull is walked from there
        double[] lo2 = {-2, -2, 2}, hi2 = {-1, 2, 3};
        assertTrue(HullClip.zeroInterval(lo2, hi2, 2, 0, out));
        assertEquals(1 / 6.0, out[0], ROUNDING, "column 0's top (-1) to column 1's top (2)");
        assertEquals(0.75, out[1], ROUNDING, "column 2's bottom (2) to column 1's bottom (-2)");
    }

    /** A column exactly {@code eps} from zero, above or below, touches it; and only column 0 may touch. */
    @Test
    void aColumnExactlyEpsAwayTouches() {
        double[] out = new double[2];
        // the middle column's bottom is exactly eps above zero; the others lie far above
        assertTrue(HullClip.zeroInterval(new double[] {0.5, 0.25, 0.7}, new double[] {0.6, 0.35, 0.8}, 2, 0.25, out));
        assertArrayEquals(new double[] {0.5, 0.5}, out, ROUNDING);
        // ... its top exactly eps below zero, the others far below
        assertTrue(HullClip.zeroInterval(new double[] {-0.6, -0.35, -0.8}, new double[] {-0.5, -0.25, -0.7}, 2, 0.25, out));
        assertArrayEquals(new double[] {0.5, 0.5}, out, ROUNDING);
        // only the first column touches: the interval is [0, 0]
        assertTrue(HullClip.zeroInterval(new double[] {0.1, 1, 2}, new double[] {0.2, 1.1, 2.1}, 2, 0.15, out));
        assertArrayEquals(new double[] {0, 0}, out, ROUNDING);
        // only the last one: [1, 1]
        assertTrue(HullClip.zeroInterval(new double[] {2, 1, 0.1}, new double[] {2.1, 1.1, 0.2}, 2, 0.15, out));
        assertArrayEquals(new double[] {1, 1}, out, ROUNDING);
        // the last column straddles zero, the one before lies below: the interval stops at 1
        assertTrue(HullClip.zeroInterval(new double[] {1, -1, -0.3}, new double[] {1, -1, 0.3}, 2, 0, out));
        assertEquals(0.25, out[0], ROUNDING);
        assertEquals(1, out[1], 0);
    }
}
