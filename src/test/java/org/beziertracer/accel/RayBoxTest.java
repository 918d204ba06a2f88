package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

class RayBoxTest {

    private static final double TOLERANCE = 1e-12;
    private static final double INF = Double.POSITIVE_INFINITY;
    private static final double[] UNIT = {0, 0, 0, 1, 1, 1};

    private static double entry(double[] box, double ox, double oy, double oz, double dx, double dy,
            double dz, double tMin, double tMax) {
        return RayBox.entry(box, 0, ox, oy, oz, 1 / dx, 1 / dy, 1 / dz, tMin, tMax);
    }

    @Test
    void aRayAlongXEntersTheUnitBoxAtItsNearFace() {
        assertEquals(2.0, entry(UNIT, -2, 0.5, 0.5, 1, 0, 0, 0, INF), TOLERANCE);
        assertEquals(1.0, entry(UNIT, 3, 0.5, 0.5, -2, 0, 0, 0, INF), TOLERANCE);
    }

    @Test
    void anOriginInsideTheBoxEntersAtTMin() {
        assertEquals(0.25, entry(UNIT, 0.5, 0.5, 0.5, 0.3, -0.7, 0.1, 0.25, INF), 0);
    }

    @Test
    void boxesBehindTheOriginOrBeyondTMaxAreMissed() {
        assertEquals(RayBox.MISS, entry(UNIT, 2, 0.5, 0.5, 1, 0, 0, 0, INF));
        assertEquals(RayBox.MISS, entry(UNIT, -2, 0.5, 0.5, 1, 0, 0, 0, 1.5));
        assertEquals(RayBox.MISS, entry(UNIT, -2, 0.99, 0.5, 1, 0.1, 0, 0, INF), "tilted out of y before reaching x");
    }

    @Test
    void anAxisParallelRayOutsideASlabMissesForBothSignedZeros() {
        for (double zero : new double[] {0.0, -0.0}) {
            assertEquals(RayBox.MISS, entry(UNIT, -2, 1.5, 0.5, 1, zero, zero, 0, INF), "zero=" + zero);
            assertEquals(RayBox.MISS, entry(UNIT, -2, -0.5, 0.5, 1, zero, zero, 0, INF), "zero=" + zero);
        }
    }

    @Test
    void anAxisParallelRayLyingOnAFaceHitsBecauseBoxesAreClosed() {
        for (double zero : new double[] {0.0, -0.0}) {
            for (double y : new double[] {0.0, 1.0}) {
                assertEquals(2.0, entry(UNIT, -2, y, 0.5, 1, zero, zero, 0, INF), 0,
                        "y=" + y + " zero=" + zero);
                assertEquals(2.0, entry(UNIT, -2, y, 1.0, 1, zero, zero, 0, INF), 0,
                        "edge y=" + y + " zero=" + zero);
            }
        }
    }

    @Test
    void aFlatBoxIsHitByARayInItsPlaneAndByOneCrossingIt() {
        double[] flat = {0, 0, 0.5, 1, 1, 0.5};
        assertEquals(3.0, entry(flat, 0.5, -3, 0.5, 0, 1, 0, 0, INF), 0, "in plane");
        assertEquals(0.5, entry(flat, 0.5, 0.5, 0, 0, 0, 1, 0, INF), TOLERANCE, "crossing");
        assertEquals(RayBox.MISS, entry(flat, 0.5, -3, 0.6, 0, 1, 0, 0, INF), "parallel above");
    }

    @Test
    void randomRaysAgreeWithTheTextbookSlabFormulaAndNeverReturnNaN() {
        Random rnd = new Random(11);
        double[] box = new double[6];
        for (int k = 0; k < 100_000; k++) {
            for (int a = 0; a < 3; a++) {
                double c = rnd.nextGaussian(), h = rnd.nextDouble();
                box[a] = c - h;
                box[a + 3] = c + h;
            }
            double[] o = {3 * rnd.nextGaussian(), 3 * rnd.nextGaussian(), 3 * rnd.nextGaussian()};
            double[] d = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            if (rnd.nextInt(4) == 0) {
                d[rnd.nextInt(3)] = rnd.nextBoolean() ? 0.0 : -0.0;
            }
            double tMin = rnd.nextBoolean() ? 0 : rnd.nextDouble();
            double tMax = rnd.nextBoolean() ? INF : 5 * rnd.nextDouble();
            double t = entry(box, o[0], o[1], o[2], d[0], d[1], d[2], tMin, tMax);
            java.util.function.Supplier<String> in = () -> String.format("box=%s o=%s d=%s tMin=%s tMax=%s -> %s",
                    java.util.Arrays.toString(box), java.util.Arrays.toString(o),
                    java.util.Arrays.toString(d), tMin, tMax, t);
            assertTrue(t == RayBox.MISS || (t >= tMin && t <= tMax), in);
            // Textbook reference (divisions, zero components handled by an explicit inside test)
            double near = tMin, far = tMax;
            for (int a = 0; a < 3; a++) {
                if (d[a] == 0) {
                    if (o[a] < box[a] || o[a] > box[a + 3]) {
                        near = INF;
                    }
                    continue;
                }
                double t0 = (box[a] - o[a]) / d[a], t1 = (box[a + 3] - o[a]) / d[a];
                near = Math.max(near, Math.min(t0, t1));
                far = Math.min(far, Math.max(t0, t1));
            }
            if (far - near > 1e-9) {
                assertEquals(near, t, TOLERANCE * (1 + Math.abs(near)), in);
            } else if (near - far > 1e-9) {
                assertEquals(RayBox.MISS, t, in);
            }
        }
    }
}
