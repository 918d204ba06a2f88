package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@link PixelSampler}: where the samples of a pixel go, for each kind, filter and spp; the same
 * inputs always give the same positions, and jittered positions are uniform within their cells.
 */
class PixelSamplerTest {

    private final double[] out = new double[2];

    /** The path tracer's spread order: every cell once, from the centre, any first samples spread over the pixel. */
    @Test
    void theSpreadOrderTakesEveryCellOnceFromTheCentreAndSpreadsItsFirstSamples() {
        for (int spp : new int[] {1, 2, 3, 6, 16, 64, 100, 256, 1000, 1024}) {
            PixelSampler sampler = new PixelSampler(SamplerKind.REGULAR, PixelFilter.BOX, spp, 1, true);
            int kx = (int) Math.ceil(Math.sqrt(spp)), ky = (spp + kx - 1) / kx;
            java.util.Set<Integer> cells = new java.util.HashSet<>();
            double sumX = 0, sumY = 0, drift = 0;
            for (int k = 0; k < spp; k++) {
                sampler.offset(3, 4, k, out);
                int cx = (int) Math.floor(out[0] * kx), cy = (int) Math.floor(out[1] * ky);
                assertTrue(cells.add(cy * kx + cx), "spp " + spp + ": cell of sample " + k + " taken twice");
                assertTrue(cy * kx + cx < spp, "spp " + spp + ": only the grid's first spp cells");
                sumX += out[0];
                sumY += out[1];
                if (k >= 3) {
                    drift += Math.max(Math.abs(sumX / (k + 1) - 0.5), Math.abs(sumY / (k + 1) - 0.5));
                }
            }
            if (spp >= 4) {
                // Row by row, the mean of the first k samples sits 0.4 pixels or more up the pixel on average
                double meanDrift = drift / (spp - 3);
                assertTrue(meanDrift < 0.07, "spp " + spp + ": the means of the first k samples are "
                        + meanDrift + " from the centre on average");
            }
            sampler.offset(3, 4, 0, out);
            if (spp == 256) {
                assertEquals((8 + 0.5) / 16, out[0], 0, "sample 0 in the centre cell");
                assertEquals((8 + 0.5) / 16, out[1], 0);
            }
        }
        assertEquals(159, PixelSampler.goldenStride(256), "256/φ ≈ 158.2; 159 is the nearest odd");
    }

    @Test
    void regularSamplesAreTheCellCentres() {
        for (int spp : new int[] {1, 2, 4, 5, 9}) {
            PixelSampler sampler = new PixelSampler(SamplerKind.REGULAR, PixelFilter.BOX, spp, 1);
            int kx = (int) Math.ceil(Math.sqrt(spp)), ky = (spp + kx - 1) / kx;
            for (int s = 0; s < spp; s++) {
                sampler.offset(3, 4, s, out);
                assertEquals((s % kx + 0.5) / kx, out[0], 0, "spp " + spp + " sample " + s);
                assertEquals((s / kx + 0.5) / ky, out[1], 0, "spp " + spp + " sample " + s);
            }
        }
    }

    @Test
    void jitteredSamplesStayInTheirCellsAndFillThemUniformly() {
        int spp = 6, kx = 3, ky = 2;
        PixelSampler sampler = new PixelSampler(SamplerKind.JITTERED, PixelFilter.BOX, spp, 99);
        double[] meanX = new double[spp], meanY = new double[spp];
        int pixels = 4000;
        for (int p = 0; p < pixels; p++) {
            for (int s = 0; s < spp; s++) {
                sampler.offset(p % 80, p / 80, s, out);
                double cellX = (s % kx) / (double) kx, cellY = (s / kx) / (double) ky;
                assertTrue(out[0] >= cellX && out[0] < cellX + 1.0 / kx, "x of sample " + s + " of pixel " + p + ": " + out[0]);
                assertTrue(out[1] >= cellY && out[1] < cellY + 1.0 / ky, "y of sample " + s + " of pixel " + p + ": " + out[1]);
                meanX[s] += (out[0] - cellX) * kx / pixels;
                meanY[s] += (out[1] - cellY) * ky / pixels;
            }
        }
        // A uniform point in the cell has mean 1/2 and standard deviation 1/√12 per axis: the mean
        // of 4000 is within 5 standard errors (0.023) of 1/2
        for (int s = 0; s < spp; s++) {
            assertEquals(0.5, meanX[s], 0.023, "x of sample " + s);
            assertEquals(0.5, meanY[s], 0.023, "y of sample " + s);
        }
    }

    @Test
    void positionsDependOnlyOnPixelSampleAndSeed() {
        PixelSampler a = new PixelSampler(SamplerKind.JITTERED, PixelFilter.TENT, 4, 7);
        PixelSampler b = new PixelSampler(SamplerKind.JITTERED, PixelFilter.TENT, 4, 7);
        PixelSampler other = new PixelSampler(SamplerKind.JITTERED, PixelFilter.TENT, 4, 8);
        double[] o2 = new double[2], o3 = new double[2];
        int differs = 0;
        for (int k = 0; k < 500; k++) {
            int x = k % 31, y = k / 31, s = k % 4;
            a.offset(x, y, s, out);
            b.offset(x, y, s, o2);
            assertEquals(out[0], o2[0], 0);
            assertEquals(out[1], o2[1], 0);
            a.offset(x, y, s, o2);
            assertEquals(out[0], o2[0], 0, "asking twice gives the same position");
            other.offset(x, y, s, o3);
            if (o3[0] != out[0]) {
                differs++;
            }
        }
        assertTrue(differs > 490, "another seed moves the samples: " + differs + " of 500");
        a.offset(1, 2, 0, out);
        a.offset(2, 1, 0, o2);
        assertNotEquals(out[0], o2[0], "neighbouring pixels do not share a position");
    }

    @Test
    void theAdaptiveSamplerStartsAtTheCentreThenJitters() {
        PixelSampler sampler = new PixelSampler(SamplerKind.ADAPTIVE, PixelFilter.BOX, 5, 3);
        sampler.offset(10, 20, 0, out);
        assertEquals(0.5, out[0], 0);
        assertEquals(0.5, out[1], 0);
        // the 4 extra samples jitter in a 2×2 grid
        for (int s = 1; s < 5; s++) {
            sampler.offset(10, 20, s, out);
            double cellX = ((s - 1) % 2) / 2.0, cellY = ((s - 1) / 2) / 2.0;
            assertTrue(out[0] >= cellX && out[0] < cellX + 0.5 && out[1] >= cellY && out[1] < cellY + 0.5,
                    "sample " + s + " at " + out[0] + "," + out[1]);
            assertNotEquals(0.5 * (2 * cellX + 0.5), out[0], "jittered, not the cell centre");
        }
    }

    @Test
    void theTentFilterReachesIntoNeighboursAndFavoursTheCentre() {
        PixelSampler sampler = new PixelSampler(SamplerKind.JITTERED, PixelFilter.TENT, 1, 5);
        int inner = 0, n = 20000;
        double min = 1, max = 0;
        for (int k = 0; k < n; k++) {
            sampler.offset(k % 200, k / 200, 0, out);
            min = Math.min(min, out[0]);
            max = Math.max(max, out[0]);
            assertTrue(out[0] >= -0.5 && out[0] < 1.5, "x " + out[0]);
            if (Math.abs(out[0] - 0.5) < 0.5) {
                inner++;
            }
        }
        assertTrue(min < -0.3 && max > 1.3, "reaches the neighbours: " + min + ".." + max);
        // A tent of radius 1 puts 3/4 of its mass within half a pixel of the centre
        assertEquals(0.75, inner / (double) n, 0.02);
    }

    @Test
    void fewerThanOneSampleIsRejected() {
        assertThrows(IllegalArgumentException.class, () -> new PixelSampler(SamplerKind.REGULAR, PixelFilter.BOX, 0, 1));
    }
}
