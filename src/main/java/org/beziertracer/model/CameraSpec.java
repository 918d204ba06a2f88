package org.beziertracer.model;

import org.beziertracer.math.Vec3;

/**
 * A look-at camera: {@code eye}, {@code target}, {@code up} and the <b>horizontal</b> field of
 * view in degrees; {@code fovDegrees == 0} means orthographic, with {@code orthoWidth} the width
 * of the view in scene units.
 */
public record CameraSpec(Vec3 eye, Vec3 target, Vec3 up, double fovDegrees, double orthoWidth) {
    public CameraSpec {
        if (eye == null || target == null || up == null || !eye.isFinite() || !target.isFinite() || !up.isFinite()) {
            throw new IllegalArgumentException("camera eye, target and up must be finite");
        }
        if (eye.sub(target).length() == 0) {
            throw new IllegalArgumentException("camera eye and target must differ");
        }
        if (!Double.isFinite(eye.sub(target).length())) {
            throw new IllegalArgumentException("camera eye and target are too far apart: their distance overflows"
                    + " (beyond the largest number, about 1.8e308)");
        }
        if (up.length() == 0) {
            throw new IllegalArgumentException("camera up must not be the zero vector");
        }
        if (up.cross(target.sub(eye)).length() <= 1e-12 * up.length() * target.sub(eye).length()) {
            throw new IllegalArgumentException("camera up must not be parallel to the view direction");
        }
        if (!(fovDegrees >= 0 && fovDegrees < 179)) {
            throw new IllegalArgumentException("field of view must be 0 (orthographic) to <179 degrees, got " + fovDegrees);
        }
        if (fovDegrees == 0 && !(orthoWidth > 0 && Double.isFinite(orthoWidth))) {
            throw new IllegalArgumentException("an orthographic camera needs a positive view width, got " + orthoWidth);
        }
    }

    public static CameraSpec perspective(Vec3 eye, Vec3 target, Vec3 up, double fovDegrees) {
        return new CameraSpec(eye, target, up, fovDegrees, 1);
    }
}
