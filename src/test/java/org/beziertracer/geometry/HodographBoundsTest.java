package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

class HodographBoundsTest {
    private static final double EPS = 1e-9;

    private static double[] bounds(double[] net, int n, int m) {
        double[] out = new double[HodographBounds.STRIDE + 2];
        HodographBounds.compute(net, 0, n, m, out, 2, new double[6]);
        return out;
    }

    private static double dist(double[] p, int i, double[] c, int j) {
        double dx = p[i] - c[j], dy = p[i + 1] - c[j + 1], dz = p[i + 2] - c[j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Test
    void derivativesDividedByTheDegreeStayInTheirBallsEverywhere() {
        Random rnd = new Random(20261202L);
        double[] d = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < 200; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            double[] net = TestNets.randomNet(rnd, n, m, 3, 10);
            double[] b = bounds(net, n, m);
            double la = Math.sqrt(b[2] * b[2] + b[3] * b[3] + b[4] * b[4]);
            double lb = Math.sqrt(b[5] * b[5] + b[6] * b[6] + b[7] * b[7]);
            assertEquals(1e-10 * (la + b[8]) * (lb + b[9]), b[10], 1e-12 * b[10], "rounding margin, trial " + trial);
            for (int s = 0; s < 30; s++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, d, scratch);
                double[] su = {d[3] / n, d[4] / n, d[5] / n}, sv = {d[6] / m, d[7] / m, d[8] / m};
                String at = TestNets.degrees(n, m, 3) + " at (" + u + ", " + v + "), trial " + trial;
                assertTrue(dist(su, 0, b, 2) <= b[2 + 6] + EPS, "Su/n outside its ball, " + at);
                assertTrue(dist(sv, 0, b, 5) <= b[2 + 7] + EPS, "Sv/m outside its ball, " + at);
            }
        }
    }

    @Test
    void ballsAreCentredOnTheDifferencesBoxAndTouchTheFarthestDifference() {
        // Bilinear net (n = m = 1): u-differences (2,0,0) and (4,0,2); v-differences (0,3,0) and (2,3,2).
        double[] net = {0, 0, 0, 2, 0, 0, 0, 3, 0, 4, 3, 2};
        double[] b = bounds(net, 1, 1);
        assertArrayEquals(new double[] {3, 0, 1, 1, 3, 1}, java.util.Arrays.copyOfRange(b, 2, 8), EPS);
        assertEquals(Math.sqrt(2), b[2 + 6], EPS, "ra");
        assertEquals(Math.sqrt(2), b[2 + 7], EPS, "rb");
        double la = Math.sqrt(10), lb = Math.sqrt(11);
        assertEquals(1e-10 * (la + Math.sqrt(2)) * (lb + Math.sqrt(2)), b[2 + 8], 1e-22, "rounding margin");
        assertEquals(0, b[0], "nothing written before the offset");
        assertEquals(0, b[1]);
    }

    @Test
    void aTranslatedNetHasTheSameBounds() {
        Random rnd = new Random(7);
        double[] net = TestNets.randomNet(rnd, 3, 2, 3, 5), moved = net.clone();
        for (int k = 0; k < moved.length; k++) {
            moved[k] += 100 * (k % 3 + 1);
        }
        double[] a = bounds(net, 3, 2), b = bounds(moved, 3, 2);
        assertArrayEquals(java.util.Arrays.copyOf(a, 10), java.util.Arrays.copyOf(b, 10), 1e-9);
    }
}
