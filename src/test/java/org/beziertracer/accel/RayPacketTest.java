package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class RayPacketTest {

    /** {@code of} is {@code clear} and an {@code add} per ray: the same bounds, the same verdict. */
    @Test
    void ofIsAnAddPerRay() {
        SplittableRandom random = new SplittableRandom(1203);
        RayPacket whole = new RayPacket(), oneByOne = new RayPacket();
        for (int trial = 0; trial < 20_000; trial++) {
            int n = random.nextInt(1, 17);
            double[] rays = new double[6 * n];
            boolean sameSigns = random.nextBoolean();
            for (int i = 0; i < rays.length; i++) {
                double v = random.nextDouble(-3, 3);
                rays[i] = sameSigns && i % 6 >= 3 ? Math.copySign(0.1 + Math.abs(v), (i % 6) - 4) : v;
                if (random.nextInt(200) == 0) {
                    rays[i] = random.nextBoolean() ? Double.NaN : Double.POSITIVE_INFINITY;
                }
            }
            whole.of(rays, n);
            oneByOne.clear();
            for (int i = 0; i < n; i++) {
                int o = 6 * i;
                oneByOne.add(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5]);
            }
            String what = "trial " + trial;
            assertArrayEquals(oneByOne.oLo, whole.oLo, what);
            assertArrayEquals(oneByOne.oHi, whole.oHi, what);
            assertArrayEquals(oneByOne.dLo, whole.dLo, what);
            assertArrayEquals(oneByOne.dHi, whole.dHi, what);
            assertEquals(oneByOne.reciprocals(), whole.reciprocals(), what);
            if (whole.reciprocals()) {
                assertArrayEquals(oneByOne.invLo, whole.invLo, what);
                assertArrayEquals(oneByOne.invHi, whole.invHi, what);
            }
        }
    }
}
