package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class BvhOptionsTest {

    @Test
    void defaultsAreFourPrimitivesPerLeafAndSixteenBins() {
        assertEquals(new BvhOptions(4, 16), BvhOptions.defaults());
    }

    @Test
    void nonsensicalSettingsAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> new BvhOptions(0, 16));
        assertThrows(IllegalArgumentException.class, () -> new BvhOptions(4, 1));
        assertThrows(IllegalArgumentException.class, () -> new BvhOptions(4, BvhOptions.MAX_BIN_COUNT + 1));
    }
}
