package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.accel.RayPacket;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * {@link WhittedTracer#tracePacket} gives every camera ray of a packet the colour {@link
 * WhittedTracer#trace} gives it alone, to the bit: first hits from the packet's leaves, shadow
 * rays traced as packets, shading afterwards; on scenes with shadows, mirrors, glass, planes,
 * spheres, shared patch borders, two lights and the tessellated mode.
 */
class PacketTracingTest {

    private static final int W = 96, H = 72;

    private static void samePictureEitherWay(String name, RenderJob job) {
        WhittedTracer alone = WhittedTracer.forJob(job), together = WhittedTracer.forJob(job);
        Camera camera = job.camera();
        int side = RenderWorker.PACKET;
        double[] rays = new double[6 * side * side], packetRgb = new double[3 * side * side], rgb = new double[3];
        RayPacket packet = new RayPacket();
        int gathered = 0, packets = 0, lit = 0;
        for (int y0 = 0; y0 < H; y0 += side) {
            for (int x0 = 0; x0 < W; x0 += side) {
                int n = 0;
                for (int y = y0; y < y0 + side; y++) {
                    for (int x = x0; x < x0 + side; x++) {
                        camera.generateRay(x + 0.5, y + 0.5, W, H, rays, 6 * n++);
                    }
                }
                boolean ok = together.gather(packet.of(rays, n));
                gathered += ok ? 1 : 0;
                packets++;
                together.tracePacket(ok ? packet : null, rays, n, packetRgb);
                for (int i = 0; i < n; i++) {
                    int o = 6 * i;
                    alone.trace(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5], rgb);
                    for (int c = 0; c < 3; c++) {
                        assertEquals(rgb[c], packetRgb[3 * i + c], 0, name + ": ray " + i + " of the packet at ("
                                + x0 + ", " + y0 + "), channel " + c);
                    }
                    lit += rgb[0] + rgb[1] + rgb[2] > 0.3 ? 1 : 0;
                }
            }
        }
        assertTrue(gathered > packets / 2, name + ": " + gathered + " of " + packets + " packets gathered");
        assertTrue(lit > W * H / 20, name + ": only " + lit + " bright pixels, the scene is not in view");
        assertEquals(alone.primaryRays(), together.primaryRays(), name + ": camera rays");
        assertEquals(alone.shadowRays(), together.shadowRays(), name + ": shadow rays");
        assertEquals(alone.secondaryRays(), together.secondaryRays(), name + ": secondary rays");
    }

    private static RenderSettings settings() {
        return TestScenes.settings(W, H, "phong");
    }

    @Test
    void shadowsMirrorsAndGlass() {
        samePictureEitherWay("shadows", TestScenes.job(TestScenes.shadows(), settings()));
        samePictureEitherWay("reflection", TestScenes.job(TestScenes.reflection(), settings()));
        samePictureEitherWay("refraction", TestScenes.job(TestScenes.refraction(), settings()));
    }

    @Test
    void theTeapotWithTwoLightsExactAndTessellated() {
        RenderJob job = TestScenes.job(TestScenes.teapot(), settings());
        samePictureEitherWay("teapot", job);
        List<PointLight> two = List.of(new PointLight(new Vec3(-200, -350, 450)),
                new PointLight(new Vec3(300, -100, 200), 0.5, 0.5, 0.6));
        samePictureEitherWay("teapot, two lights", job.withLights(two));
        Scene teapot = TestScenes.teapot();
        RenderJob tessellated = RenderJob.prepare(teapot, settings(),
                RenderOptions.defaults().withThreads(1).withProgressive(false).withTessellate(8));
        samePictureEitherWay("teapot, tessellated", tessellated.withLights(two));
    }

    @Test
    void aLoggedPacketTellsEachRaysStoryAsAlone() {
        // The shading events (the --pixel trace) come per ray, in the same order and with the
        // same shadow answers, whether the rays go as a packet or one by one
        RenderJob job = TestScenes.job(TestScenes.shadows(), settings());
        List<String> alone = new java.util.ArrayList<>(), together = new java.util.ArrayList<>();
        WhittedTracer one = WhittedTracer.forJob(job), packed = WhittedTracer.forJob(job);
        one.setLog(alone::add);
        packed.setLog(together::add);
        int n = RenderWorker.PACKET * RenderWorker.PACKET;
        double[] rays = new double[6 * n], rgb = new double[3 * n];
        for (int i = 0; i < n; i++) {
            job.camera().generateRay(40 + i % 4 * 0.5, 50 + i / 4 * 0.5, W, H, rays, 6 * i);
            one.trace(rays[6 * i], rays[6 * i + 1], rays[6 * i + 2], rays[6 * i + 3], rays[6 * i + 4], rays[6 * i + 5],
                    new double[3]);
        }
        RayPacket packet = new RayPacket();
        assertTrue(packed.gather(packet.of(rays, n)));
        packed.tracePacket(packet, rays, n, rgb);
        assertTrue(alone.stream().anyMatch(line -> line.contains("shadow")), "the rays cast shadow rays: " + alone);
        assertEquals(alone, together);
    }

    @Test
    void aShadowCastNearTheLight() {
        // The bump hangs just below the light: the ground's shadow rays meet it past half-way
        Scene near = Scene.builder()
                .addMaterial(Material.DEFAULT)
                .addMaterial(Material.diffuse(0.7, 0.7, 0.7))
                .addPatches(List.of(TestScenes.bump(3)), 0)
                .addPlane(new Plane(new Vec3(0, 0, 0), Vec3.Z, 1, 1))
                .addLight(new PointLight(new Vec3(0.2, -0.3, 5.6)))
                .build();
        samePictureEitherWay("a shadow cast near the light", TestScenes.job(near, settings()));
    }

    @Test
    void aLightAtTheEyeAndNoShadows() {
        samePictureEitherWay("bump, light at the eye", TestScenes.job(TestScenes.bumpOnly(), settings()));
        RenderSettings noShadows = new RenderSettings(W, H, 1, "regular", "clipping", true, "phong", 0, false, 5);
        samePictureEitherWay("shadows off", TestScenes.job(TestScenes.shadows(), noShadows));
        samePictureEitherWay("normals", TestScenes.job(TestScenes.shadows(), TestScenes.settings(W, H, "normals")));
    }
}
