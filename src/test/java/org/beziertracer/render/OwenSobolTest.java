package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The Sobol points against the published sequence, the net property after scrambling and
 * shuffling, and the uniformity of one point over seeds (the estimate stays unbiased).
 */
class OwenSobolTest {

    @Test
    void unscrambledPointsAreSobolsPublishedOnes() {
        // the first eight points of the 2-D Sobol sequence (Joe & Kuo's tables; Bratley & Fox 1988)
        double[][] expected = {{0, 0}, {0.5, 0.5}, {0.25, 0.75}, {0.75, 0.25}, {0.125, 0.625}, {0.625, 0.125},
                {0.375, 0.375}, {0.875, 0.875}};
        for (int i = 0; i < expected.length; i++) {
            assertEquals(expected[i][0], (OwenSobol.sobol(i, 0) & 0xFFFFFFFFL) * 0x1.0p-32, "x of point " + i);
            assertEquals(expected[i][1], (OwenSobol.sobol(i, 1) & 0xFFFFFFFFL) * 0x1.0p-32, "y of point " + i);
        }
    }

    @Test
    void theByteTablesGiveTheGeneratorMatrixProductToTheBit() {
        // dimension 1 by its definition: the XOR of the direction numbers of the index's set bits
        int[] directions = new int[32];
        int v = 0x8000_0000;
        for (int bit = 0; bit < 32; bit++) {
            directions[bit] = v;
            v ^= v >>> 1;
        }
        Random rnd = new Random(341);
        for (int trial = 0; trial < 100_000; trial++) {
            int index = trial < 1024 ? trial : trial < 1056 ? 1 << (trial - 1024) : rnd.nextInt();
            int x = 0;
            for (int bit = 0; bit < 32; bit++) {
                if ((index >>> bit & 1) != 0) {
                    x ^= directions[bit];
                }
            }
            assertEquals(x, OwenSobol.sobol(index, 1), "index " + Integer.toHexString(index));
        }
    }

    @Test
    void theFirstPowerOfTwoPointsOfEverySeedFormANet() {
        Random rnd = new Random(34);
        for (int trial = 0; trial < 40; trial++) {
            int seed = rnd.nextInt();
            for (int k = 0; k <= 8; k++) {
                int n = 1 << k;
                for (int a = 0; a <= k; a++) {
                    int cellsX = 1 << a, cellsY = 1 << (k - a);
                    boolean[] taken = new boolean[n];
                    for (int i = 0; i < n; i++) {
                        int cx = (int) (OwenSobol.sample(i, 0, seed) * cellsX);
                        int cy = (int) (OwenSobol.sample(i, 1, seed) * cellsY);
                        int cell = cy * cellsX + cx;
                        assertTrue(!taken[cell], "seed " + seed + ", " + n + " points, intervals " + cellsX + "x"
                                + cellsY + ": two points in cell " + cell);
                        taken[cell] = true;
                    }
                }
            }
        }
    }

    @Test
    void onePointOverManySeedsIsUniform() {
        // chi-square of a 16-bin histogram of point 5's coordinates over 32,000 seeds
        for (int dim = 0; dim < 2; dim++) {
            int bins = 16, draws = 32_000;
            int[] count = new int[bins];
            for (int seed = 0; seed < draws; seed++) {
                double x = OwenSobol.sample(5, dim, OwenSobol.hash(seed, 77));
                assertTrue(x >= 0 && x < 1, "in [0, 1): " + x);
                count[(int) (x * bins)]++;
            }
            double expected = (double) draws / bins, chi2 = 0;
            for (int c : count) {
                chi2 += (c - expected) * (c - expected) / expected;
            }
            // 15 degrees of freedom: P(chi2 > 37.7) = 0.001
            assertTrue(chi2 < 37.7, "dimension " + dim + ": chi-square " + chi2);
        }
    }

    @Test
    void theScrambleIsABijectionOnEveryPrefix() {
        // Owen's scramble maps the 2^k intervals of each level onto themselves one to one
        Random rnd = new Random(5);
        for (int trial = 0; trial < 20; trial++) {
            int seed = rnd.nextInt();
            for (int k = 1; k <= 10; k++) {
                boolean[] seen = new boolean[1 << k];
                for (int top = 0; top < 1 << k; top++) {
                    int x = OwenSobol.nestedUniformScramble(top << (32 - k), seed) >>> (32 - k);
                    assertTrue(!seen[x], "level " + k + ": interval " + x + " twice");
                    seen[x] = true;
                }
            }
        }
    }
}
