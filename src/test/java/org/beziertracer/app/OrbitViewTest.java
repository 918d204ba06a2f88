package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class OrbitViewTest {

    @Test
    void rotationKeepsAnOrthonormalFrameAndTheDistance() {
        OrbitView v = OrbitView.fit(Models.patch().controlBounds(), 40);
        double d = v.camera(1.5).eye().sub(v.target()).length();
        for (int k = 0; k < 500; k++) {
            v = v.rotated(7, -3, 0.01);
        }
        assertEquals(1, v.right().length(), 1e-9);
        assertEquals(1, v.up().length(), 1e-9);
        assertEquals(0, v.right().dot(v.up()), 1e-9);
        assertEquals(d, v.camera(1.5).eye().sub(v.target()).length(), 1e-9);
    }

    @Test
    void perspectiveZeroIsOrthographicAndTheFramingIsKept() {
        OrbitView v = OrbitView.fit(Models.patch().controlBounds(), 40);
        CameraSpec persp = v.camera(1);
        CameraSpec ortho = v.withFov(0).camera(1);
        assertEquals(0, ortho.fovDegrees());
        double widthAtTarget = 2 * persp.eye().sub(persp.target()).length() * Math.tan(Math.toRadians(persp.fovDegrees()) / 2);
        assertEquals(ortho.orthoWidth(), widthAtTarget, 1e-9, "same picture size at the target");
    }

    @Test
    void zoomMovesAlongTheViewAxis() {
        OrbitView v = OrbitView.fit(Models.patch().controlBounds(), 40);
        Vec3 f = v.forward();
        OrbitView z = v.zoomed(1.5);
        assertEquals(1.5 * v.camera(1).eye().sub(v.target()).length(), z.camera(1).eye().sub(v.target()).length(), 1e-9);
        assertEquals(1, z.forward().dot(f), 1e-12);
    }
}
