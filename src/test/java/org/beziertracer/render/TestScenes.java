package org.beziertracer.render;

import java.util.List;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.beziertracer.model.io.Models;

/** Small scenes built in code (z up) for the renderer tests and golden images. */
final class TestScenes {
    private TestScenes() {}

    static final Vec3 EYE = new Vec3(0.5, -9, 5.5);
    static final Vec3 TARGET = new Vec3(0, 0, 0.6);

    /** A bicubic bump over [-1.5,1.5]², inner control points raised to z = 1.6, lifted by {@code z0}. */
    static BezierPatch bump(double z0) {
        double[] net = Models.flatGrid(4, 4).copyNet();
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                int k = 3 * (j * 4 + i);
                net[k + 2] = z0 + ((i == 1 || i == 2) && (j == 1 || j == 2) ? 1.6 : 0);
            }
        }
        return new BezierPatch(3, 3, net);
    }

    static Camera camera() {
        return Camera.lookAt(EYE, TARGET, Vec3.Z, 50);
    }

    static RenderSettings settings(int w, int h, String shading) {
        return new RenderSettings(w, h, 1, "regular", "clipping", true, shading, 0, true, 5);
    }

    /** The job for {@code scene}: its own camera if it has one, else {@link #camera()}. */
    static RenderJob job(Scene scene, RenderSettings s) {
        RenderJob job = RenderJob.prepare(scene, s, RenderOptions.defaults().withThreads(2).withProgressive(false));
        return scene.camera().isPresent() ? job : job.withCamera(camera());
    }

    /** The bump alone, default material, light at the eye. */
    static Scene bumpOnly() {
        return new Scene(List.of(bump(0.2)));
    }

    /** Bump patch and a red sphere above a grey ground plane, one light: shadows on the ground. */
    static Scene shadows() {
        return Scene.builder()
                .addMaterial(Material.DEFAULT)
                .addMaterial(Material.diffuse(0.7, 0.7, 0.7))
                .addMaterial(Material.diffuse(0.8, 0.15, 0.1))
                .addPatches(List.of(bump(0.2)), 0)
                .addPlane(new Plane(new Vec3(0, 0, 0), Vec3.Z, 1, 1))
                .addSphere(new Sphere(new Vec3(2.4, 0.6, 1.6), 0.7, 2))
                .addLight(new PointLight(new Vec3(-4, -5, 9)))
                .build();
    }

    /** A mirror sphere beside the bump on a checkered plane. */
    static Scene reflection() {
        return Scene.builder()
                .addMaterial(Material.DEFAULT)
                .addMaterial(Material.diffuse(0.1, 0.1, 0.12).withChecker(1))
                .addMaterial(new Material(0.9, 0.9, 0.9, 0.0, 0.05, 0.8, 200, 0.9, 0, 1.5, 0, 0, 0, 0))
                .addPatches(List.of(bump(0.2)), 0)
                .addPlane(new Plane(new Vec3(0, 0, 0), Vec3.Z, 1, 1))
                .addSphere(new Sphere(new Vec3(2.3, 1.2, 1.2), 1.2, 2))
                .addLight(new PointLight(new Vec3(-4, -5, 9)))
                .build();
    }

    /**
     * The Utah teapot (32 patches sharing borders) on a grey floor, lit from the upper left, at
     * the view of issue 4: borders, the collapsed lid top and the knob in one picture.
     */
    static Scene teapot() {
        return Scene.builder()
                .addMaterial(new Material(0.75, 0.12, 0.1, 0.1, 0.75, 0.6, 60, 0, 0, 1.5, 0, 0, 0, 0))
                .addMaterial(Material.diffuse(0.7, 0.7, 0.7))
                .addPatches(Models.teapot().patches(), 0)
                .addPlane(new Plane(new Vec3(0, 0, 0), Vec3.Z, 1, 40))
                .addLight(new PointLight(new Vec3(-200, -350, 450)))
                .camera(CameraSpec.perspective(new Vec3(-150, -420, 260), new Vec3(10, 0, 55), Vec3.Z, 40))
                .build();
    }

    /** A glass sphere in front of the bump on a checkered plane. */
    static Scene refraction() {
        return Scene.builder()
                .addMaterial(Material.DEFAULT)
                .addMaterial(Material.diffuse(0.1, 0.1, 0.12).withChecker(1))
                .addMaterial(new Material(0.9, 0.95, 1.0, 0.0, 0.0, 0.8, 200, 0.0, 0.9, 1.5, 0, 0, 0, 0))
                .addPatches(List.of(bump(0.2)), 0)
                .addPlane(new Plane(new Vec3(0, 0, 0), Vec3.Z, 1, 1))
                .addSphere(new Sphere(new Vec3(0.3, -2.6, 1.1), 1.1, 2))
                .addLight(new PointLight(new Vec3(-4, -5, 9)))
                .build();
    }
}
