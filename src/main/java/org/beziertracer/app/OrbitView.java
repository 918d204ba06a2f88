package org.beziertracer.app;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;

/**
 * The interactive view: an orbit camera about {@code target}, described by the camera's
 * orthonormal {@code right} and {@code up} axes (the forward axis is {@code up × right}), a zoom
 * factor and the perspective amount. Immutable; every interaction returns a new view.
 *
 * <p>Dragging empty space turns the model with an {@link Arcball}, which is the same as turning the
 * camera the other way about the same axis ({@link #turned}). The wheel scales the visible half-width at the target ({@link #zoomed}).
 *
 * <p>Framing: the model's bounding sphere (centre {@code target}, {@code radius}) fills the
 * smaller side of the picture at zoom 1. The perspective runs from 0 (parallel rays,
 * orthographic) to {@value #MAX_FOV_DEGREES}° of horizontal field of view; changing it moves the
 * eye so that the picture keeps its size at the target (a "dolly zoom").
 */
public record OrbitView(Vec3 target, double radius, Vec3 right, Vec3 up, double zoom, double fovDegrees) {

    /** Strongest perspective: horizontal field of view at the right end of the slider. */
    public static final double MAX_FOV_DEGREES = 110;
    /** Field of view of a fresh view. */
    public static final double DEFAULT_FOV_DEGREES = 40;
    /** Margin around the bounding sphere at zoom 1. */
    static final double MARGIN = 1.1;

    public OrbitView {
        if (!(radius > 0) || !Double.isFinite(radius)) {
            radius = 1;
        }
        if (!(zoom > 0) || !Double.isFinite(zoom)) {
            throw new IllegalArgumentException("zoom must be positive, got " + zoom);
        }
        if (!(fovDegrees >= 0 && fovDegrees <= MAX_FOV_DEGREES)) {
            throw new IllegalArgumentException("field of view must be 0.." + MAX_FOV_DEGREES + ", got " + fovDegrees);
        }
    }

    /**
     * The default framing of a model: seen from the front, a little from the left and above, with
     * world +z up (the teapot stands on z = 0; the default patch lies in z = 0).
     */
    public static OrbitView fit(Aabb bounds, double fovDegrees) {
        Vec3 back = new Vec3(-0.35, -0.85, 0.75).normalize();
        Vec3 forward = back.scale(-1);
        Vec3 right = forward.cross(Vec3.Z).normalize();
        Vec3 up = right.cross(forward).normalize();
        return new OrbitView(center(bounds), 0.5 * bounds.diagonal(), right, up, 1, fovDegrees);
    }

    /** A view looking along a scene's own camera, framed on the model. */
    public static OrbitView fromCamera(CameraSpec cam, Aabb bounds) {
        Vec3 forward = cam.target().sub(cam.eye()).normalize();
        Vec3 right = forward.cross(cam.up()).normalize();
        Vec3 up = right.cross(forward).normalize();
        double fov = Math.min(MAX_FOV_DEGREES, cam.fovDegrees());
        return new OrbitView(center(bounds), 0.5 * bounds.diagonal(), right, up, 1, fov);
    }

    private static Vec3 center(Aabb b) {
        return b.isEmpty() ? Vec3.ZERO : b.center();
    }

    /** What the view is centred on. */
    public Framing framing() { return new Framing(target, radius); }

    /** Same orientation, zoom and perspective, centred on {@code f}. */
    public OrbitView withFraming(Framing f) {
        return new OrbitView(f.target(), f.radius(), right, up, zoom, fovDegrees);
    }

    /** Unit vector from the eye towards the target. */
    public Vec3 forward() { return up.cross(right).normalize(); }

    /** Half the visible width, in scene units, in the plane through the target (aspect = width / height). */
    public double halfWidth(double aspect) {
        return radius * MARGIN * Math.max(1, aspect) * zoom;
    }

    /** Distance from the eye to the target; for the orthographic view, a distance outside the model. */
    public double distance(double aspect) {
        double hw = halfWidth(aspect);
        if (fovDegrees == 0) {
            return 4 * radius * Math.max(1, zoom) + hw;
        }
        double d = hw / Math.tan(Math.toRadians(fovDegrees) / 2);
        return Math.max(d, 1.05 * radius);
    }

    /** The camera for a picture of the given aspect ratio (width / height). */
    public CameraSpec camera(double aspect) {
        Vec3 eye = target.sub(forward().scale(distance(aspect)));
        if (fovDegrees == 0) {
            return new CameraSpec(eye, target, up, 0, 2 * halfWidth(aspect));
        }
        // Keep the framing at the target when the eye had to back off
        double hw = halfWidth(aspect);
        double fov = 2 * Math.toDegrees(Math.atan(hw / distance(aspect)));
        return new CameraSpec(eye, target, up, fov, 1);
    }

    /**
     * The view after the model turned by {@code t} ({@link Arcball}): the camera turns the other way
     * about the same axis, taken from view into world coordinates (x → right, y → up, z → −forward).
     */
    public OrbitView turned(Arcball.Turn t) {
        if (t.angle() == 0) {
            return this;
        }
        Vec3 f = forward();
        Vec3 a = right.scale(t.axis().x()).add(up.scale(t.axis().y())).sub(f.scale(t.axis().z())).normalize();
        Vec3 r2 = rotate(right, a, -t.angle());
        Vec3 u2 = rotate(up, a, -t.angle());
        // Re-orthonormalise against drift
        Vec3 f2 = u2.cross(r2).normalize();
        r2 = f2.cross(u2).normalize();
        u2 = r2.cross(f2).normalize();
        return new OrbitView(target, radius, r2, u2, zoom, fovDegrees);
    }

    /** The view zoomed by {@code factor} (greater than 1 moves away). */
    public OrbitView zoomed(double factor) {
        double z = Math.max(0.02, Math.min(50, zoom * factor));
        return new OrbitView(target, radius, right, up, z, fovDegrees);
    }

    public OrbitView withFov(double fov) {
        return new OrbitView(target, radius, right, up, zoom, Math.max(0, Math.min(MAX_FOV_DEGREES, fov)));
    }

    /** Same orientation and zoom, re-centred on another model. */
    public OrbitView reframed(Aabb bounds) {
        return withFraming(Framing.of(bounds));
    }

    /** Rodrigues rotation of {@code v} about unit {@code axis} by {@code angle} radians. */
    static Vec3 rotate(Vec3 v, Vec3 axis, double angle) {
        double c = Math.cos(angle), s = Math.sin(angle);
        return v.scale(c).add(axis.cross(v).scale(s)).add(axis.scale(axis.dot(v) * (1 - c)));
    }
}
