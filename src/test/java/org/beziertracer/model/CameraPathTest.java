package org.beziertracer.model;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Random;

import org.beziertracer.math.Vec3;
import org.junit.jupiter.api.Test;

class CameraPathTest {

    private static final double TOLERANCE = 1e-12;
    private static final CameraSpec BASE = CameraSpec.perspective(new Vec3(10, 0, 3), new Vec3(0, 0, 1), Vec3.Z, 40);

    @Test
    void frameKOfATurntableIsTurnedByDegreesTimesKMinusOneOverFrames() {
        CameraPath.Turntable t = new CameraPath.Turntable(36, Vec3.Z, null, 360);
        assertEquals(0, t.angleDegrees(1));
        assertEquals(10, t.angleDegrees(2), TOLERANCE);
        assertEquals(350, t.angleDegrees(36), TOLERANCE);
        CameraSpec quarter = new CameraPath.Turntable(4, Vec3.Z, null, 360).at(2, BASE);
        // a quarter turn about z through the target (0,0,1): the eye (10,0,3) goes to (0,10,3)
        assertClose(new Vec3(0, 10, 3), quarter.eye(), "eye after 90 degrees");
        assertClose(BASE.target(), quarter.target(), "the target on the axis stays");
        assertClose(Vec3.Z, quarter.up(), "up along the axis stays");
        assertEquals(40, quarter.fovDegrees());
        assertEquals(BASE, new CameraPath.Turntable(4, Vec3.Z, null, 360).at(1, BASE), "frame 1 is the base camera");
    }

    @Test
    void aTurntableKeepsDistancesToTheCenterForAnyAxis() {
        Random random = new Random(3701);
        for (int trial = 0; trial < 200; trial++) {
            Vec3 axis = new Vec3(random.nextGaussian(), random.nextGaussian(), random.nextGaussian());
            Vec3 center = new Vec3(random.nextDouble(), random.nextDouble(), random.nextDouble());
            int frames = 1 + random.nextInt(100), k = 1 + random.nextInt(frames);
            CameraPath.Turntable t = new CameraPath.Turntable(frames, axis, center, 360 * random.nextDouble());
            CameraSpec c;
            try {
                c = t.at(k, BASE);
            } catch (IllegalArgumentException e) {
                continue; // up turned along the view: not this test's concern
            }
            String inputs = "axis " + axis + ", center " + center + ", frame " + k + "/" + frames;
            assertEquals(BASE.eye().sub(center).length(), c.eye().sub(center).length(), 1e-9, inputs);
            assertEquals(BASE.eye().sub(BASE.target()).length(), c.eye().sub(c.target()).length(), 1e-9, inputs);
            Vec3 a = axis.normalize();
            assertEquals(BASE.eye().sub(center).dot(a), c.eye().sub(center).dot(a), 1e-9, "height along the axis: " + inputs);
        }
    }

    @Test
    void keyframesInterpolateLinearlyAndHoldBeforeTheFirstAndAfterTheLast() {
        CameraPath.Keyframes k = new CameraPath.Keyframes(List.of(
                new CameraPath.Keyframe(0, new Vec3(10, 0, 0), Vec3.ZERO, Vec3.Z, 30),
                new CameraPath.Keyframe(10, new Vec3(0, 10, 0), new Vec3(0, 0, 2), Vec3.Z, 50)));
        CameraSpec mid = k.at(5, BASE);
        assertClose(new Vec3(5, 5, 0), mid.eye(), "eye half way");
        assertClose(new Vec3(0, 0, 1), mid.target(), "target half way");
        assertEquals(40, mid.fovDegrees(), TOLERANCE);
        assertEquals(32, k.at(1, BASE).fovDegrees(), TOLERANCE);
        assertClose(new Vec3(10, 0, 0), k.at(-3, BASE).eye(), "before the first");
        assertClose(new Vec3(0, 10, 0), k.at(99, BASE).eye(), "after the last");
        assertEquals(0, k.firstFrame());
        assertEquals(10, k.lastFrame());
    }

    private static void assertClose(Vec3 expected, Vec3 actual, String what) {
        assertEquals(0, expected.sub(actual).length(), TOLERANCE, what + ": expected " + expected + ", got " + actual);
    }
}
