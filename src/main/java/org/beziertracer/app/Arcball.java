package org.beziertracer.app;

import org.beziertracer.math.Vec3;

/**
 * Shoemake's arcball: K. Shoemake, "ARCBALL: A user interface for specifying three-dimensional
 * orientation using a mouse", Proc. Graphics Interface '92, pp. 151–156. A ball of radius half the
 * picture's smaller side sits in the middle of the picture; a drag from {@code p0} to {@code p1}
 * (picture pixels, y down) lifts both onto the ball (points outside it onto its rim) and turns the
 * model about {@code p0 × p1} by <b>twice</b> the arc between them (the quaternion
 * {@code [p0·p1, p0×p1]}). So a drag from the centre to the rim — across half the picture's smaller
 * side, or further — turns 180°, a drag across a quarter of it 60°, whatever the window's size or
 * device scale; a straight drag through the centre turns about one axis, and dragging back turns
 * back. Immutable.
 *
 * <p>View coordinates: x right, y up, z towards the viewer.
 */
public final class Arcball {

    /** A rotation of the model in view coordinates: unit {@code axis} (x right, y up, z to the viewer), {@code angle} in radians. */
    public record Turn(Vec3 axis, double angle) {
        static final Turn NONE = new Turn(new Vec3(0, 1, 0), 0);
    }

    private final double cx, cy, radius;

    /** The ball of a picture {@code width × height} pixels. */
    public Arcball(double width, double height) {
        cx = width / 2;
        cy = height / 2;
        radius = Math.max(1, Math.min(width, height) / 2);
    }

    public double radius() { return radius; }

    /** The point of the ball under picture pixel {@code (x, y)}; outside the ball, the nearest point of its rim. */
    public Vec3 onBall(double x, double y) {
        double bx = (x - cx) / radius, by = (cy - y) / radius;
        double d2 = bx * bx + by * by;
        if (d2 > 1) {
            double d = Math.sqrt(d2);
            return new Vec3(bx / d, by / d, 0);
        }
        return new Vec3(bx, by, Math.sqrt(1 - d2));
    }

    /** The model's rotation for a drag from {@code (x0, y0)} to {@code (x1, y1)}. */
    public Turn drag(double x0, double y0, double x1, double y1) {
        Vec3 p0 = onBall(x0, y0), p1 = onBall(x1, y1);
        Vec3 axis = p0.cross(p1);
        double sin = axis.length();
        if (!(sin > 1e-12)) {
            return Turn.NONE; // no move, or from one point of the rim to its opposite: no defined axis
        }
        return new Turn(axis.scale(1 / sin), 2 * Math.atan2(sin, p0.dot(p1)));
    }
}
