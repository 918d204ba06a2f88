package org.beziertracer.render;

import java.util.List;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.Material;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;

/**
 * A job's shading data in flat arrays, built once per render and shared read-only by the workers.
 *
 * <p>Layouts: {@code materials[MAT_STRIDE * k + …] = r, g, b, ka, kd, ks, shininess, kr, kt, ior,
 * checkerSquares, r2, g2, b2} (a textured material's colour is its {@link #textures} entry's at the
 * hit); {@code lights[6 * k + …] = x, y, z, r, g, b}. Primitive materials:
 * {@code patchMaterial[k]}, {@code planeMaterial[k]}, {@code sphereMaterial[k]}, {@code meshMaterial[k]}.
 *
 * <p>The job's own lights, when it has them, replace the scene's. With no lights in the scene there
 * is one white light at the camera's eye (the memoir's light at the centre of projection), so it
 * follows the camera as it orbits.
 */
final class ShadingScene {
    static final int MAT_STRIDE = 14;
    static final int R = 0, G = 1, B = 2, KA = 3, KD = 4, KS = 5, SHININESS = 6, KR = 7, KT = 8, IOR = 9,
            CHECKER = 10, R2 = 11, G2 = 12, B2 = 13;
    /** Background colour (linear RGB) for rays that miss everything. */
    static final double BG_R = 0.02, BG_G = 0.022, BG_B = 0.03;
    /** Second checker colour when the material has none. */
    static final double CHECKER_LIGHT = 0.95;

    final SceneIntersector intersector;
    final double[] materials;
    /** Per material, its texture when its colour varies over (u,v) ({@code Surface.texture}), else null. */
    final SurfaceTexture[] textures;
    final int[] patchMaterial, planeMaterial, sphereMaterial, meshMaterial;
    final double[] lights;
    final int lightCount;
    final ShadingMode mode;
    /** Checker squares forced on patches (settings); 0 = each material's own. */
    final int patchChecker;
    final boolean shadows;
    final int maxDepth;
    final double minAttenuation;
    /** Offset of secondary-ray origins along the normal, in scene units. */
    final double eps;
    /** The analysis views' settings, and the ends of a curvature view's scale ({@link AnalysisRange}). */
    final Analysis analysis;
    final double rangeLow, rangeHigh;

    ShadingScene(RenderJob job) {
        intersector = job.intersector();
        Scene scene = job.scene();
        List<Material> mats = scene.materials();
        materials = new double[MAT_STRIDE * mats.size()];
        for (int k = 0; k < mats.size(); k++) {
            Material m = mats.get(k);
            boolean noSecond = m.r2() == 0 && m.g2() == 0 && m.b2() == 0;
            double[] row = {m.r(), m.g(), m.b(), m.ambient(), m.diffuse(), m.specular(), m.shininess(),
                    m.reflectivity(), m.transparency(), m.ior(), m.checkerSquares(),
                    noSecond ? CHECKER_LIGHT : m.r2(), noSecond ? CHECKER_LIGHT : m.g2(),
                    noSecond ? CHECKER_LIGHT : m.b2()};
            System.arraycopy(row, 0, materials, MAT_STRIDE * k, MAT_STRIDE);
        }
        textures = new SurfaceTexture[mats.size()];
        for (int k = 0; k < mats.size(); k++) {
            Surface surface = scene.surface(k);
            textures[k] = surface != null && surface.texture() != null ? new SurfaceTexture(surface.texture()) : null;
        }
        patchMaterial = new int[scene.patchCount()];
        for (int k = 0; k < patchMaterial.length; k++) {
            patchMaterial[k] = scene.patchMaterial(k);
        }
        planeMaterial = scene.planes().stream().mapToInt(p -> p.material()).toArray();
        sphereMaterial = scene.spheres().stream().mapToInt(s -> s.material()).toArray();
        meshMaterial = new int[scene.meshes().size()];
        for (int k = 0; k < meshMaterial.length; k++) {
            meshMaterial[k] = scene.meshMaterial(k);
        }
        List<PointLight> ls = job.lights() != null ? job.lights()
                : scene.lights().isEmpty() ? List.of(new PointLight(job.camera().eye())) : scene.lights();
        lightCount = ls.size();
        lights = new double[6 * lightCount];
        for (int k = 0; k < lightCount; k++) {
            PointLight l = ls.get(k);
            double[] row = {l.position().x(), l.position().y(), l.position().z(), l.r(), l.g(), l.b()};
            System.arraycopy(row, 0, lights, 6 * k, 6);
        }
        mode = job.shading();
        patchChecker = job.settings().checker();
        shadows = job.settings().shadows();
        maxDepth = job.settings().maxDepth();
        minAttenuation = job.options().minAttenuation();
        double size = RenderJob.bounds(scene).diagonal();
        eps = 1e-6 * (size > 0 ? size : 1);
        analysis = job.options().analysis();
        double[] range = AnalysisRange.of(job);
        rangeLow = range[0];
        rangeHigh = range[1];
    }

    /** Offset into {@link #materials} of the material of the primitive {@code (kind, index)}. */
    int materialOffset(int kind, int index) {
        int m = kind == Hit.PATCH ? patchMaterial[index] : kind == Hit.PLANE ? planeMaterial[index]
                : kind == Hit.SPHERE ? sphereMaterial[index] : meshMaterial[index];
        return MAT_STRIDE * m;
    }
}
