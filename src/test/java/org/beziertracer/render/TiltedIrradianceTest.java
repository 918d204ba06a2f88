package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Material;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Surface;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * Direct light on <b>curved</b> diffuse surfaces whose normals tilt away from a rect light, against
 * the closed form: a point of normal {@code n} sees a uniform polygon of radiance {@code L} with
 * irradiance {@code E = L/2 · Σ Θ_i (u_i · n)} (Lambert, "Photometria", 1760; in vector form e.g.
 * J. Arvo, "Applications of irradiance tensors to the simulation of non-Lambertian phenomena",
 * SIGGRAPH 1995, eq. 9: {@code Θ_i} the angle an edge subtends, {@code u_i} the unit normal of the
 * plane through the point and the edge), valid while the whole polygon is above the tangent plane.
 * A diffuse surface of albedo {@code ρ} then has radiance {@code ρ/π · E}. The other light tests
 * look at planes facing the light; here the NURBS sphere (rational) and a parabolic cylinder (a
 * polynomial Bézier patch) are seen at normals 0–75° from the light's axis, where the comparison
 * with Sunflow (docs/rendering.md) found Sunflow 6–13 % brighter. Convex shapes under a black sky:
 * direct light is all there is, at any depth.
 */
class TiltedIrradianceTest {
    private static final double PERCENT = 0.01;
    private static final double ALBEDO = 0.8, L = 50;
    /** A 1 × 1 rect light 6 above the origin, facing down (edge1 × edge2 = −z). */
    private static final Vec3 CORNER = new Vec3(-0.5, -0.5, 6), EDGE1 = new Vec3(0, 1, 0), EDGE2 = new Vec3(1, 0, 0);

    /** Lambert's irradiance at {@code p} (normal {@code n}) from the polygon {@code corners}, of radiance {@code radiance}. */
    static double polygonIrradiance(Vec3 p, Vec3 n, Vec3[] corners, double radiance) {
        double sum = 0;
        for (int i = 0; i < corners.length; i++) {
            Vec3 a = corners[i].sub(p).normalize(), b = corners[(i + 1) % corners.length].sub(p).normalize();
            double theta = Math.acos(Math.max(-1, Math.min(1, a.dot(b))));
            sum += theta * a.cross(b).normalize().dot(n);
        }
        return radiance / 2 * Math.abs(sum);
    }

    private static Vec3[] corners() {
        return new Vec3[] {CORNER, CORNER.add(EDGE1), CORNER.add(EDGE1).add(EDGE2), CORNER.add(EDGE2)};
    }

    private static Scene lit(Scene.Builder b) {
        return b.surface(0, Surface.diffuse(ALBEDO, ALBEDO, ALBEDO))
                .addAreaLight(AreaLight.rect(CORNER, EDGE1, EDGE2, L, L, L, Double.NaN)).build();
    }

    /**
     * The mean radiance the path tracer sees at {@code p}: an 8 × 8 picture of a 0.2° view of it from
     * {@code 0.5} along {@code view} (so every pixel is within 0.001 of {@code p}), 1,024 samples a pixel.
     */
    private static double radianceAt(Scene scene, Vec3 p, Vec3 view) {
        Camera camera = Camera.lookAt(p.add(view.normalize().scale(0.5)), p, Math.abs(view.normalize().z()) > 0.9 ? Vec3.Y
                : Vec3.Z, 0.2);
        RenderSettings s = new RenderSettings(8, 8, 1024, "jittered", "clipping", true, "phong", 0, true, 5);
        RenderOptions o = RenderOptions.defaults().withThreads(2).withProgressive(false)
                .withPath(PathOptions.defaults().withIntegrator(Integrator.PATH).withMaxDepth(3));
        float[] rgb = Renderer.renderOnce(RenderJob.prepare(scene, s, o).withCamera(camera)).film().linearRgb();
        double sum = 0;
        for (int i = 1; i < rgb.length; i += 3) {
            sum += rgb[i];
        }
        return sum / (rgb.length / 3);
    }

    private static void assertLambert(Scene scene, Vec3 p, Vec3 n, Vec3 view, String where) {
        for (Vec3 c : corners()) {
            assertTrue(c.sub(p).dot(n) > 0, "the light is above the tangent plane at " + where);
        }
        double expected = ALBEDO / Math.PI * polygonIrradiance(p, n, corners(), L);
        double got = radianceAt(scene, p, view);
        assertEquals(expected, got, PERCENT * expected, where + ": radiance " + got + " for Lambert's " + expected
                + " (ratio " + got / expected + ")");
    }

    @Test
    void lambertsFormulaGivesTheFormFactorOfASquareStraightBelowIt() {
        // Howell's C-11 (as PathTracerTest): four quarters a × a at height h, F = 2x/r·atan(x/r)/(2π), x = a/h
        double a = 0.5, h = 6, x = a / h, r = Math.sqrt(1 + x * x);
        double expected = L * Math.PI * 4 * (2 * x / r * Math.atan(x / r)) / (2 * Math.PI);
        assertEquals(expected, polygonIrradiance(Vec3.ZERO, Vec3.Z, corners(), L), 1e-12 * expected);
    }

    @Test
    void theNurbsSphereTiltedAwayFromTheLightHasLambertsRadiance() {
        Scene scene = lit(Scene.builder().addMaterial(Material.DEFAULT).addPatches(Models.sphere().patches(), 0));
        for (double degrees : new double[] {0, 40, 60, 75}) {
            double t = Math.toRadians(degrees);
            Vec3 n = new Vec3(Math.sin(t), 0, Math.cos(t));
            // the unit sphere: the point is its normal; seen from above the tilt, off to the side
            assertLambert(scene, n, n, n.add(new Vec3(0, -0.6, 0.3)), "sphere, normal " + degrees + "° from the light");
            Vec3 m = new Vec3(0, -Math.sin(t), Math.cos(t));
            assertLambert(scene, m, m, m.add(new Vec3(0.5, 0, 0.2)), "sphere, normal " + degrees + "° toward −y");
        }
    }

    @Test
    void aPolynomialBezierCylinderTiltedAwayFromTheLightHasLambertsRadiance() {
        // z = 1 − x² over [−1, 1]²: the quadratic Bézier (−1, 0), (0, 2), (1, 0) in x, z; linear in y
        double[] net = new double[3 * 6];
        double[][] xz = {{-1, 0}, {0, 2}, {1, 0}};
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < 3; i++) {
                int k = 3 * (j * 3 + i);
                net[k] = xz[i][0];
                net[k + 1] = j == 0 ? -1 : 1;
                net[k + 2] = xz[i][1];
            }
        }
        Scene scene = lit(Scene.builder().addMaterial(Material.DEFAULT).addPatches(java.util.List.of(new BezierPatch(2, 1, net)), 0));
        for (double x : new double[] {0, 0.5, 0.866, -0.95}) {
            Vec3 p = new Vec3(x, 0.1, 1 - x * x);
            Vec3 n = new Vec3(2 * x, 0, 1).normalize();
            assertLambert(scene, p, n, n.add(new Vec3(0, -0.5, 0.2)), "cylinder at x = " + x + ", normal "
                    + Math.round(Math.toDegrees(Math.atan(2 * Math.abs(x)))) + "° from the light");
        }
    }
}
