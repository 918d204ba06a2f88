package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

class GeneratedModelsTest {

    @Test
    void wavyGridsOfEveryDegreeAreOnePatchOfThatDegree() {
        for (int points = 2; points <= 16; points++) {
            Scene s = GeneratedModels.wavy(points);
            assertEquals(1, s.patchCount());
            BezierPatch p = s.patches().get(0);
            assertEquals(points - 1, p.degreeU(), "wavy" + points);
            assertEquals(points - 1, p.degreeV(), "wavy" + points);
        }
        assertThrows(IllegalArgumentException.class, () -> GeneratedModels.wavy(1));
        assertThrows(IllegalArgumentException.class, () -> GeneratedModels.wavy(17));
    }

    @Test
    void theBenchmarkGridsAndTheArchAreBuiltIns() {
        assertEquals(GeneratedModels.wavy(6).patches(), Models.load("wavy6").patches());
        assertEquals(GeneratedModels.wavy(10).patches(), Models.load("WAVY10").patches());
        assertEquals(GeneratedModels.curved().patches(), Models.load("curved").patches());
    }

    @Test
    void aWavyGridIsTheFlatGridLiftedByTheHeight() {
        BezierPatch wavy = GeneratedModels.wavyGrid(10);
        BezierPatch flat = Models.flatGrid(10, 10);
        for (int j = 0; j < 10; j++) {
            for (int i = 0; i < 10; i++) {
                double x = flat.get(i, j, 0), y = flat.get(i, j, 1);
                assertEquals(x, wavy.get(i, j, 0));
                assertEquals(y, wavy.get(i, j, 1));
                assertEquals(GeneratedModels.height(x, y), wavy.get(i, j, 2), "point " + i + "," + j);
            }
        }
    }

    @Test
    void theHeightIsNotSeparable() {
        // h(x,y) = f(x) g(y) would make h(a,b) h(c,d) = h(a,d) h(c,b)
        double a = 0.3, b = -0.7, c = 1.1, d = 0.4;
        double lhs = GeneratedModels.height(a, b) * GeneratedModels.height(c, d);
        double rhs = GeneratedModels.height(a, d) * GeneratedModels.height(c, b);
        assertTrue(Math.abs(lhs - rhs) > 1e-3, lhs + " vs " + rhs);
        // nor a sum f(x) + g(y)
        double sum = GeneratedModels.height(a, b) + GeneratedModels.height(c, d)
                - GeneratedModels.height(a, d) - GeneratedModels.height(c, b);
        assertTrue(Math.abs(sum) > 1e-3, "sum test " + sum);
    }

    @Test
    void theCurvedPatchIsABicubicArchTallerThanHalfItsWidth() {
        BezierPatch p = Models.load("curved").patches().get(0);
        assertEquals(3, p.degreeU());
        assertEquals(3, p.degreeV());
        var box = p.controlBounds();
        assertTrue(box.maxZ() - box.minZ() > 0.5 * (box.maxX() - box.minX()), box.toString());
        // twisted: the corners of the arch's feet are not at one height
        assertNotEquals(p.get(0, 0, 2), p.get(0, 3, 2));
    }
}
