package org.beziertracer.render;

import static org.beziertracer.Tolerances.DERIVED;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.UserMessages;
import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.junit.jupiter.api.Test;

class CameraTest {
    final double[] ray = new double[6];

    private static Vec3 dir(double[] r) { return new Vec3(r[3], r[4], r[5]); }

    private static Vec3 origin(double[] r) { return new Vec3(r[0], r[1], r[2]); }

    @Test
    void centrePixelRayGoesThroughTheTarget() {
        Camera c = Camera.lookAt(new Vec3(1, -7, 3), new Vec3(0.5, 2, -1), Vec3.Z, 55);
        c.generateRay(5 + 0.5, 3 + 0.5, 11, 7, ray); // centre of pixel (5,3) of an 11×7 image
        Vec3 toTarget = new Vec3(0.5, 2, -1).sub(origin(ray)).normalize();
        assertEquals(0, dir(ray).normalize().sub(toTarget).length(), DERIVED, "centre ray " + dir(ray));
    }

    @Test
    void horizontalFieldOfViewSpansTheImageWidth() {
        double fov = 60;
        Camera c = Camera.lookAt(new Vec3(0, -5, 0), Vec3.ZERO, Vec3.Z, fov);
        c.generateRay(0, 50, 200, 100, ray); // left edge, middle row
        Vec3 left = dir(ray).normalize();
        c.generateRay(200, 50, 200, 100, ray);
        Vec3 right = dir(ray).normalize();
        assertEquals(fov, Math.toDegrees(Math.acos(left.dot(right))), DERIVED);
        assertTrue(left.x() < 0 && right.x() > 0, "left edge ray must point to -x (right-handed, z up): " + left);
        c.generateRay(100, 0, 200, 100, ray); // top edge: half the width's angle times the aspect
        Vec3 top = dir(ray).normalize();
        assertEquals(Math.atan(Math.tan(Math.toRadians(fov / 2)) / 2), Math.atan2(top.z(), top.y()), DERIVED);
    }

    @Test
    void orthographicRaysAreParallelAndSpanTheViewWidth() {
        Camera c = Camera.orthographic(new Vec3(0, -5, 0), Vec3.ZERO, Vec3.Z, 4);
        c.generateRay(0, 0, 40, 20, ray);
        Vec3 d0 = dir(ray), o0 = origin(ray);
        c.generateRay(40, 20, 40, 20, ray);
        assertEquals(0, d0.sub(dir(ray)).length(), DERIVED);
        assertEquals(new Vec3(-2, -5, 1), o0);
        assertEquals(new Vec3(2, -5, -1), origin(ray));
    }

    @Test
    void orbitKeepsTheDistanceAndTurnsAboutTheUpAxis() {
        Camera c = Camera.lookAt(new Vec3(0, -10, 0), Vec3.ZERO, Vec3.Z, 40);
        Camera turned = c.orbit(90, 0);
        assertEquals(10, turned.eye().length(), DERIVED);
        assertEquals(0, turned.eye().sub(new Vec3(10, 0, 0)).length(), DERIVED, "yaw 90 about +z: " + turned.eye());
        Camera raised = c.orbit(0, 30);
        assertEquals(10, raised.eye().length(), DERIVED);
        assertEquals(5, raised.eye().z(), DERIVED);
        assertTrue(c.orbit(0, 200).eye().z() < 10, "pitch is clamped below the pole");
    }

    @Test
    void zoomMovesTheEyeAlongTheViewAxis() {
        Camera c = Camera.lookAt(new Vec3(0, -10, 2), new Vec3(0, 0, 2), Vec3.Z, 40).zoom(0.5);
        assertEquals(new Vec3(0, -5, 2), c.eye());
        UserMessages.of(IllegalArgumentException.class, () -> c.zoom(0));
        assertEquals(2, Camera.orthographic(new Vec3(0, -5, 0), Vec3.ZERO, Vec3.Z, 4).zoom(0.5).orthoWidth(), DERIVED);
    }

    @Test
    void fitKeepsEveryCornerOfTheBoxInTheImage() {
        Aabb box = new Aabb(-120, -80, 0, 141, 80, 120); // the teapot
        for (double fov : new double[] {20, 40, 90, 0}) {
            Camera c = Camera.fit(box, 4 / 3.0, fov);
            Vec3 f = c.forward(), r = f.cross(Vec3.Z).normalize(), u = r.cross(f);
            double tanH = fov == 0 ? 0 : Math.tan(Math.toRadians(fov / 2));
            for (int k = 0; k < 8; k++) {
                Vec3 p = new Vec3((k & 1) == 0 ? box.minX() : box.maxX(), (k & 2) == 0 ? box.minY() : box.maxY(),
                        (k & 4) == 0 ? box.minZ() : box.maxZ());
                Vec3 q = p.sub(c.eye());
                double x = fov == 0 ? q.dot(r) / (c.orthoWidth() / 2) : q.dot(r) / q.dot(f) / tanH;
                double y = fov == 0 ? q.dot(u) / (c.orthoWidth() / 2) * 4 / 3 : q.dot(u) / q.dot(f) / tanH * 4 / 3;
                assertTrue(Math.abs(x) <= 1 && Math.abs(y) <= 1, "fov " + fov + ": corner " + p + " at " + x + "," + y);
            }
        }
    }

    @Test
    void fitLooksAtAFlatPatchFromAbove() {
        Camera c = Camera.fit(new Aabb(-1.5, -1.5, 0, 1.5, 1.5, 0), 4 / 3.0, 40);
        assertTrue(c.forward().z() < -0.6, "steep enough to see a flat patch well: " + c.forward());
    }
}
