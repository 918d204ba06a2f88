package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;

/** The offsets a sampler precomputes (those that do not depend on the pixel) are the ones it would compute. */
class PixelSamplerOffsetsTest {

    @Test
    void regularOffsetsAreTheCellCentresForEveryPixel() {
        for (PixelFilter filter : PixelFilter.values()) {
            PixelSampler s = new PixelSampler(SamplerKind.REGULAR, filter, 6, 7);
            double[] o = new double[2];
            for (int k = 0; k < 6; k++) {
                // 6 samples: 3 x 2 cells
                double ox = filter.warp((k % 3 + 0.5) / 3), oy = filter.warp((k / 3 + 0.5) / 2);
                for (int[] px : new int[][] {{0, 0}, {17, 3}, {799, 599}}) {
                    s.offset(px[0], px[1], k, o);
                    assertEquals(ox, o[0], 0, filter + " sample " + k);
                    assertEquals(oy, o[1], 0, filter + " sample " + k);
                }
            }
        }
    }

    @Test
    void theAdaptiveCentreIsFixedAndItsExtraSamplesAreJittered() {
        PixelSampler s = new PixelSampler(SamplerKind.ADAPTIVE, PixelFilter.BOX, 5, 3);
        double[] a = new double[2], b = new double[2];
        s.offset(4, 9, 0, a);
        assertEquals(0.5, a[0], 0);
        assertEquals(0.5, a[1], 0);
        s.offset(4, 9, 1, a);
        s.offset(5, 9, 1, b);
        assertNotEquals(a[0], b[0], "extra samples depend on the pixel");
    }
}
