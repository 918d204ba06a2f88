package org.beziertracer.render;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;

/**
 * Look-at pinhole camera with a <b>horizontal</b> field of view, or an orthographic camera when
 * the field of view is 0 (then {@code orthoWidth} is the width of the view in scene units).
 *
 * <p>Image coordinates: pixel (i, j) counts from the top-left corner; the continuous point
 * {@code (x, y) = (i + 0.5, j + 0.5)} is the pixel's centre, and a sampler adds sub-pixel offsets
 * to {@code i, j}. With {@code sx = (2x/W − 1)·tan(fov/2)} and {@code sy = (1 − 2y/H)·tan(fov/2)·H/W}
 * the perspective ray is {@code eye + t (forward + sx·right + sy·up)} (direction not normalised,
 * so {@code t = 1} lies on the image plane one unit in front of the eye). The orthographic ray starts at
 * {@code eye + sx'·right + sy'·up} (with {@code tan(fov/2)} replaced by {@code orthoWidth/2})
 * and runs along {@code forward}.
 *
 * <p>Immutable and thread-safe; {@link #generateRay} writes into a caller-owned array and
 * allocates nothing. {@link #orbit}, {@link #zoom} and the {@code with…} methods return new cameras.
 */
public final class Camera {

    /** Default direction from the target toward the eye for {@link #fit}: front-left, above (z-up models). */
    public static final Vec3 DEFAULT_VIEW = new Vec3(-0.35, -1, 0.6);
    /** Default horizontal field of view of {@link #fit}, degrees. */
    public static final double DEFAULT_FOV = 40;

    private final Vec3 eye, target, up;
    private final double fovDegrees, orthoWidth;
    // Orthonormal frame: forward (toward the target), right, true up
    private final double fx, fy, fz, rx, ry, rz, ux, uy, uz;
    /** tan(fov/2) for perspective, orthoWidth/2 for orthographic. */
    private final double halfWidth;

    public Camera(CameraSpec spec) {
        this.eye = spec.eye();
        this.target = spec.target();
        this.up = spec.up();
        this.fovDegrees = spec.fovDegrees();
        this.orthoWidth = spec.orthoWidth();
        Vec3 f = target.sub(eye).normalize();
        Vec3 r = f.cross(up).normalize();
        Vec3 u = r.cross(f);
        fx = f.x(); fy = f.y(); fz = f.z();
        rx = r.x(); ry = r.y(); rz = r.z();
        ux = u.x(); uy = u.y(); uz = u.z();
        halfWidth = fovDegrees == 0 ? orthoWidth / 2 : Math.tan(Math.toRadians(fovDegrees) / 2);
    }

    /** Perspective look-at camera; {@code fovDegrees} is horizontal, 0 &lt; fov &lt; 179. */
    public static Camera lookAt(Vec3 eye, Vec3 target, Vec3 up, double fovDegrees) {
        return new Camera(CameraSpec.perspective(eye, target, up, fovDegrees));
    }

    /** Orthographic camera showing {@code viewWidth} scene units across. */
    public static Camera orthographic(Vec3 eye, Vec3 target, Vec3 up, double viewWidth) {
        return new Camera(new CameraSpec(eye, target, up, 0, viewWidth));
    }

    /**
     * Writes the ray through the continuous image point {@code (x, y)} (pixels from the top-left;
     * pixel centres at {@code i + 0.5}) of a {@code width × height} image into
     * {@code ray[0..5] = ox, oy, oz, dx, dy, dz}. Allocation-free.
     */
    public void generateRay(double x, double y, int width, int height, double[] ray) {
        generateRay(x, y, width, height, ray, 0);
    }

    /** {@link #generateRay(double, double, int, int, double[])} into {@code ray[at..at+5]}. */
    public void generateRay(double x, double y, int width, int height, double[] ray, int at) {
        // (1 − 2y/height)·halfWidth·height/width, with one division a ray instead of three
        double invWidth = 1.0 / width;
        double sx = (2 * x * invWidth - 1) * halfWidth;
        double sy = (height - 2 * y) * invWidth * halfWidth;
        if (fovDegrees == 0) {
            ray[at] = eye.x() + sx * rx + sy * ux;
            ray[at + 1] = eye.y() + sx * ry + sy * uy;
            ray[at + 2] = eye.z() + sx * rz + sy * uz;
            ray[at + 3] = fx; ray[at + 4] = fy; ray[at + 5] = fz;
        } else {
            ray[at] = eye.x(); ray[at + 1] = eye.y(); ray[at + 2] = eye.z();
            ray[at + 3] = fx + sx * rx + sy * ux;
            ray[at + 4] = fy + sx * ry + sy * uy;
            ray[at + 5] = fz + sx * rz + sy * uz;
        }
    }

    /**
     * Rotates the eye about the target: {@code yawDegrees} about the up vector, then
     * {@code pitchDegrees} about the camera's right axis (positive raises the eye). The pitch is
     * limited so the view never passes through the up direction.
     */
    public Camera orbit(double yawDegrees, double pitchDegrees) {
        Vec3 upUnit = up.normalize();
        Vec3 offset = rotate(eye.sub(target), upUnit, Math.toRadians(yawDegrees));
        double dist = offset.length();
        double elevation = Math.asin(Math.max(-1, Math.min(1, offset.dot(upUnit) / dist)));
        double limit = Math.toRadians(89);
        double pitch = Math.max(-limit - elevation, Math.min(limit - elevation, Math.toRadians(pitchDegrees)));
        Vec3 right = upUnit.cross(offset);
        if (right.length() > 1e-12 * dist) {
            offset = rotate(offset, right.normalize(), -pitch);
        }
        return with(target.add(offset), target, fovDegrees, orthoWidth);
    }

    /**
     * Moves the eye along the view axis: the eye–target distance is multiplied by {@code factor}
     * (&lt; 1 moves closer). An orthographic camera scales its view width instead.
     */
    public Camera zoom(double factor) {
        if (!(factor > 0) || !Double.isFinite(factor)) {
            throw new IllegalArgumentException("zoom factor must be positive, got " + factor);
        }
        if (fovDegrees == 0) {
            return with(eye, target, 0, orthoWidth * factor);
        }
        return with(target.add(eye.sub(target).scale(factor)), target, fovDegrees, orthoWidth);
    }

    /** The same camera with another field of view (0 = orthographic, keeping the visible width at the target). */
    public Camera withFov(double newFovDegrees) {
        double width = newFovDegrees == 0 && fovDegrees != 0
                ? 2 * halfWidth * eye.sub(target).length() : orthoWidth;
        return with(eye, target, newFovDegrees, width);
    }

    private Camera with(Vec3 e, Vec3 t, double fov, double width) {
        return new Camera(new CameraSpec(e, t, up, fov, width));
    }

    /**
     * Frames a box: the eye looks at the box centre from {@link #DEFAULT_VIEW} (z up), or, for a
     * box that is flat in z, from a steeper direction so a flat patch is clearly visible; the
     * distance is the smallest at which every corner is inside the view (plus a 5% margin).
     *
     * @param box        what must be visible (not empty)
     * @param aspect     image width / height
     * @param fovDegrees horizontal field of view; 0 gives an orthographic camera
     */
    public static Camera fit(Aabb box, double aspect, double fovDegrees) {
        if (box.isEmpty()) {
            box = new Aabb(-1, -1, -1, 1, 1, 1);
        }
        Vec3 c = box.center();
        double diag = Math.max(box.diagonal(), 1e-9);
        boolean flatInZ = box.maxZ() - box.minZ() < 0.01 * diag;
        Vec3 back = (flatInZ ? new Vec3(-0.35, -1, 1.3) : DEFAULT_VIEW).normalize();
        Vec3 f = back.scale(-1);
        Vec3 r = f.cross(Vec3.Z).normalize();
        Vec3 u = r.cross(f);
        double tanH = fovDegrees == 0 ? 1 : Math.tan(Math.toRadians(fovDegrees) / 2);
        double tanV = tanH / aspect;
        double dist = 0, halfW = 0;
        for (int k = 0; k < 8; k++) {
            Vec3 q = new Vec3((k & 1) == 0 ? box.minX() : box.maxX(), (k & 2) == 0 ? box.minY() : box.maxY(),
                    (k & 4) == 0 ? box.minZ() : box.maxZ()).sub(c);
            double qr = Math.abs(q.dot(r)), qu = Math.abs(q.dot(u)), qf = q.dot(f);
            dist = Math.max(dist, Math.max(qf + qr / tanH, qf + qu / tanV));
            halfW = Math.max(halfW, Math.max(qr, qu * aspect));
        }
        if (fovDegrees == 0) {
            return orthographic(c.add(back.scale(diag)), c, Vec3.Z, 2 * halfW * 1.05);
        }
        dist = Math.max(dist * 1.05, 1e-6 * diag);
        return lookAt(c.add(back.scale(dist)), c, Vec3.Z, fovDegrees);
    }

    /** Rodrigues rotation of {@code v} about the unit axis {@code k} by {@code angle} radians. */
    private static Vec3 rotate(Vec3 v, Vec3 k, double angle) {
        double cos = Math.cos(angle), sin = Math.sin(angle);
        return v.scale(cos).add(k.cross(v).scale(sin)).add(k.scale(k.dot(v) * (1 - cos)));
    }

    public CameraSpec spec() { return new CameraSpec(eye, target, up, fovDegrees, orthoWidth); }

    public Vec3 eye() { return eye; }

    public Vec3 target() { return target; }

    public Vec3 up() { return up; }

    public double fovDegrees() { return fovDegrees; }

    public double orthoWidth() { return orthoWidth; }

    public boolean isOrthographic() { return fovDegrees == 0; }

    /** Unit view direction (eye toward target). */
    public Vec3 forward() { return new Vec3(fx, fy, fz); }

    @Override
    public String toString() {
        return "Camera[eye=" + eye + ", target=" + target + ", up=" + up + ", fov=" + fovDegrees
                + (fovDegrees == 0 ? ", width=" + orthoWidth : "") + "]";
    }
}
