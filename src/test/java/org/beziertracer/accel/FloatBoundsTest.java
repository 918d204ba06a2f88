package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The hierarchy keeps float boxes rounded outward: they contain the double boxes, so a ray that
 * meets a primitive's double box always reaches its leaf, even where rounding to the nearest float
 * would have cut the box.
 */
class FloatBoundsTest {

    @Test
    void downAndUpBracketEveryDouble() {
        Random rnd = new Random(41);
        for (int t = 0; t < 100_000; t++) {
            double x = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(40) - 20);
            float lo = RayBox.down(x), hi = RayBox.up(x);
            assertTrue(lo <= x && x <= hi, "x=" + x);
            assertTrue(Math.nextUp(lo) > x || lo == x, "down is the largest float not above " + x);
            assertTrue(Math.nextDown(hi) < x || hi == x, "up is the smallest float not below " + x);
        }
        assertEquals(1f, RayBox.down(1.0), 0);
        assertEquals(1f, RayBox.up(1.0), 0);
    }

    /**
     * Boxes whose faces sit just past a float (1 + 1e-9 rounds to 1.0f to nearest); rays that
     * graze those faces between the float and the double still hit, through any builder.
     */
    @Test
    void raysBetweenTheNearestFloatAndTheDoubleFaceStillHit() {
        int n = 64;
        double eps = 1e-9;
        double[] bounds = new double[6 * n];
        for (int p = 0; p < n; p++) {
            double x = 3 * p;
            double[] box = {x - eps, -1 - eps, -1 - eps, x + 1 + eps, 1 + eps, 1 + eps};
            System.arraycopy(box, 0, bounds, 6 * p, 6);
        }
        assertEquals(1f, (float) (1 + eps), 0, "to nearest, the face rounds inward");
        for (BvhOptions opts : new BvhOptions[] {ParallelBuildTest.SAH, ParallelBuildTest.MORTON}) {
            Bvh bvh = Bvh.build(bounds, n, opts);
            FlatList flat = FlatList.build(bounds, n);
            BoxScene scene = new BoxScene(bounds, n);
            for (int p = 0; p < n; p++) {
                // Straight down at y = 1 + eps/2, z = 0: only inside the double box's y range
                scene.setRay(3 * p + 0.5, 1 + eps / 2, 5, 0, 0, -1, 0);
                for (Accelerator acc : new Accelerator[] {bvh, flat}) {
                    double t = acc.closestHit(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy, scene.invDz,
                            0, Double.POSITIVE_INFINITY, scene, scene, acc.newStack());
                    assertEquals(scene.bruteForce(Double.POSITIVE_INFINITY), t, 0, acc + " box " + p);
                    assertTrue(t < Double.POSITIVE_INFINITY, acc + ": box " + p + " was culled");
                }
            }
        }
    }
}
