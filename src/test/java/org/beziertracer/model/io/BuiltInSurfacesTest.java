package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.Patches;
import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/** The built-in free-form models are the exact shapes they name. */
class BuiltInSurfacesTest {

    /** Distance from the exact shape, relative to its size: rational Bézier pieces are exact to rounding. */
    private static final double SHAPE_TOLERANCE = org.beziertracer.Tolerances.ROUNDING;

    @Test
    void everySpherePointIsAtDistanceOneFromTheOrigin() {
        List<BezierPatch> sphere = Models.load("sphere").patches();
        assertEquals(8, sphere.size());
        Random rnd = new Random(51);
        for (BezierPatch p : sphere) {
            assertTrue(p.isRational());
            for (int k = 0; k < 200; k++) {
                Vec3 q = Patches.evaluate(p, rnd.nextDouble(), rnd.nextDouble());
                assertEquals(1, q.length(), SHAPE_TOLERANCE, () -> "point " + q);
            }
        }
    }

    @Test
    void everyTorusPointSatisfiesTheTorusEquation() {
        List<BezierPatch> torus = Models.load("torus").patches();
        assertEquals(16, torus.size());
        double r = BuiltInSurfaces.TORUS_MINOR;
        Random rnd = new Random(52);
        for (BezierPatch p : torus) {
            for (int k = 0; k < 200; k++) {
                Vec3 q = Patches.evaluate(p, rnd.nextDouble(), rnd.nextDouble());
                double ring = Math.hypot(q.x(), q.y()) - 1;
                assertEquals(r, Math.hypot(ring, q.z()), SHAPE_TOLERANCE, () -> "point " + q);
            }
        }
    }

    @Test
    void theTrimmedPlateHasAnOuterLoopAndThreeHoles() {
        BezierPatch plate = Models.load("trimmed-plate").patches().get(0);
        assertNotNull(plate.trim());
        assertEquals(1, plate.trim().outer().size());
        assertEquals(8, plate.trim().outer().get(0).pieces().size());
        assertEquals(3, plate.trim().holes().size());
    }

    @Test
    void theTeacupAndTeaspoonAreTheNewellPatches() {
        Scene cup = Models.load("teacup"), spoon = Models.load("teaspoon");
        assertEquals(26, cup.patchCount());
        assertEquals(16, spoon.patchCount());
        Aabb box = cup.controlBounds();
        assertEquals(-1, box.min().x(), 1e-12);
        assertEquals(0, box.min().z(), 1e-12);
        assertEquals(0.954545, box.max().z(), 1e-12);
        assertEquals(-1, spoon.controlBounds().min().z(), 1e-12); // the handle's end, z-up
    }

    @Test
    void everyBuiltInModelGoesThroughObjAndBack() {
        for (String name : BuiltIns.names(FileFormat.Holds.MODEL)) {
            List<BezierPatch> patches = Models.load(name).patches();
            String text = ObjWriter.toString(patches);
            assertEquals(patches, ObjReader.read(text, name + ".obj"), name);
        }
    }
}
