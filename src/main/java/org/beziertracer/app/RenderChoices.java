package org.beziertracer.app;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.render.Integrator;
import org.beziertracer.render.PathOptions;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.SamplerKind;
import org.beziertracer.render.ShadingMode;

/**
 * Translates between {@link Settings} and what the renderer and scene files speak: the renderer's
 * {@link RenderSettings}, {@link IntersectOptions} and {@link RenderOptions}, and the settings a
 * scene file brings. Stateless.
 */
public final class RenderChoices {
    private RenderChoices() {}

    /** Checker squares per unit of (u, v) when the texture is on. */
    public static final int CHECKER_SQUARES = 8;
    /** Ray depth with reflections on. */
    public static final int REFLECTION_DEPTH = 5;
    /** Most progressive passes per frame the engine accepts. */
    public static final int MAX_PASSES_PER_FRAME = 16;

    /**
     * The renderer settings for a picture of {@code width × height} device pixels; path traced, the
     * samples are the {@link Level#PATH_SAMPLES} target (jittered, as {@code render --sampler jittered}).
     */
    public static RenderSettings renderSettings(Settings s, int width, int height) {
        return renderSettings(s, width, height, s.pathTraced() ? s.level(Level.PATH_SAMPLES) : s.samplesPerPixel());
    }

    /** As {@link #renderSettings(Settings, int, int)} with {@code spp} samples per pixel. */
    static RenderSettings renderSettings(Settings s, int width, int height, int spp) {
        return new RenderSettings(width, height, spp, SamplerKind.JITTERED.label(), s.method().label(),
                s.on(Toggle.BVH), s.shading().label(), s.on(Toggle.TEXTURE) ? CHECKER_SQUARES : 0,
                s.on(Toggle.SHADOWS), s.on(Toggle.REFLECTIONS) ? REFLECTION_DEPTH : 0);
    }

    /** The intersection options: method, BVH switch and tessellation. */
    public static IntersectOptions intersectOptions(Settings s) {
        return IntersectOptions.defaults().withMethod(s.method()).withBvh(s.on(Toggle.BVH))
                .withTessellate(s.tessellate());
    }

    /**
     * The renderer's options: passes per displayed frame, tessellation, the analysis views' settings
     * and the integrator (path traced: {@link #pathOptions}).
     */
    public static RenderOptions renderOptions(Settings s) {
        int passes = Math.max(1, Math.min(MAX_PASSES_PER_FRAME, s.level(Level.INTERACTIVITY)));
        return RenderOptions.defaults().withPassesPerFrame(passes).withTessellate(s.tessellate())
                .withAnalysis(s.analysisSettings()).withPath(pathOptions(s));
    }

    /**
     * The integrator: Whitted, or when {@link Settings#pathTraced()} the path tracer with its
     * defaults (depth 16, no clamp, as {@code render --integrator path}), the {@link Level#PATH_SECONDS}
     * budget and the {@link Settings#exposure()} of its tone map.
     */
    public static PathOptions pathOptions(Settings s) {
        PathOptions p = PathOptions.defaults();
        return s.pathTraced() ? p.withIntegrator(Integrator.PATH).withBudgetMillis(1000L * s.level(Level.PATH_SECONDS))
                .withExposure(s.exposure()) : p;
    }

    /**
     * {@code s} with what a scene file sets taken over: method, BVH, shading, checker, shadows,
     * depth and samples (snapped to the offered choices). The file's strings are parsed here, once.
     * (The light is chosen by {@link #lightFor}.)
     */
    public static Settings fromScene(Settings s, RenderSettings file) {
        ShadingMode shading = ShadingMode.parse(file.shading());
        Settings out = s.with(Method.parse(file.method()))
                .with(Toggle.BVH, file.bvh())
                .with(Toggle.NORMALS, shading == ShadingMode.NORMALS)
                .with(Toggle.PHONG, shading != ShadingMode.FLAT)
                .with(Toggle.TEXTURE, file.checker() > 0)
                .with(Toggle.SHADOWS, file.shadows())
                .with(Toggle.REFLECTIONS, file.maxDepth() > 0)
                .with(Toggle.SUPER_SAMPLING, file.spp() > 1);
        out = out.withAnalysis(shading.isAnalysis() ? shading : null);
        return file.spp() > 1 ? out.with(Level.SAMPLES_PER_PIXEL, Level.SAMPLES_PER_PIXEL.snap(file.spp())) : out;
    }

    /**
     * True when {@code scene} brings light of its own: point or spot lights, area lights or an
     * environment (the studio scene is lit by an area light and its sky alone; the path tracer then
     * needs no placed light added).
     */
    public static boolean hasOwnLight(org.beziertracer.model.Scene scene) {
        return !scene.lights().isEmpty() || !scene.spotLights().isEmpty() || !scene.areaLights().isEmpty()
                || scene.environment().isPresent();
    }

    /**
     * {@code s} with the light for a newly opened scene: a scene with lights of its own is lit by
     * them; one without keeps the chosen placement, unless that was the scene's lights, which then
     * gives way to the default light (above left of the eye).
     */
    public static Settings lightFor(Settings s, boolean sceneHasLights) {
        if (sceneHasLights) {
            return s.light() == LightPlacement.SCENE ? s : s.with(LightPlacement.SCENE);
        }
        return s.light() == LightPlacement.SCENE ? s.with(Settings.defaults().light()) : s;
    }
}
