package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.Environment;
import org.beziertracer.model.HdrImage;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.Texture;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * The path tracer's hot path allocates nothing: after a warm-up, tracing thousands of paths
 * (every BSDF kind, image and checker textures, area lights, the environment) adds no more to the thread's allocated bytes than
 * the measuring itself costs — far less than one small object per path.
 */
class PathAllocationTest {

    @Test
    void tracingPathsAllocatesNothing() {
        Scene scene = Scene.builder().addMaterial(Material.DEFAULT).addMaterial(Material.DEFAULT)
                .addMaterial(Material.DEFAULT).addPatches(Models.sphere().patches(), 0)
                .surface(0, Surface.dielectric(1.5, 0.2)).surface(1, Surface.plastic(0.5, 0.5, 0.5, 0.3).withTexture(new Texture.Image("grain.png",
                        new HdrImage(2, 2, new float[] {0.1f, 0.2f, 0.3f, 0.9f, 0.8f, 0.7f, 0.5f, 0.5f, 0.5f, 0, 1, 0}), 3, 2)))
                .surface(2, Surface.conductor(new Surface.Vec(0.2, 0.9, 1.1), new Surface.Vec(3.9, 2.4, 2.1), 0.3)
                        .withTexture(new Texture.Checker(new Surface.Vec(1, 1, 1), new Surface.Vec(0.5, 0.4, 0.3), 4, 4)))
                .addPlane(new Plane(new Vec3(0, 0, -1), Vec3.Z, 1, 1))
                .addPlane(new Plane(new Vec3(0, 3, 0), new Vec3(0, -1, 0), 2, 1))
                .addAreaLight(AreaLight.sphere(new Vec3(2, -2, 3), 0.5, 8, 8, 8, Double.NaN))
                .addAreaLight(AreaLight.rect(new Vec3(-1, -1, 4), new Vec3(0, 2, 0), new Vec3(2, 0, 0), 4, 4, 4, Double.NaN))
                .environment(Environment.color(0.3, 0.3, 0.3)).build();
        RenderSettings s = new RenderSettings(16, 16, 1, "jittered", "clipping", true, "phong", 0, true, 5);
        RenderOptions o = RenderOptions.defaults().withThreads(1)
                .withPath(PathOptions.defaults().withIntegrator(Integrator.PATH).withMaxDepth(12));
        RenderJob job = RenderJob.prepare(scene, s, o).withCamera(Camera.lookAt(new Vec3(0, -4, 1), Vec3.ZERO, Vec3.Z, 50));
        ShadingScene shading = new ShadingScene(job);
        PathTracer tracer = new PathTracer(job.intersector());
        tracer.bind(shading, new PathScene(job, shading));
        int n = 16;
        double[] rays = new double[6 * n], rgb = new double[3 * n];
        int[] pixels = new int[2 * n], samples = new int[n];
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long id = Thread.currentThread().getId();
        long before = 0;
        int rounds = 1600, warm = 600; // the warm-up lets the JIT settle (its own allocations end within ~300 rounds)
        for (int round = 0; round < rounds; round++) {
            if (round == warm) {
                before = bean.getThreadAllocatedBytes(id);
            }
            for (int i = 0; i < n; i++) {
                int x = i % 4 + 4 * (round % 4), y = i / 4 + 4 * (round / 4 % 4);
                pixels[2 * i] = x;
                pixels[2 * i + 1] = y;
                samples[i] = round;
                job.camera().generateRay(x + 0.5, y + 0.5, 16, 16, rays, 6 * i);
            }
            tracer.tracePacket(null, rays, pixels, samples, n, 1, rgb);
        }
        long allocated = bean.getThreadAllocatedBytes(id) - before;
        long paths = (long) (rounds - warm) * n;
        assertTrue(allocated < 4096, allocated + " bytes allocated for " + paths + " paths");
    }
}
