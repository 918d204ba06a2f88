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
    void randomizeMovesWeldedCopiesTogetherSoTheTeapotStaysClosed() {
        Scene teapot = Models.teapot();
        Scene bent = NetEdits.randomize(teapot, 7);
        WeldIndex before = WeldIndex.build(teapot), after = WeldIndex.build(bent);
        assertTrue(before.weldedPointCount() > 300, "the teapot shares most border points: " + before.weldedPointCount());
        assertEquals(before.weldedPointCount(), after.weldedPointCount(), "every weld survives");
        int moved = 0;
        for (int p = 0; p < teapot.patchCount(); p++) {
            double[] a = teapot.patches().get(p).copyNet(), b = bent.patches().get(p).copyNet();
            for (int k = 0; k < a.length; k++) {
                if (k % 3 != 2) {
                    assertEquals(a[k], b[k], "only z moves");
                } else if (a[k] != b[k]) {
                    moved++;
                }
            }
        }
        assertTrue(moved > 400, "points moved: " + moved);
    }
}
