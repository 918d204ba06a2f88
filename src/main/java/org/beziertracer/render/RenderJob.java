package org.beziertracer.render;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.math.Aabb;
import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;

/**
 * Everything one render needs: the intersection snapshot (which holds the immutable
 * {@link Scene}), the camera, the scene-file settings and the engine options. Immutable; the UI
 * builds a new job for every edit, camera move or settings change and passes it to
 * {@link RenderSession#start}. The image size is {@code settings.width() × settings.height()}.
 *
 * <p>The intersector must have been built with the method and BVH switch the settings ask for
 * (and the tessellation the options ask for);
 * {@link #prepare} does that. An edit of one patch can reuse the old snapshot via
 * {@link SceneIntersector#withPatch} in a new job.
 *
 * <p>{@code lights}, when not null, replaces the scene's lights for shading only (the desktop
 * app's light placements, some of which follow the camera): a light that moves then needs no
 * new intersector.
 *
 * <p>{@code window} is the piece of the image to render ({@code render --crop}, {@code --tile}); the
 * camera and the samples stay the whole image's, so the window's pixels are byte-identical to the
 * same pixels of the whole render. Null in the constructor means the whole image.
 */
public record RenderJob(SceneIntersector intersector, Camera camera, RenderSettings settings, RenderOptions options,
                        List<PointLight> lights, PixelWindow window) {

    public RenderJob {
        if (intersector == null || camera == null || settings == null || options == null) {
            throw new IllegalArgumentException("intersector, camera, settings and options are required");
        }
        lights = lights == null ? null : List.copyOf(lights);
        window = window == null ? PixelWindow.whole(settings.width(), settings.height()) : window;
        if (!window.fits(settings.width(), settings.height())) {
            throw new IllegalArgumentException("the pixel window " + window + " is outside the "
                    + settings.width() + "x" + settings.height() + " image");
        }
    }

    /** The whole image, lit by {@code lights} (null: the scene's own). */
    public RenderJob(SceneIntersector intersector, Camera camera, RenderSettings settings, RenderOptions options,
                     List<PointLight> lights) {
        this(intersector, camera, settings, options, lights, null);
    }

    /** A job lit by the scene's own lights (or, with none, by one light at the eye). */
    public RenderJob(SceneIntersector intersector, Camera camera, RenderSettings settings, RenderOptions options) {
        this(intersector, camera, settings, options, null);
    }

    /**
     * Builds the intersector (method and BVH from {@code settings}, exact or tessellated from
     * {@link RenderOptions#tessellate()}) and picks the camera: the scene's
     * own, else {@link #defaultCamera}.
     */
    public static RenderJob prepare(Scene scene, RenderSettings settings, RenderOptions options) {
        SceneIntersector si = SceneIntersector.build(scene, intersectOptions(settings, options));
        Camera camera = scene.camera().map(Camera::new)
                .orElseGet(() -> defaultCamera(scene, (double) settings.width() / settings.height()));
        return new RenderJob(si, camera, settings, options);
    }

    /** The intersection options {@link #prepare} builds with: method and BVH from the settings, K from the options. */
    public static IntersectOptions intersectOptions(RenderSettings settings, RenderOptions options) {
        return IntersectOptions.defaults().withMethod(Method.parse(settings.method())).withBvh(settings.bvh())
                .withTessellate(options.tessellate()).withKernel(options.kernel());
    }

    /** {@link Camera#fit} of {@link #bounds(Scene)} with the default 40° field of view. */
    public static Camera defaultCamera(Scene scene, double aspect) {
        return Camera.fit(bounds(scene), aspect, Camera.DEFAULT_FOV);
    }

    /**
     * The finite part of the scene: control boxes of the patches, boxes of the meshes and of the spheres (planes are
     * infinite; a scene of planes only gets the unit box around the first plane's point).
     */
    public static Aabb bounds(Scene scene) {
        Aabb box = scene.bounds();
        for (Sphere s : scene.spheres()) {
            Vec3 r = new Vec3(s.radius(), s.radius(), s.radius());
            box = box.union(s.center().sub(r)).union(s.center().add(r));
        }
        if (box.isEmpty() && !scene.planes().isEmpty()) {
            Vec3 p = scene.planes().get(0).point();
            box = box.union(p.sub(new Vec3(1, 1, 1))).union(p.add(new Vec3(1, 1, 1)));
        }
        return box;
    }

    public Scene scene() { return intersector.scene(); }

    public int width() { return settings.width(); }

    public int height() { return settings.height(); }

    public ShadingMode shading() { return ShadingMode.parse(settings.shading()); }

    public SamplerKind sampler() { return SamplerKind.parse(settings.sampler()); }

    public RenderJob withCamera(Camera c) { return new RenderJob(intersector, c, settings, options, lights, window); }

    /** Same intersector: only for options with the same {@link RenderOptions#tessellate()}. */
    public RenderJob withOptions(RenderOptions o) { return new RenderJob(intersector, camera, settings, o, lights, window); }

    /** The same job shaded with {@code l} instead of the scene's lights (null: the scene's own). */
    public RenderJob withLights(List<PointLight> l) { return new RenderJob(intersector, camera, settings, options, l, window); }

    /** The same job rendering only the pixels of {@code w} (null: the whole image). */
    public RenderJob withWindow(PixelWindow w) { return new RenderJob(intersector, camera, settings, options, lights, w); }

    /**
     * The pixels the film must hold to render {@link #window()} exactly as the whole image does: the
     * window itself, grown by one pixel (inside the image) when the adaptive sampler compares each
     * pixel's first sample with its four neighbours'.
     */
    public PixelWindow filmWindow() {
        boolean neighbours = sampler() == SamplerKind.ADAPTIVE && settings.spp() > 1;
        return neighbours ? window.grow(1, width(), height()) : window;
    }
}
