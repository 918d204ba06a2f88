package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SplitOptionsTest {

    @Test
    void defaultsSplitAdaptivelyAndWholePatchesDoNot() {
        SplitOptions d = SplitOptions.defaults();
        assertTrue(d.enabled());
        assertEquals(0.05, d.flatnessTolerance());
        assertEquals(6, d.maxDepth());
        SplitOptions w = SplitOptions.wholePatches();
        assertFalse(w.enabled());
        assertEquals(0, w.maxDepth());
    }

    @Test
    void higherDegreesGetAFinerToleranceAndADeeperCapBicubicsTheFineSplitsOnly() {
        SplitOptions d = SplitOptions.defaults();
        SplitOptions big = d.forPatches(SplitOptions.FINE_PATCHES + 1);
        for (int n = 1; n <= 3; n++) {
            assertEquals(0.05 * SplitOptions.FINE_FLATNESS, d.flatnessFor(n, 3 - n + 1));
            assertEquals(6 + SplitOptions.FINE_DEPTH, d.maxDepthFor(n, 3));
            assertEquals(0.05, big.flatnessFor(n, 3 - n + 1));
            assertEquals(6, big.maxDepthFor(n, 3));
        }
        assertEquals(0, new SplitOptions(true, 0.05, 0).maxDepthFor(3, 3), "no split stays no split");
        assertEquals(0.05 * 3 / 9, d.flatnessFor(9, 9), 1e-15);
        assertEquals(0.05 * 3 / 5, d.flatnessFor(2, 5), 1e-15);
        int[] extra = {0, 0, 0, 0, 2, 2, 2, 4, 4, 4, 4, 4, 4, 6, 6, 6}; // by max(n, m) = 0..15
        for (int deg = 4; deg <= 15; deg++) {
            assertEquals(big.maxDepthFor(deg, 1), d.maxDepthFor(deg, 1), "the fine split is for bicubics only");
            assertEquals(6 + extra[deg], d.maxDepthFor(deg, 1), "degree " + deg);
            assertEquals(6 + extra[deg], d.maxDepthFor(1, deg), "degree " + deg);
        }
        assertEquals(16, new SplitOptions(true, 0.05, 14).maxDepthFor(15, 15), "capped at 16");
        assertEquals(0, new SplitOptions(true, 0.05, 0).maxDepthFor(9, 9), "no split stays no split");
        // a solver's own leaf criterion (Newton's refinement) keeps the tolerance and cap it was given
        SplitOptions own = new SplitOptions(true, 1, 10, (net, n, m, size, depth) -> true);
        assertEquals(1, own.flatnessFor(9, 9));
        assertEquals(10, own.maxDepthFor(15, 15));
    }

    @Test
    void depthLimitsAreInclusive() {
        assertEquals(0, new SplitOptions(true, 0.1, 0).maxDepth());
        assertEquals(16, new SplitOptions(true, 0.1, 16).maxDepth());
        assertEquals(Double.MIN_VALUE, new SplitOptions(true, Double.MIN_VALUE, 3).flatnessTolerance());
    }

    @Test
    void badValuesAreRefusedWithTheirValueInTheMessage() {
        for (double bad : new double[] {0, -0.0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> new SplitOptions(true, bad, 3), "flatness " + bad);
            assertTrue(e.getMessage().startsWith("flatness tolerance must be positive"), e.getMessage());
        }
        for (int bad : new int[] {-1, 17}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> new SplitOptions(true, 0.1, bad), "depth " + bad);
            assertEquals("split depth must be 0..16, got " + bad, e.getMessage());
        }
    }
}
