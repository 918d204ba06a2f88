package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * A path's numbers depend on seed, pixel, sample and dimension only, and their low discrepancy
 * pays: 16 samples a pixel integrate a smooth function of a 2-D point several times more
 * accurately than independent random numbers do.
 */
class PathRandomTest {

    @Test
    void numbersDependOnSeedPixelSampleAndDimensionOnly() {
        PathRandom a = new PathRandom(), b = new PathRandom();
        a.start(7, 10, 20, 3);
        double[] first = new double[6];
        for (int d = 0; d < 3; d++) {
            first[2 * d] = a.next2();
            first[2 * d + 1] = a.second();
        }
        // another pixel and sample in between change nothing
        b.start(7, 11, 20, 3);
        b.next();
        b.start(7, 10, 20, 3);
        for (int d = 0; d < 3; d++) {
            assertEquals(first[2 * d], b.next2());
            assertEquals(first[2 * d + 1], b.second());
        }
        // skip keeps later dimensions where they were
        b.start(7, 10, 20, 3);
        b.skip(2);
        assertEquals(first[4], b.next2());
        b.start(8, 10, 20, 3);
        assertNotEquals(first[0], b.next2(), "the seed changes the numbers");
        b.start(7, 10, 21, 3);
        assertNotEquals(first[0], b.next2(), "the pixel changes the numbers");
    }

    @Test
    void sixteenSamplesIntegrateASmoothFunctionBetterThanIndependentNumbers() {
        // f(u, v) = u·v + sin(3u)·v² on the unit square: the exact integral and its variance
        double integral = 0.25 + (1 - Math.cos(3)) / 9;
        int pixels = 400, spp = 16;
        double sumSq = 0;
        PathRandom rnd = new PathRandom();
        for (int p = 0; p < pixels; p++) {
            double sum = 0;
            for (int s = 0; s < spp; s++) {
                rnd.start(1, p % 20, p / 20, s);
                rnd.next(); // a bounce's light choice, then its 2-D sample
                double u = rnd.next2(), v = rnd.second();
                sum += f(u, v);
            }
            double e = sum / spp - integral;
            sumSq += e * e;
        }
        double rmse = Math.sqrt(sumSq / pixels);
        // independent numbers: rmse = σ_f / √spp, σ_f estimated on a fine grid
        double mean = 0, meanSq = 0;
        int g = 512;
        for (int i = 0; i < g; i++) {
            for (int j = 0; j < g; j++) {
                double fv = f((i + 0.5) / g, (j + 0.5) / g);
                mean += fv;
                meanSq += fv * fv;
            }
        }
        mean /= g * g;
        meanSq /= g * g;
        double independent = Math.sqrt(meanSq - mean * mean) / Math.sqrt(spp);
        assertTrue(rmse < independent / 4, "rmse " + rmse + " against " + independent + " for independent numbers");
        // and the same test run on java.util.Random does not pass (the bound is not loose)
        Random r = new Random(2);
        double iidSq = 0;
        for (int p = 0; p < pixels; p++) {
            double sum = 0;
            for (int s = 0; s < spp; s++) {
                sum += f(r.nextDouble(), r.nextDouble());
            }
            double e = sum / spp - integral;
            iidSq += e * e;
        }
        assertTrue(Math.sqrt(iidSq / pixels) > independent / 2, "independent numbers: " + Math.sqrt(iidSq / pixels));
    }

    private static double f(double u, double v) {
        return u * v + Math.sin(3 * u) * v * v;
    }
}
