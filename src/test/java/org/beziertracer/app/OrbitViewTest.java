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
            v = v.turned(new Arcball(1200, 900).drag(600, 450, 607, 447));
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

    /** The angle the camera turned between two views: between their forward axes. */
    private static double degreesBetween(OrbitView a, OrbitView b) {
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, a.forward().dot(b.forward())))));
    }

    @Test
    void anArcballDragFromTheCentreToTheRimTurnsHalfATurnAtAnyWindowSize() {
        OrbitView v = OrbitView.fit(Models.patch().controlBounds(), 40);
        for (int[] size : new int[][] {{800, 600}, {1370, 800}, {640, 640}, {2740, 1600}}) {
            int w = size[0], h = size[1];
            Arcball ball = new Arcball(w, h);
            double r = Math.min(w, h) / 2.0;
            assertEquals(r, ball.radius(), 0);
            String at = w + "×" + h;
            // Across the half-width (beyond the ball's rim when the window is wider than tall): 180°
            assertEquals(180, degreesBetween(v, v.turned(ball.drag(w / 2.0, h / 2.0, w, h / 2.0))), 1e-6, at);
            // Half the ball's radius: 2·asin(1/2) = 60°; a quarter: 2·asin(1/4) ≈ 29°, both ways the same
            assertEquals(60, degreesBetween(v, v.turned(ball.drag(w / 2.0, h / 2.0, w / 2.0 + r / 2, h / 2.0))), 1e-6, at);
            assertEquals(60, degreesBetween(v, v.turned(ball.drag(w / 2.0, h / 2.0, w / 2.0, h / 2.0 - r / 2))), 1e-6, at);
            assertEquals(Math.toDegrees(2 * Math.asin(0.25)),
                    degreesBetween(v, v.turned(ball.drag(w / 2.0, h / 2.0, w / 2.0 - r / 4, h / 2.0))), 1e-6, at);
        }
        // The drag: 100 px in the default 800×600 picture is 39°, not about 90°
        assertEquals(Math.toDegrees(2 * Math.asin(100 / 300.0)),
                degreesBetween(v, v.turned(new Arcball(800, 600).drag(400, 300, 500, 300))), 1e-6);
    }

    @Test
    void anArcballDragTurnsTheModelWithTheMouseAndBackAgain() {
        OrbitView v = OrbitView.fit(Models.patch().controlBounds(), 40);
        Arcball ball = new Arcball(800, 600);
        // Dragging right turns the model's front to the right: the camera moves to its left
        OrbitView right = v.turned(ball.drag(400, 300, 460, 300));
        assertEquals(1, Math.signum(right.forward().dot(v.right())), "the camera looks further right: " + right.forward());
        assertEquals(0, right.up().sub(v.up()).length(), 1e-12, "a horizontal drag through the centre turns about up");
        // Dragging up turns the front up, showing the underside: the camera moves below and looks up
        OrbitView up = v.turned(ball.drag(400, 300, 400, 240));
        assertEquals(1, Math.signum(up.forward().dot(v.up())), "the camera looks up at it: " + up.forward());
        assertEquals(0, up.right().sub(v.right()).length(), 1e-12, "a vertical drag through the centre turns about right");
        // Step by step along a line through the centre, and back: the start again (seeded random steps)
        java.util.Random rnd = new java.util.Random(36);
        OrbitView w = v;
        double x = 400, y = 300;
        double[] xs = new double[41];
        for (int k = 0; k <= 40; k++) {
            xs[k] = 400 + (k == 0 ? 0 : xs[k - 1] - 400 + rnd.nextDouble() * 6);
        }
        for (int k = 1; k <= 40; k++) {
            w = w.turned(ball.drag(xs[k - 1], y, xs[k], y));
        }
        for (int k = 40; k >= 1; k--) {
            w = w.turned(ball.drag(xs[k], y, xs[k - 1], y));
        }
        assertEquals(0, w.forward().sub(v.forward()).length(), 1e-9, "back where it started");
        assertEquals(0, w.up().sub(v.up()).length(), 1e-9);
        assertEquals(v, v.turned(ball.drag(x, y, x, y)), "no move, no turn");
    }
}
