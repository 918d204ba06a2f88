package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.geometry.Patches;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** The wireframe of rational and trimmed patches: exact rational iso-curves, trimmed iso-curves, trim curves. */
class FreeFormOverlayTest {

    private static ScreenProjector ortho(Scene s, int size) {
        CameraSpec camera = OrbitView.fit(s.controlBounds(), 0).camera(1);
        return new ScreenProjector(camera, size, size);
    }

    @Test
    void orthographicRationalIsoCurvesLieOnTheProjectedSurface() {
        Scene sphere = Models.load("sphere");
        ScreenProjector p = ortho(sphere, 500);
        int k = 4;
        List<float[]> curves = OverlayBuilder.build(new OverlayRequest(sphere, p, false, false, k, 1)).isoCurves();
        assertEquals(8 * 2 * (k + 1), curves.size());
        double[] out = new double[3];
        // patch 0's iso-curves of constant v: the projected rational patch, point for point
        BezierPatch first = sphere.patches().get(0);
        for (int b = 0; b <= k; b++) {
            float[] line = curves.get(b);
            for (int a = 0; a <= k; a++) {
                Vec3 q = Patches.evaluate(first, (double) a / k, (double) b / k);
                p.project(q.x(), q.y(), q.z(), out);
                assertEquals(out[0], line[2 * a], 1e-3, "point " + a + " of curve " + b);
                assertEquals(out[1], line[2 * a + 1], 1e-3);
            }
        }
    }

    @Test
    void aTrimmedPatchDrawsItsTrimCurvesAndNoIsoCurveInsideItsHole() {
        double[] flat = Models.flatGrid(2, 2).copyNet();
        TrimRegion hole = new TrimRegion(List.of(), List.of(TrimLoop.circle(0.5, 0.5, 0.3, true)));
        BezierPatch plate = new BezierPatch(1, 1, flat, null, new PatchDomain(0, 1, 0, 1, hole), null);
        Scene scene = new Scene(List.of(plate));
        // straight down, orthographic: the hole stays a circle on the screen
        ScreenProjector p = new ScreenProjector(new CameraSpec(new Vec3(0, 0, 10), Vec3.ZERO, Vec3.Y, 0, 4), 400, 400);
        int k = 8;
        List<float[]> curves = OverlayBuilder.build(new OverlayRequest(scene, p, false, false, k, 1)).isoCurves();
        // the middle iso-curves are cut in two by the hole, and the circle's 4 arcs are drawn
        assertTrue(curves.size() > 2 * (k + 1) + 4, "curves " + curves.size());
        double[] centre = new double[3], rim = new double[3];
        p.project(0, 0, 0, centre); // the plate's centre, (u,v) = (0.5, 0.5)
        p.project(0.9, 0, 0, rim); // the hole's radius on the plate is 0.3 · 3 = 0.9
        double radius = Math.hypot(rim[0] - centre[0], rim[1] - centre[1]);
        int onCircle = 0;
        for (float[] line : curves) {
            for (int i = 0; i < line.length; i += 2) {
                double r = Math.hypot(line[i] - centre[0], line[i + 1] - centre[1]);
                assertTrue(r >= radius - 1e-2, "a drawn point inside the hole: r = " + r + " < " + radius);
                onCircle += Math.abs(r - radius) < 1e-2 ? 1 : 0;
            }
        }
        assertTrue(onCircle >= 4 * 24, "the trim circle is drawn: " + onCircle + " points on it");
    }
}
