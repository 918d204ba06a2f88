package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.Scene;
import org.beziertracer.render.DefaultLight;

/**
 * The light of the settings ({@link LightPlacement} and its offset) in the scene for one view: where
 * it is, and the offset that puts it somewhere else (a dragged light marker). Everything here is
 * O(lights), so it runs on the UI thread; the renderer gets the lights with each request and needs
 * no new snapshot when a light that follows the view moves. Stateless.
 */
public final class LightRig {
    private LightRig() {}

    /**
     * The lights to render with: null for {@link LightPlacement#SCENE} (the scene's own, or the
     * renderer's light at the eye when it has none), else the one light of the placement.
     */
    public static List<PointLight> lights(Settings s, CameraSpec camera, Framing framing) {
        Vec3 p = position(s.light(), s.lightOffset(), camera, framing);
        return p == null ? null : List.of(new PointLight(p));
    }

    /** Where the light of {@code placement} with {@code offset} is, or null for {@link LightPlacement#SCENE}. */
    public static Vec3 position(LightPlacement placement, Vec3 offset, CameraSpec camera, Framing framing) {
        return switch (placement.frame()) {
            case SCENE -> null;
            case WORLD -> framing.target().add(offset.scale(radius(framing)));
            case MODEL -> DefaultLight.position(camera, framing.target(), framing.radius(), offset);
            case VIEW -> {
                Vec3[] axes = axes(camera);
                double dist = camera.target().sub(camera.eye()).length();
                yield camera.eye().add(axes[0].scale(offset.x() * dist)).add(axes[1].scale(offset.y() * dist))
                        .add(axes[2].scale(offset.z() * dist));
            }
        };
    }

    /** The offset that puts the light of {@code placement} at {@code position} (the inverse of {@link #position}). */
    public static Vec3 offsetOf(LightPlacement placement, Vec3 position, CameraSpec camera, Framing framing) {
        return switch (placement.frame()) {
            case SCENE -> null;
            case WORLD -> position.sub(framing.target()).scale(1 / radius(framing));
            case MODEL -> DefaultLight.offsetOf(camera, framing.target(), framing.radius(), position);
            case VIEW -> {
                Vec3[] axes = axes(camera);
                Vec3 d = position.sub(camera.eye());
                double dist = camera.target().sub(camera.eye()).length();
                yield new Vec3(d.dot(axes[0]) / dist, d.dot(axes[1]) / dist, d.dot(axes[2]) / dist);
            }
        };
    }

    /**
     * The lights a "Show light" marker is drawn for: the placement's light, or the scene's own
     * lights (which cannot be dragged). Positions in the scene.
     */
    public static List<Vec3> shown(Settings s, Scene scene, CameraSpec camera, Framing framing) {
        if (s.light() != LightPlacement.SCENE) {
            return List.of(position(s.light(), s.lightOffset(), camera, framing));
        }
        List<Vec3> out = new ArrayList<>();
        for (PointLight l : scene.lights()) {
            out.add(l.position());
        }
        return out;
    }

    /** Camera right, up and forward, as the picture has them. */
    private static Vec3[] axes(CameraSpec camera) {
        ScreenProjector p = new ScreenProjector(camera, 1, 1);
        return new Vec3[] {p.right(), p.up(), p.forward()};
    }

    private static double radius(Framing framing) {
        return framing.radius() > 0 ? framing.radius() : 1;
    }
}
