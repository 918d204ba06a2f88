package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.render.Camera;
import org.junit.jupiter.api.Test;

class ScreenProjectorTest {

    private static final double EPS = 1e-9;

    private static CameraSpec perspective() {
        return CameraSpec.perspective(new Vec3(-3, -8, 5), new Vec3(0.2, 0, 0.1), Vec3.Z, 40);
    }

    private static CameraSpec ortho() {
        return new CameraSpec(new Vec3(-3, -8, 5), new Vec3(0.2, 0, 0.1), Vec3.Z, 0, 6);
    }

    @Test
    void projectionInvertsTheRendererCameraRays() {
        Random rnd = new Random(5);
        for (CameraSpec spec : new CameraSpec[] {perspective(), ortho()}) {
            ScreenProjector p = new ScreenProjector(spec, 320, 200);
            Camera cam = new Camera(spec);
            double[] ray = new double[6];
            double[] out = new double[3];
            for (int k = 0; k < 200; k++) {
                double x = rnd.nextDouble() * 320, y = rnd.nextDouble() * 200, t = 0.5 + 5 * rnd.nextDouble();
                cam.generateRay(x, y, 320, 200, ray);
                assertTrue(p.project(ray[0] + t * ray[3], ray[1] + t * ray[4], ray[2] + t * ray[5], out));
                assertEquals(x, out[0], 1e-7, "x of a point on the renderer's ray through " + x + "," + y + " " + spec);
                assertEquals(y, out[1], 1e-7, "y of a point on the renderer's ray through " + x + "," + y + " " + spec);
            }
        }
    }

    @Test
    void theDragPlaneKeepsTheDepthAndFollowsTheCursor() {
        for (CameraSpec spec : new CameraSpec[] {perspective(), ortho()}) {
            ScreenProjector p = new ScreenProjector(spec, 640, 480);
            Vec3 start = new Vec3(0.5, -0.25, 0.3);
            double[] a = new double[3];
            p.project(start.x(), start.y(), start.z(), a);
            Vec3 q = p.onScreenPlane(a[0] + 37, a[1] - 21, start);
            double[] b = new double[3];
            p.project(q.x(), q.y(), q.z(), b);
            assertEquals(a[0] + 37, b[0], 1e-7);
            assertEquals(a[1] - 21, b[1], 1e-7);
            assertEquals(a[2], b[2], 1e-7, "the point moves parallel to the screen");
            assertEquals(0, q.sub(start).dot(p.forward()), EPS);
        }
    }

    @Test
    void pointsBehindThePerspectiveEyeDoNotProject() {
        ScreenProjector p = new ScreenProjector(perspective(), 100, 100);
        assertTrue(!p.project(-6, -16, 10, new double[3]));
    }
}
