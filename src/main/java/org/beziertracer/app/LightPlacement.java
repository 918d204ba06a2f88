package org.beziertracer.app;

import java.util.List;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.Scene;

/**
 * Where the light is: the scene's own lights, one light at the eye (the memoir's light at the
 * centre of projection; it follows the camera), or one light fixed in the scene at a corner of
 * the model's bounding box scaled out by two radii.
 */
public enum LightPlacement {
    SCENE("Scene's lights"),
    AT_EYE("At the eye"),
    ABOVE_LEFT("Above left"),
    ABOVE_RIGHT("Above right"),
    BELOW("Below");

    private final String label;

    LightPlacement(String label) { this.label = label; }

    @Override
    public String toString() { return label; }

    /**
     * The scene to render: {@code scene} itself for {@link #SCENE} (a scene without lights is lit
     * from the eye by the renderer), no lights for {@link #AT_EYE}, else one fixed light.
     */
    public Scene apply(Scene scene) {
        return switch (this) {
            case SCENE -> scene;
            case AT_EYE -> scene.lights().isEmpty() ? scene : scene.toBuilder().lights(List.of()).build();
            default -> scene.toBuilder().lights(List.of(new PointLight(position(scene.controlBounds())))).build();
        };
    }

    /** Position of a fixed light for a model with these bounds. */
    Vec3 position(Aabb box) {
        Vec3 c = box.isEmpty() ? Vec3.ZERO : box.center();
        double r = box.isEmpty() ? 1 : Math.max(1e-6, box.diagonal());
        Vec3 dir = switch (this) {
            case ABOVE_LEFT -> new Vec3(-1, -1, 1.5);
            case ABOVE_RIGHT -> new Vec3(1, -1, 1.5);
            default -> new Vec3(0.3, -0.5, -1.5);
        };
        return c.add(dir.normalize().scale(2 * r));
    }
}
