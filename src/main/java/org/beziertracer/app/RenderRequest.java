package org.beziertracer.app;

import java.util.List;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.render.Camera;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;

/**
 * One picture to render, made on the UI thread in constant time from immutable parts; the engine
 * does everything that grows with the model (placing the light, building the snapshot) on its own
 * thread.
 *
 * @param scene     the edited scene
 * @param lights    the lights to shade with ({@link LightRig#lights}), or null for the scene's own
 * @param camera    the view
 * @param settings  size in device pixels, samples, shading, checker, shadows, depth
 * @param intersect method, BVH switch and tessellation, typed
 * @param options   passes per displayed frame and tessellation
 * @param target    the picture to paint into; its size equals the settings' size
 */
public record RenderRequest(Scene scene, List<PointLight> lights, CameraSpec camera, RenderSettings settings,
                            IntersectOptions intersect, RenderOptions options, Picture target) {

    /** The request for {@code s} with everything taken from the app's settings; {@code framing} places a fixed light. */
    public static RenderRequest of(Scene scene, CameraSpec camera, Framing framing, Settings s, Picture target) {
        return of(scene, camera, framing, s, target, false);
    }

    /**
     * As {@link #of(Scene, CameraSpec, Framing, Settings, Picture)}; a {@code preview} of a
     * path-traced picture (while the view turns or points are dragged) takes one sample a pixel
     * and then stops.
     */
    public static RenderRequest of(Scene scene, CameraSpec camera, Framing framing, Settings s, Picture target,
                                   boolean preview) {
        int spp = preview && s.pathTraced() ? 1 : RenderChoices.renderSettings(s, 1, 1).spp();
        return new RenderRequest(scene, LightRig.lights(s, camera, framing), camera,
                RenderChoices.renderSettings(s, target.width(), target.height(), spp), RenderChoices.intersectOptions(s),
                RenderChoices.renderOptions(s), target);
    }

    /** True when the path tracer renders this request. */
    public boolean pathTraced() { return options.path().traced(); }

    /**
     * The render job of this request over {@code snapshot}, the {@link #scene} intersected with
     * {@link #intersect} (the engine's snapshot, or a fresh build when a test renders the same
     * request from scratch), shaded with the request's {@link #lights}.
     */
    public RenderJob job(SceneIntersector snapshot) {
        return new RenderJob(snapshot, new Camera(camera), settings, options, lights);
    }
}
