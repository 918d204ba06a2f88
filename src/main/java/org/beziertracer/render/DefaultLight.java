package org.beziertracer.render;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;

/**
 * The light a model without lights of its own is shown with, in the desktop app (its default
 * "Above left of the eye" placement) and on the command line ({@code render}): placed from the
 * model's <b>bounding sphere</b> (centre {@code c}, radius {@code R}), not from the eye, so it
 * never lands inside or on the edge of the model whatever the eye's distance:
 * {@code c + R·(x·right + y·up + z·forward)} in the camera's orthonormal frame (forward from the
 * eye to the target, right = forward × up, up = right × forward). The preset {@link #OFFSET} puts it
 * above left of the line of sight, towards the eye, about 1.5 radii from the centre and 21° off the
 * view axis: a sphere is lit over about nine tenths of its disc with a visible fall-off (three-point
 * lighting's key light, as a photographer sets it), and at the default framing (eye three to four
 * radii away, 40° field) the light lies inside the picture, even a picture taller than wide, where
 * its marker can be dragged.
 * Stateless.
 */
public final class DefaultLight {
    private DefaultLight() {}

    /** The preset offset, in bounding-sphere radii along the camera's right, up and forward axes. */
    public static final Vec3 OFFSET = new Vec3(-0.45, 0.3, -1.4);

    /** The light at {@code offset} (radii along right, up, forward) from the sphere {@code (centre, radius)}. */
    public static Vec3 position(CameraSpec camera, Vec3 centre, double radius, Vec3 offset) {
        Vec3[] axes = axes(camera);
        double r = radius > 0 ? radius : 1;
        return centre.add(axes[0].scale(offset.x() * r)).add(axes[1].scale(offset.y() * r)).add(axes[2].scale(offset.z() * r));
    }

    /** The offset (radii along right, up, forward) of {@code position} from the sphere: the inverse of {@link #position}. */
    public static Vec3 offsetOf(CameraSpec camera, Vec3 centre, double radius, Vec3 position) {
        Vec3[] axes = axes(camera);
        double r = radius > 0 ? radius : 1;
        Vec3 d = position.sub(centre);
        return new Vec3(d.dot(axes[0]) / r, d.dot(axes[1]) / r, d.dot(axes[2]) / r);
    }

    /** The default light for a model in {@code bounds} seen by {@code camera} (the sphere around the box). */
    public static Vec3 position(CameraSpec camera, Aabb bounds) {
        if (bounds.isEmpty()) {
            return camera.eye();
        }
        return position(camera, bounds.center(), 0.5 * bounds.diagonal(), OFFSET);
    }

    /** Camera right, up and forward (unit, orthonormal). */
    private static Vec3[] axes(CameraSpec camera) {
        Vec3 f = camera.target().sub(camera.eye()).normalize();
        Vec3 r = f.cross(camera.up()).normalize();
        return new Vec3[] {r, r.cross(f), f};
    }
}
