package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class ImageDifferenceTest {

    @Test
    void aPixelDiffersWhenOneChannelMovesByMoreThanThePercentOfTheRange() {
        int grey = 0xFF808080;
        assertFalse(ImageDifference.differs(grey, grey, 10));
        assertFalse(ImageDifference.differs(grey, 0xFF808080 + 25, 10), "25 levels are within 10 % (25.5)");
        assertTrue(ImageDifference.differs(grey, 0xFF808080 + 26, 10), "blue by 26");
        assertTrue(ImageDifference.differs(grey, 0xFF808080 - (26 << 8), 10), "green by 26");
        assertTrue(ImageDifference.differs(grey, 0xFF808080 + (26 << 16), 10), "red by 26");
        assertFalse(ImageDifference.differs(grey, 0x00808080, 10), "alpha is not a colour");
    }

    @Test
    void countAndOverlayMarkExactlyTheDifferingPixels() {
        int[] a = {0xFF000000, 0xFFFFFFFF, 0xFF204060, 0xFF102030};
        int[] b = {0xFF000000, 0xFF000000, 0xFF204061, 0xFF10FF30};
        assertEquals(2, ImageDifference.count(a, b, 10));
        int[] o = ImageDifference.overlay(a, b, 10);
        assertArrayEquals(new int[] {0xFF000000, ImageDifference.MARK, 0xFF202020, ImageDifference.MARK}, o);
        assertThrows(IllegalArgumentException.class, () -> ImageDifference.count(a, new int[3], 10));
    }
}
