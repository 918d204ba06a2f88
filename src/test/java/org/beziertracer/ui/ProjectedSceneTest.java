package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.Patches;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class ProjectedSceneTest {

    private static Scene randomPatch() {
        return NetEdits.randomize(Models.patch(), 11);
    }

    @Test
    void pickFindsTheNearestControlPointWithinTheRadius() {
        Scene s = randomPatch();
        ScreenProjector p = new ScreenProjector(OrbitView.fit(s.controlBounds(), 40).camera(4 / 3.0), 800, 600);
        ProjectedScene ps = new ProjectedScene(s, p);
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                PointRef got = ps.pick(ps.x(0, i, j) + 2, ps.y(0, i, j) - 1, 6);
                assertEquals(new PointRef(0, i, j), got, "pick near P" + i + j);
            }
        }
        assertNull(ps.pick(-100, -100, 6));
    }

    @Test
    void orthographicWireframeIsTheProjectionOfTheSurface() {
        // A parallel projection is affine, and Bézier surfaces are affine invariant: the cheap 2-D
        // evaluation on projected control points is then exact.
        Scene s = randomPatch();
        CameraSpec ortho = OrbitView.fit(s.controlBounds(), 0).camera(1);
        ScreenProjector p = new ScreenProjector(ortho, 500, 500);
        ProjectedScene ps = new ProjectedScene(s, p);
        int k = 6;
        List<double[]> curves = ps.isoCurves(k);
        assertEquals(2 * (k + 1), curves.size());
        double[] out = new double[3];
        for (int b = 0; b <= k; b++) {
            double[] line = curves.get(b);
            for (int a = 0; a <= k; a++) {
                Vec3 q = Patches.evaluate(s.patches().get(0), (double) a / k, (double) b / k);
                p.project(q.x(), q.y(), q.z(), out);
                assertEquals(out[0], line[2 * a], 1e-7);
                assertEquals(out[1], line[2 * a + 1], 1e-7);
            }
        }
    }

    @Test
    void perspectiveWireframeInterpolatesTheProjectedCorners() {
        Random rnd = new Random(3);
        Scene s = NetEdits.randomize(Models.patch(), rnd.nextLong());
        ScreenProjector p = new ScreenProjector(OrbitView.fit(s.controlBounds(), 80).camera(1.5), 600, 400);
        ProjectedScene ps = new ProjectedScene(s, p);
        List<double[]> curves = ps.isoCurves(5);
        double[] first = curves.get(0);
        assertEquals(ps.x(0, 0, 0), first[0], 1e-9);
        assertEquals(ps.y(0, 3, 0), first[first.length - 1], 1e-9);
    }
}
