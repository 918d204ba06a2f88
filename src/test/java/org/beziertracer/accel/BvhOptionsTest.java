package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

class BvhOptionsTest {

    @Test
    void defaultsAreFourPrimitivesPerLeafAndSixteenBins() {
        assertEquals(new BvhOptions(4, 16), BvhOptions.defaults());
    }

    @Test
    void nonsensicalSettingsAreRejected() {
        UserMessages.of(IllegalArgumentException.class, () -> new BvhOptions(0, 16));
        UserMessages.of(IllegalArgumentException.class, () -> new BvhOptions(4, 1));
        UserMessages.of(IllegalArgumentException.class, () -> new BvhOptions(4, BvhOptions.MAX_BIN_COUNT + 1));
    }
}
