package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.math.Aabb;
import org.junit.jupiter.api.Test;

class FlatListTest {

    @Test
    void closestHitAndOccludedMatchBruteForce() {
        Random rnd = new Random(21);
        for (int n : new int[] {0, 1, 2, 7, 1000}) {
            double[] bounds = BoxScene.randomBoxes(rnd, n);
            BvhTest.checkQueries(FlatList.build(bounds, n), new BoxScene(bounds, n), rnd, "flat n=" + n);
        }
    }

    @Test
    void flatListAndBvhGiveTheSameAnswers() {
        Random rnd = new Random(22);
        int n = 3000;
        double[] bounds = BoxScene.randomBoxes(rnd, n);
        BoxScene scene = new BoxScene(bounds, n);
        Accelerator flat = FlatList.build(bounds, n), bvh = Bvh.build(bounds, n);
        int[] stack = bvh.newStack();
        for (int r = 0; r < 3000; r++) {
            scene.randomRay(rnd);
            double tMax = r % 2 == 0 ? Double.POSITIVE_INFINITY : 12.0;
            String in = "ray " + r + ": " + scene.ray() + " tMax=" + tMax;
            double a = flat.closestHit(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                    scene.invDz, scene.tMin, tMax, scene, scene, null);
            double b = bvh.closestHit(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                    scene.invDz, scene.tMin, tMax, scene, scene, stack);
            assertEquals(a, b, 0, in);
            assertEquals(flat.occluded(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                    scene.invDz, scene.tMin, tMax, scene, scene, null),
                    bvh.occluded(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                    scene.invDz, scene.tMin, tMax, scene, scene, stack), in);
        }
        assertEquals(bvh.bounds(), flat.bounds());
    }

    @Test
    void refitGivesANewListAndKeepsTheOldOne() {
        double[] bounds = {0, 0, 0, 1, 1, 1};
        FlatList old = FlatList.build(bounds, 1);
        FlatList moved = old.refit(new double[] {5, 5, 5, 6, 6, 6});
        assertEquals(new Aabb(0, 0, 0, 1, 1, 1), old.bounds());
        assertEquals(new Aabb(5, 5, 5, 6, 6, 6), moved.bounds());
        bounds[0] = -100;
        assertEquals(new Aabb(0, 0, 0, 1, 1, 1), old.bounds(), "build copies the input");
    }

    @Test
    void reportsNoNodesAndNeedsNoStack() {
        FlatList flat = FlatList.build(new double[12], 2);
        assertEquals(0, flat.nodeCount());
        assertEquals(0, flat.depth());
        assertEquals(0, flat.stackSize());
        assertEquals(2, flat.primCount());
        UserMessages.of(IllegalArgumentException.class, () -> flat.refit(new double[6]));
    }
}
