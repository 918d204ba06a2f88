package org.beziertracer.render;

import static org.beziertracer.Tolerances.COLOUR;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Material;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/** Shadows and reflected rays see trimmed surfaces as trimmed: light passes through the holes. */
class TrimmedShadowTest {

    /** A flat plate over [-1,1]² at height 2 with a round hole of radius 0.4 at its centre. */
    private static BezierPatch plateWithHole() {
        TrimRegion hole = new TrimRegion(List.of(), List.of(TrimLoop.circle(0.5, 0.5, 0.2, true)));
        return new BezierPatch(1, 1, new double[] {-1, -1, 2, 1, -1, 2, -1, 1, 2, 1, 1, 2}, null,
                new PatchDomain(0, 1, 0, 1, hole), null);
    }

    private static WhittedTracer tracer(Scene scene) {
        RenderSettings s = new RenderSettings(9, 9, 1, "regular", "clipping", true, "phong", 0, true, 5);
        return WhittedTracer.forJob(RenderJob.prepare(scene, s, RenderOptions.defaults().withThreads(1)
                .withProgressive(false)).withCamera(Camera.lookAt(new Vec3(3, 0, 10), Vec3.ZERO, Vec3.Y, 40)));
    }

    @Test
    void lightFallsThroughTheHoleAndTheMaterialCastsAShadow() {
        Material m = new Material(1, 1, 1, 0.1, 0.9, 0, 1, 0, 0, 1.5, 0, 0, 0, 0); // ambient 0.1, pure diffuse
        Scene scene = Scene.builder().addMaterial(m).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .addPatches(List.of(plateWithHole()), 0).addLight(new PointLight(new Vec3(0, 0, 5))).build();
        WhittedTracer t = tracer(scene);
        double[] rgb = new double[3];
        // rays from below the plate to the floor, so only the shadow rays meet the plate
        t.trace(0, 0, 1, 0, 0, -1, rgb);
        assertEquals(1.0, rgb[0], COLOUR, "under the hole: ambient + full diffuse");
        t.trace(0.7, 0, 1, 0, 0, -1, rgb);
        assertEquals(0.1, rgb[0], COLOUR, "under the material: only ambient");
    }

    @Test
    void aMirrorSeesThroughTheHole() {
        Material mirror = new Material(0, 0, 0, 0, 0, 0, 1, 1, 0, 1.5, 0, 0, 0, 0); // reflects everything
        Material lit = new Material(1, 1, 1, 1, 0, 0, 1, 0, 0, 1.5, 0, 0, 0, 0); // ambient 1: white
        Scene scene = Scene.builder().addMaterial(mirror).addMaterial(lit)
                .addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1)).addPatches(List.of(plateWithHole()), 1).build();
        WhittedTracer t = tracer(scene);
        double[] through = new double[3], onto = new double[3];
        t.trace(0, 0, 1, 0, 0, -1, through); // reflected straight up through the hole: the background
        t.trace(0.7, 0, 1, 0, 0, -1, onto); // reflected up onto the plate's white underside
        assertEquals(1.0, onto[0], COLOUR);
        assertTrue(through[0] < 0.5, "the reflection through the hole is not the plate: " + through[0]);
    }
}
