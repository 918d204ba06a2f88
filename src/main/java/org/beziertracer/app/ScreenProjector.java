package org.beziertracer.app;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;

/**
 * Maps scene points to picture pixels and pixels back to rays, with the renderer's camera
 * convention: look-at frame {@code f = normalize(target − eye)}, {@code r = normalize(f × up)},
 * {@code u = r × f}; <b>horizontal</b> field of view; pixel {@code (i, j)} from the top-left
 * has its centre at {@code ((i + 0.5)/W, (j + 0.5)/H)}. Pixel coordinates here are continuous:
 * a point projecting to {@code (x, y)} lies in pixel {@code (floor x, floor y)}. Orthographic
 * when the field of view is 0, with {@link CameraSpec#orthoWidth()} the visible width.
 *
 * <p>Immutable; width and height are in device pixels (the picture's own pixels).
 */
public final class ScreenProjector {

    private final CameraSpec camera;
    private final int width;
    private final int height;
    private final Vec3 eye, f, r, u;
    private final double halfW, halfH;
    private final boolean ortho;

    public ScreenProjector(CameraSpec camera, int width, int height) {
        this.camera = camera;
        this.width = Math.max(1, width);
        this.height = Math.max(1, height);
        eye = camera.eye();
        f = camera.target().sub(eye).normalize();
        r = f.cross(camera.up()).normalize();
        u = r.cross(f);
        ortho = camera.fovDegrees() == 0;
        halfW = ortho ? camera.orthoWidth() / 2 : Math.tan(Math.toRadians(camera.fovDegrees()) / 2);
        halfH = halfW * this.height / this.width;
    }

    public CameraSpec camera() { return camera; }

    public int width() { return width; }

    public int height() { return height; }

    /** Unit view direction (eye towards target). */
    public Vec3 forward() { return f; }

    /**
     * Projects {@code (x, y, z)} into {@code out[0..2]} = pixel x, pixel y, depth along the view
     * axis. Returns false (and leaves {@code out} unspecified) for a perspective point at or
     * behind the eye plane.
     */
    public boolean project(double x, double y, double z, double[] out) {
        double px = x - eye.x(), py = y - eye.y(), pz = z - eye.z();
        double depth = px * f.x() + py * f.y() + pz * f.z();
        double sx = px * r.x() + py * r.y() + pz * r.z();
        double sy = px * u.x() + py * u.y() + pz * u.z();
        if (!ortho) {
            if (depth <= 1e-9) {
                return false;
            }
            sx /= depth;
            sy /= depth;
        }
        out[0] = (sx / halfW + 1) * 0.5 * width;
        out[1] = (1 - sy / halfH) * 0.5 * height;
        out[2] = depth;
        return true;
    }

    /** The primary ray through continuous pixel position {@code (x, y)}: {@code [origin, unit direction]}. */
    public Vec3[] ray(double x, double y) {
        double sx = 2 * x / width - 1;
        double sy = 1 - 2 * y / height;
        if (ortho) {
            Vec3 o = eye.add(r.scale(sx * halfW)).add(u.scale(sy * halfH));
            return new Vec3[] {o, f};
        }
        Vec3 d = f.add(r.scale(sx * halfW)).add(u.scale(sy * halfH)).normalize();
        return new Vec3[] {eye, d};
    }

    /**
     * Where the ray through pixel {@code (x, y)} meets the plane parallel to the screen through
     * {@code p} — the plane a dragged control point moves in.
     */
    public Vec3 onScreenPlane(double x, double y, Vec3 p) {
        Vec3[] ray = ray(x, y);
        double denom = ray[1].dot(f);
        double t = p.sub(ray[0]).dot(f) / denom;
        return ray[0].add(ray[1].scale(t));
    }

    /**
     * The point of the line through {@code p} along the unit vector {@code axis} nearest to the ray
     * through pixel {@code (x, y)} — where a point dragged along that axis goes; {@code p} itself
     * when the axis points (almost) along the ray.
     */
    public Vec3 onLine(double x, double y, Vec3 p, Vec3 axis) {
        Vec3[] ray = ray(x, y);
        Vec3 w = ray[0].sub(p);
        double b = ray[1].dot(axis), d = ray[1].dot(w), e = axis.dot(w);
        double denom = 1 - b * b;
        if (denom < 1e-9) {
            return p;
        }
        return p.add(axis.scale((e - b * d) / denom));
    }

    /** The unit vector of the screen's x axis (to the right) in the scene. */
    public Vec3 right() { return r; }

    /** The unit vector of the screen's y axis (up) in the scene. */
    public Vec3 up() { return u; }
}
