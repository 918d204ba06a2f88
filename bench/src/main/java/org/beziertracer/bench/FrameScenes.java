package org.beziertracer.bench;

import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.beziertracer.render.Camera;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;

/**
 * The two reference frames of the renderer issue, as {@link RenderJob}s (setup-time only; the
 * rendering itself is {@code Renderer.renderOnce}):
 * <ul>
 * <li>{@code teapot}: 800×600, 1 spp, Phong + shadow rays, eye (-150,-420,260), target (10,0,55),
 * up (0,0,1), horizontal fov 40°, one white light at (-200,-350,450) — the same frame as
 * {@code render teapot --size 800x600 --eye -150,-420,260 --target 10,0,55 --up 0,0,1 --fov 40
 * --light -200,-350,450};</li>
 * <li>{@code patch}: the default bicubic patch, 800×600, its default settings and "fit model"
 * camera, light at the eye — {@code render patch --size 800x600}.</li>
 * </ul>
 */
public final class FrameScenes {
    private FrameScenes() {}

    public static final int WIDTH = 800;
    public static final int HEIGHT = 600;

    /** The teapot view's camera. */
    public static Camera teapotCamera() {
        return Camera.lookAt(new Vec3(-150, -420, 260), new Vec3(10, 0, 55), new Vec3(0, 0, 1), 40);
    }

    /** The scene (lights placed) of {@code name}, {@code teapot} or {@code patch}. */
    public static Scene scene(String name) {
        SceneDocument doc = SceneFiles.load(name);
        Scene scene = doc.scene();
        if (name.equals("teapot")) {
            scene = scene.toBuilder().lights(List.of(new PointLight(new Vec3(-200, -350, 450)))).build();
        }
        return scene;
    }

    /**
     * The full job: scene, 800×600 settings (1 spp, Phong, shadows, the document's method and BVH),
     * camera, {@code threads} workers, one-shot (not progressive), {@code tessellate} 0 = exact.
     */
    public static RenderJob job(String name, int threads, int tessellate) {
        if (!name.equals("teapot") && !name.equals("patch")) {
            throw new IllegalArgumentException("scene must be teapot or patch, got " + name);
        }
        SceneDocument doc = SceneFiles.load(name);
        RenderSettings s = doc.settings();
        RenderSettings settings = new RenderSettings(WIDTH, HEIGHT, 1, s.sampler(), s.method(), s.bvh(), "phong",
                s.checker(), true, s.maxDepth());
        RenderOptions options = RenderOptions.defaults().withThreads(threads).withProgressive(false)
                .withTessellate(tessellate);
        RenderJob job = RenderJob.prepare(scene(name), settings, options);
        return name.equals("teapot") ? job.withCamera(teapotCamera()) : job;
    }
}
