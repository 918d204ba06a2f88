package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class NetEditsTest {

    @Test
    void resetGivesAFlatSquareGridOfTheChosenSize() {
        Scene s = NetEdits.resetGrid(Models.teapot(), 3, 7);
        assertEquals(1, s.patchCount());
        BezierPatch p = s.patches().get(0);
        assertEquals(2, p.degreeU());
        assertEquals(6, p.degreeV());
        double[] net = p.copyNet();
        for (int k = 2; k < net.length; k += 3) {
            assertEquals(0, net[k], "all points in the plane z = 0");
        }
    }

    @Test
    void randomizeIsSeededAndOnlyMovesZWithinTheRange() {
        Scene a = NetEdits.randomize(Models.patch(), 42);
        Scene b = NetEdits.randomize(Models.patch(), 42);
        Scene c = NetEdits.randomize(Models.patch(), 43);
        assertEquals(a.patches(), b.patches(), "same seed, same surface");
        assertNotEquals(a.patches(), c.patches());
        double[] flat = Models.flatGrid(4, 4).copyNet();
        double[] net = a.patches().get(0).copyNet();
        for (int k = 0; k < net.length; k++) {
            if (k % 3 == 2) {
                assertTrue(Math.abs(net[k]) <= NetEdits.RANDOM_Z_RANGE, "z offset " + net[k]);
            } else {
                assertEquals(flat[k], net[k], "x and y stay on the grid");
            }
        }
    }

    @Test
    void movePointChangesOnlyThatPoint() {
        Scene s = NetEdits.movePoint(Models.patch(), new PointRef(0, 2, 1), 9, 8, 7);
        BezierPatch p = s.patches().get(0);
        assertEquals(9, p.get(2, 1, 0));
        assertEquals(7, p.get(2, 1, 2));
        assertEquals(Models.flatGrid(4, 4).get(1, 1, 0), p.get(1, 1, 0));
    }
}
