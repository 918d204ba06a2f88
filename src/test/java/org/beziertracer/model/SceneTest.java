package org.beziertracer.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.math.Aabb;
import org.junit.jupiter.api.Test;

class SceneTest {

    @Test
    void controlBoundsAreTheUnionOfThePatchBoxesComputedOnce() {
        Random rnd = new Random(35);
        List<BezierPatch> patches = new ArrayList<>();
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int k = 0; k < 50; k++) {
            double[] net = new double[3 * 16];
            for (int i = 0; i < net.length; i++) {
                net[i] = (rnd.nextDouble() - 0.5) * 1000;
                lo[i % 3] = Math.min(lo[i % 3], net[i]);
                hi[i % 3] = Math.max(hi[i % 3], net[i]);
            }
            patches.add(new BezierPatch(3, 3, net));
        }
        Scene scene = Scene.builder().patches(patches).build();
        Aabb box = scene.controlBounds();
        assertEquals(new Aabb(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]), box);
        assertSame(box, scene.controlBounds(), "the second call computes the box again");
    }

    @Test
    void aPatchsControlBoxIntoAnArrayIsItsBoxToTheBit() {
        Random rnd = new Random(3506);
        for (int k = 0; k < 2_000; k++) {
            int n = 1 + rnd.nextInt(4), m = 1 + rnd.nextInt(4);
            double scale = k % 10 == 0 ? 1e300 : Math.pow(10, rnd.nextInt(9) - 4); // some overflow the square
            double[] net = new double[3 * (n + 1) * (m + 1)];
            for (int i = 0; i < net.length; i++) {
                net[i] = k % 7 == 0 && i % 5 == 0 ? -0.0 : (rnd.nextDouble() - 0.5) * scale;
            }
            BezierPatch p = new BezierPatch(n, m, net);
            double[] b = new double[6];
            p.controlBoundsInto(b);
            Aabb box = p.controlBounds();
            assertEquals(box, new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]), "patch " + k);
            assertEquals(box.diagonal(), Aabb.diagonal(b[3] - b[0], b[4] - b[1], b[5] - b[2]), "patch " + k);
        }
    }
}
