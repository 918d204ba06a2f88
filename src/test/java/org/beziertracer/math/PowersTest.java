package org.beziertracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class PowersTest {

    @Test
    void wholeExponentsAreWithinTheirBoundOfMathPow() {
        SplittableRandom random = new SplittableRandom(20261203);
        for (int trial = 0; trial < 200_000; trial++) {
            double x = random.nextDouble(0.05, 1.0);
            int e = random.nextInt(0, Powers.MAX_SQUARED + 1);
            double expected = Math.pow(x, e);
            if (expected < 0x1p-1000) {
                continue; // near the subnormal range: fewer digits on both sides
            }
            double got = Powers.pow(x, e);
            double bound = (e + 2) * 0x1p-53 * expected;
            assertTrue(Math.abs(got - expected) <= bound, () -> x + "^" + e + " = " + got + ", Math.pow " + expected);
        }
    }

    @Test
    void smallAndSpecialExponentsAreExact() {
        for (double x : new double[] {0, 0.5, 0.73, 1, 2, 3.25}) {
            assertEquals(1.0, Powers.pow(x, 0), () -> x + "^0");
            assertEquals(1.0, Powers.pow(x, -0.0), () -> x + "^-0");
            assertEquals(x, Powers.pow(x, 1), () -> x + "^1");
            assertEquals(x * x, Powers.pow(x, 2), () -> x + "^2");
            assertEquals(x * x * x, Powers.pow(x, 3), () -> x + "^3");
        }
        assertEquals(0.0, Powers.pow(0, 40));
        assertEquals(1.0, Powers.pow(1, 1024));
        assertEquals(0x1p-40, Powers.pow(0.5, 40)); // powers of two are exact
    }

    @Test
    void otherExponentsAreMathPow() {
        SplittableRandom random = new SplittableRandom(7);
        for (int trial = 0; trial < 1000; trial++) {
            double x = random.nextDouble(0, 1);
            double e = random.nextDouble(0, 200);
            if (e == Math.rint(e)) {
                continue;
            }
            assertEquals(Math.pow(x, e), Powers.pow(x, e), () -> x + "^" + e);
        }
        for (double e : new double[] {1025, 4096, 1e9, -1, -3, 2.5}) {
            assertEquals(Math.pow(0.999, e), Powers.pow(0.999, e), () -> "0.999^" + e);
        }
    }
}
