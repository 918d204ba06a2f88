package org.beziertracer.app;

import org.beziertracer.math.Vec3;
import org.beziertracer.render.DefaultLight;

/**
 * Where the light is, as the toolbox offers it: the scene's own lights; one light that follows
 * the view — above and to the left of the eye (the default, so that a surface's relief reads at
 * once), or at the eye itself (the memoir's light at the centre of projection); or one light fixed
 * in the scene, beside the model. A light that follows the view or is fixed in the scene can be
 * dragged to another place ({@link LightRig}); the preset's {@link #preset() offset} is where it
 * starts.
 */
public enum LightPlacement {
    SCENE("Scene's lights", Frame.SCENE, null),
    /**
     * The default, shared with the command line ({@link DefaultLight}): up and to the left as seen
     * from the eye, between the eye and the model, placed from the model's bounding sphere so that
     * it never sits inside or on the edge of the model; at the default perspective its marker shows
     * inside the picture.
     */
    EYE_ABOVE_LEFT("Above left of the eye", Frame.MODEL, DefaultLight.OFFSET),
    AT_EYE("At the eye", Frame.VIEW, Vec3.ZERO),
    ABOVE_LEFT("Above left", Frame.WORLD, new Vec3(-1, -1, 1.5).normalize().scale(4)),
    ABOVE_RIGHT("Above right", Frame.WORLD, new Vec3(1, -1, 1.5).normalize().scale(4)),
    BELOW("Below", Frame.WORLD, new Vec3(0.3, -0.5, -1.5).normalize().scale(4));

    /** What a placement's offset is measured in. */
    public enum Frame {
        /** No offset: the scene's own lights (with none, the renderer puts one at the eye). */
        SCENE,
        /**
         * Follows the view: the offset from the eye along the camera's right, up and forward axes,
         * in eye-to-target distances.
         */
        VIEW,
        /**
         * Follows the view: the offset from the centre of the view's framing (the model's bounding
         * sphere) along the camera's right, up and forward axes, in framing radii ({@link DefaultLight}).
         */
        MODEL,
        /** Fixed in the scene: the offset from the centre of the view's framing, in framing radii. */
        WORLD
    }

    private final String label;
    private final Frame frame;
    private final Vec3 preset;

    LightPlacement(String label, Frame frame, Vec3 preset) {
        this.label = label;
        this.frame = frame;
        this.preset = preset;
    }

    @Override
    public String toString() { return label; }

    public Frame frame() { return frame; }

    /** Where the light starts (in {@link #frame()} units), or null for {@link #SCENE}. */
    public Vec3 preset() { return preset; }
}
