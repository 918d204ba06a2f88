package org.beziertracer.ui;

import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;

/**
 * One picture to render, built on the event thread from immutable parts.
 *
 * @param scene          the scene as rendered (lights already placed)
 * @param camera         the view
 * @param settings       size in device pixels, samples, method, BVH, shading, checker, shadows, depth
 * @param passesPerFrame progressive passes per displayed frame (the memoir's interactivity)
 * @param target         the picture to paint into; its size equals the settings' size
 * @param tessellate     0: exact Bézier intersection; {@code K ≥ 1}: a uniform K×K triangle mesh per patch
 */
public record RenderRequest(Scene scene, CameraSpec camera, RenderSettings settings, int passesPerFrame,
                            FrameBuffer target, int tessellate) {

    /** An exact (not tessellated) render. */
    public RenderRequest(Scene scene, CameraSpec camera, RenderSettings settings, int passesPerFrame, FrameBuffer target) {
        this(scene, camera, settings, passesPerFrame, target, 0);
    }
}
