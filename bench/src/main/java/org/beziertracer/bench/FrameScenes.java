package org.beziertracer.bench;

import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.GeneratedModels;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.beziertracer.render.Camera;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;

/**
 * The reference frames of the speed issues, as {@link RenderJob}s (setup-time only; the
 * rendering itself is {@code Renderer.renderOnce}). Every case is 800×600, 1 spp, Phong, shadow
 * rays on, the model's default method and BVH; each built-in case equals a CLI command
 * ({@code render NAME -o out.png --size 800x600 [camera and light flags] --stats --repeat N}):
 * <ul>
 * <li>{@code teapot}: eye (-150,-420,260), target (10,0,55), up (0,0,1), horizontal fov 40°, one
 * white light at (-200,-350,450) — {@code --eye -150,-420,260 --target 10,0,55 --up 0,0,1
 * --fov 40 --light -200,-350,450};</li>
 * <li>{@code patch}: the default bicubic patch, its "fit model" camera, light at the eye (no
 * flags);</li>
 * <li>{@code wavyN} ({@code N = 2..16}; {@code wavy10} is degree 9×9, {@code wavy6} degree
 * 5×5, both built-ins): the generated wavy grid of N×N points, fit camera, light at the eye (no
 * flags);</li>
 * <li>{@code curved}: the strongly curved bicubic arch seen from the side, eye (-4.5,-5,2.5),
 * target (0,0,0.6), light (-2,-4,5), so the arch shadows its own inside — {@code --eye
 * -4.5,-5,2.5 --target 0,0,0.6 --light -2,-4,5}.</li>
 * </ul>
 * {@link #equalK} gives, per case, the smallest tessellation K whose silhouette is within 0.5 px
 * of the exact one ({@code report.SilhouetteAccuracy}), the fair tessellated comparator.
 */
public final class FrameScenes {
    private FrameScenes() {}

    public static final int WIDTH = 800;
    public static final int HEIGHT = 600;

    /** The teapot view's camera. */
    public static Camera teapotCamera() {
        return Camera.lookAt(new Vec3(-150, -420, 260), new Vec3(10, 0, 55), new Vec3(0, 0, 1), 40);
    }

    /** The curved patch's side view. */
    public static Camera curvedCamera() {
        return Camera.lookAt(new Vec3(-4.5, -5, 2.5), new Vec3(0, 0, 0.6), new Vec3(0, 0, 1), 40);
    }

    /**
     * Smallest K whose silhouette is within 0.5 px of the exact one on each case's view
     * (measured by {@code report.SilhouetteAccuracy -s 16 --scene NAME --first …}; tables in
     * docs/performance-journal.md, "Equal accuracy per case"). The default patch is a flat square: two
     * triangles (K = 1) are exact.
     */
    public static int equalK(String name) {
        return switch (name) {
            case "teapot" -> 15;
            case "patch" -> 1;
            case "curved" -> 28;
            default -> WAVY_K[points(name)];
        };
    }

    /** {@code WAVY_K[points]}: equal-accuracy K of the {@code points×points} wavy grid, see {@link #equalK}. */
    private static final int[] WAVY_K = {0, 0, 1, 10, 20, 20, 24, 24, 28, 28, 32, 32, 36, 36, 36, 36, 36};

    /** Points per side of a {@code wavyN} name. */
    static int points(String name) {
        int points = name.startsWith("wavy") ? Integer.parseInt(name.substring(4)) : 0;
        if (points < 2 || points > 16) {
            throw new IllegalArgumentException("scene must be teapot, patch, curved or wavy2..wavy16, got " + name);
        }
        return points;
    }

    /** The document of case {@code name}: a built-in, or a generated wavy grid of any size. */
    static SceneDocument document(String name) {
        if (name.startsWith("wavy")) {
            return new SceneDocument(GeneratedModels.wavy(points(name)), RenderSettings.defaults());
        }
        return SceneFiles.load(name);
    }

    /** The scene (lights placed) of case {@code name}. */
    public static Scene scene(String name) {
        Scene scene = document(name).scene();
        Vec3 light = switch (name) {
            case "teapot" -> new Vec3(-200, -350, 450);
            case "curved" -> new Vec3(-2, -4, 5);
            default -> null;
        };
        if (light != null) {
            scene = scene.toBuilder().lights(List.of(new PointLight(light))).build();
        }
        return scene;
    }

    /**
     * The full job: scene, 800×600 settings (1 spp, Phong, shadows, the document's method and BVH),
     * camera, {@code threads} workers, one-shot (not progressive), {@code tessellate} 0 = exact.
     */
    public static RenderJob job(String name, int threads, int tessellate) {
        if (!name.equals("teapot") && !name.equals("patch") && !name.equals("curved")) {
            points(name); // validates
        }
        RenderSettings s = document(name).settings();
        RenderSettings settings = new RenderSettings(WIDTH, HEIGHT, 1, s.sampler(), s.method(), s.bvh(), "phong",
                s.checker(), true, s.maxDepth());
        RenderOptions options = RenderOptions.defaults().withThreads(threads).withProgressive(false)
                .withTessellate(tessellate);
        RenderJob job = RenderJob.prepare(scene(name), settings, options);
        return switch (name) {
            case "teapot" -> job.withCamera(teapotCamera());
            case "curved" -> job.withCamera(curvedCamera());
            default -> job;
        };
    }

    /** {@code tessellate} parameter text: a number, or {@code K} for {@link #equalK} of the case. */
    public static int tessellate(String name, String tessellate) {
        return tessellate.equals("K") ? equalK(name) : Integer.parseInt(tessellate);
    }
}
