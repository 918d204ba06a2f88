package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** Welding: points within 1e-9 of the scene's size are one handle, found in O(points) by a cell hash. */
class WeldIndexTest {

    /** Every point of {@code scene} as a reference, patch after patch. */
    static List<PointRef> allPoints(Scene scene) {
        List<PointRef> out = new ArrayList<>();
        for (int p = 0; p < scene.patchCount(); p++) {
            BezierPatch patch = scene.patches().get(p);
            for (int j = 0; j <= patch.degreeV(); j++) {
                for (int i = 0; i <= patch.degreeU(); i++) {
                    out.add(new PointRef(p, i, j));
                }
            }
        }
        return out;
    }

    static double distance(Scene s, PointRef a, PointRef b) {
        double d2 = 0;
        for (int c = 0; c < 3; c++) {
            double d = s.patches().get(a.patch()).get(a.i(), a.j(), c) - s.patches().get(b.patch()).get(b.i(), b.j(), c);
            d2 += d * d;
        }
        return Math.sqrt(d2);
    }

    /** Brute force: the handle of every point is exactly the points within the tolerance, chained. */
    private static void assertAgreesWithBruteForce(Scene scene) {
        WeldIndex welds = WeldIndex.build(scene);
        double tol = WeldIndex.tolerance(scene);
        List<PointRef> all = allPoints(scene);
        int welded = 0;
        for (PointRef a : all) {
            Set<PointRef> handle = new HashSet<>(welds.copies(a, scene));
            boolean alone = true;
            for (PointRef b : all) {
                if (!a.equals(b) && distance(scene, a, b) <= tol) {
                    assertTrue(handle.contains(b), a + " and " + b + " coincide, so they are one handle");
                    alone = false;
                }
            }
            for (PointRef b : handle) {
                assertTrue(distance(scene, a, b) <= tol, "a copy of " + a + " lies within the tolerance: " + b);
            }
            welded += alone ? 0 : 1;
        }
        assertEquals(welded, welds.weldedPointCount());
    }

    @Test
    void theTeapotsSharedBorderPointsAreWelded() {
        Scene teapot = Models.teapot();
        assertAgreesWithBruteForce(teapot);
        WeldIndex welds = WeldIndex.build(teapot);
        assertTrue(welds.weldedPointCount() > 300, "welded: " + welds.weldedPointCount());
        // The body's corner at patch 0 P(0,0) is shared by the patch beside it and the one below or above
        assertTrue(welds.copies(new PointRef(0, 0, 0), teapot).size() >= 2);
        // The lid's top collapses whole rows into one point: 4 patches × 4 points
        assertEquals(16, welds.copies(new PointRef(28, 0, 0), teapot).size(), "the collapsed lid top is one handle");
    }

    @Test
    void pointsCloserThanTheToleranceWeldEvenAcrossCellFacesAndFartherOnesDoNot() {
        Random rnd = new Random(5);
        for (int round = 0; round < 20; round++) {
            List<BezierPatch> patches = new ArrayList<>();
            double size = Math.pow(10, rnd.nextInt(7) - 3);
            for (int p = 0; p < 6; p++) {
                double[] net = new double[48];
                for (int k = 0; k < net.length; k++) {
                    net[k] = size * rnd.nextDouble();
                }
                patches.add(new BezierPatch(3, 3, net));
            }
            Scene scene = Scene.builder().patches(patches).build();
            double tol = WeldIndex.tolerance(scene);
            // Plant copies: exact, just inside, just outside the tolerance, and straddling cell faces
            List<BezierPatch> planted = new ArrayList<>(patches);
            double[] net = patches.get(5).copyNet();
            double[] src = patches.get(0).copyNet();
            double cell = WeldIndex.CELL_PER_TOLERANCE * tol;
            for (int k = 0; k < 16; k++) {
                double offset = switch (k % 4) {
                    case 0 -> 0;
                    case 1 -> 0.4 * tol;
                    case 2 -> 3 * tol;
                    default -> 0.9 * tol;
                };
                for (int c = 0; c < 3; c++) {
                    double v = src[3 * k + c];
                    if (k % 4 == 3) {
                        v = Math.floor(v / cell) * cell + 0.2 * tol; // just above a cell face
                        src[3 * k + c] = v;
                        offset = -0.5 * tol;                         // the copy just below it
                    }
                    net[3 * k + c] = v + (c == 0 ? offset : 0);
                }
            }
            planted.set(0, new BezierPatch(3, 3, src));
            planted.set(5, new BezierPatch(3, 3, net));
            assertAgreesWithBruteForce(Scene.builder().patches(planted).build());
        }
    }

    @Test
    void aStaleIndexOnlyGivesCopiesThatStillCoincide() {
        Scene teapot = Models.teapot();
        WeldIndex welds = WeldIndex.build(teapot);
        PointRef corner = new PointRef(0, 0, 0);
        List<PointRef> copies = welds.copies(corner, teapot);
        PointRef other = copies.get(1);
        Scene moved = teapot.withPatch(other.patch(), teapot.patches().get(other.patch()).withPoint(other.i(), other.j(), 1, 2, 3));
        List<PointRef> now = welds.copies(corner, moved);
        assertEquals(copies.size() - 1, now.size(), "the copy dragged away (Alt) is no longer one with the others");
        assertTrue(!now.contains(other));
        assertEquals(List.of(new PointRef(0, 9, 9)), welds.copies(new PointRef(0, 9, 9), teapot), "no such point: itself only");
        assertEquals(1, welds.copies(corner, Models.patch()).size(), "an index of another model");
    }
}
