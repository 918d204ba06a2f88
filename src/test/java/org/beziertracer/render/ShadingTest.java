package org.beziertracer.render;

import static org.beziertracer.Tolerances.COLOUR;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.Material;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

class ShadingTest {

    private static RenderJob job(Scene scene, Camera camera, int w, int h, int depth) {
        RenderSettings s = new RenderSettings(w, h, 1, "regular", "clipping", true, "phong", 0, true, depth);
        return RenderJob.prepare(scene, s, RenderOptions.defaults().withThreads(1).withProgressive(false))
                .withCamera(camera);
    }

    @Test
    void lightAtTheEyeOnAPlaneFacingTheCameraGivesAmbientPlusDiffusePlusSpecular() {
        Material m = Material.diffuse(0.5, 0.25, 0.125); // ka 0.1, kd 0.75, ks 0.4
        Scene scene = Scene.builder().addMaterial(m).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1)).build();
        Camera camera = Camera.lookAt(new Vec3(0, 0, 10), Vec3.ZERO, Vec3.Y, 40);
        double[] rgb = new double[3];
        WhittedTracer.forJob(job(scene, camera, 9, 9, 5)).trace(0, 0, 10, 0, 0, -1, rgb);
        // n·l = 1 and r·v = 1 at the foot of the eye: (ka + kd)·C + ks
        assertEquals(0.85 * 0.5 + 0.4, rgb[0], COLOUR);
        assertEquals(0.85 * 0.25 + 0.4, rgb[1], COLOUR);
        assertEquals(0.85 * 0.125 + 0.4, rgb[2], COLOUR);
    }

    @Test
    void diffuseFollowsTheCosineAndTheBackFaceIsLitWithTheFlippedNormal() {
        Material m = new Material(1, 1, 1, 0, 1, 0, 1, 0, 0, 1.5, 0, 0, 0, 0); // pure diffuse
        // normal -z: the camera above sees the back face, lit through the flipped normal
        Scene scene = Scene.builder().addMaterial(m).addPlane(new Plane(Vec3.ZERO, new Vec3(0, 0, -1), 0, 1))
                .addLight(new PointLight(new Vec3(0, 3, 3))).build();
        Camera camera = Camera.lookAt(new Vec3(0, 0, 10), Vec3.ZERO, Vec3.Y, 40);
        double[] rgb = new double[3];
        WhittedTracer.forJob(job(scene, camera, 9, 9, 5)).trace(0, 0, 10, 0, 0, -1, rgb);
        assertEquals(Math.cos(Math.toRadians(45)), rgb[0], COLOUR);
    }

    @Test
    void aSurfaceBetweenPointAndLightCastsAShadow() {
        Material m = new Material(1, 1, 1, 0.1, 0.9, 0, 1, 0, 0, 1.5, 0, 0, 0, 0);
        Scene scene = Scene.builder().addMaterial(m).addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                .addSphere(new org.beziertracer.model.Sphere(new Vec3(0, 0, 2), 0.5, 0))
                .addLight(new PointLight(new Vec3(0, 0, 5))).build();
        Camera camera = Camera.lookAt(new Vec3(3, 0, 10), Vec3.ZERO, Vec3.Z.add(Vec3.Y), 40);
        double[] rgb = new double[3];
        WhittedTracer t = WhittedTracer.forJob(job(scene, camera, 9, 9, 5));
        t.trace(3, 0, 10, -3, 0.001, -10, rgb); // hits the plane near the origin, under the sphere
        assertEquals(0.1, rgb[0], COLOUR, "only ambient in the shadow");
        assertEquals(1, t.shadowRays());
    }

    @Test
    void adaptiveDepthControlStopsBetweenTwoFacingMirrors() {
        for (double kr : new double[] {0.5, 0.9}) {
            Material mirror = new Material(0.5, 0.5, 0.5, 0.1, 0.5, 0, 1, kr, 0, 1.5, 0, 0, 0, 0);
            Scene scene = Scene.builder().addMaterial(mirror)
                    .addPlane(new Plane(Vec3.ZERO, Vec3.Z, 0, 1))
                    .addPlane(new Plane(new Vec3(0, 0, 2), new Vec3(0, 0, -1), 0, 1))
                    .addLight(new PointLight(new Vec3(0, 0, 1))).build();
            Camera camera = Camera.lookAt(new Vec3(0, 0, 1), new Vec3(10, 0, 0.5), Vec3.Z, 40);
            WhittedTracer t = WhittedTracer.forJob(job(scene, camera, 1, 1, 20));
            t.trace(0, 0, 1, 1, 0, -0.3, new double[3]);
            // path weight kr^k must stay >= 1/256; the hard cap is depth 20
            int expected = Math.min(20, (int) Math.floor(Math.log(1 / 256.0) / Math.log(kr)));
            assertEquals(expected, t.secondaryRays(), "kr " + kr);
        }
    }

    @Test
    void totalInternalReflectionSendsNoRefractedRay() {
        // A ray inside glass (ior 1.5) meeting the surface at 60° from the normal: beyond the critical 41.8°
        Material glass = new Material(1, 1, 1, 0, 0, 0, 1, 0, 1, 1.5, 0, 0, 0, 0);
        Scene scene = Scene.builder().addMaterial(glass)
                .addPlane(new Plane(Vec3.ZERO, new Vec3(0, 0, -1), 0, 1)) // normal toward the ray: we are "outside"
                .build();
        // Inside means the ray travels along the normal: d·n > 0 with n = -z → d.z < 0
        Camera camera = Camera.lookAt(new Vec3(0, 0, 1), Vec3.ZERO, Vec3.Y, 40);
        WhittedTracer t = WhittedTracer.forJob(job(scene, camera, 1, 1, 1));
        t.trace(0, 0, 1, Math.sin(Math.toRadians(60)), 0, -Math.cos(Math.toRadians(60)), new double[3]);
        assertEquals(1, t.secondaryRays(), "only the reflected ray");
        WhittedTracer steep = WhittedTracer.forJob(job(scene, camera, 1, 1, 1));
        steep.trace(0, 0, 1, Math.sin(Math.toRadians(20)), 0, -Math.cos(Math.toRadians(20)), new double[3]);
        assertEquals(2, steep.secondaryRays(), "reflected and refracted");
    }

    @Test
    void normalsModeShowsTheNormalFlippedTowardTheViewer() {
        Scene scene = Scene.builder().addPlane(new Plane(Vec3.ZERO, new Vec3(0, 0, -1), 0, 1)).build();
        Camera camera = Camera.lookAt(new Vec3(0, 0, 10), Vec3.ZERO, Vec3.Y, 40);
        RenderSettings s = new RenderSettings(9, 9, 1, "regular", "clipping", true, "normals", 0, true, 5);
        double[] rgb = new double[3];
        WhittedTracer.forJob(RenderJob.prepare(scene, s, RenderOptions.defaults()).withCamera(camera))
                .trace(0, 0, 10, 0, 0, -1, rgb);
        assertEquals(0.5, rgb[0], COLOUR);
        assertEquals(0.5, rgb[1], COLOUR);
        assertEquals(1, rgb[2], COLOUR);
    }
}
