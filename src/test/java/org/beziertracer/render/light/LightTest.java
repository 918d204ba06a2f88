package org.beziertracer.render.light;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The lights against closed forms of the irradiance they give a small patch of plane (estimated
 * from their own samples, {@code E = mean(L cosθ / pdf)}), and each light's pdf and hit agreeing
 * with its samples.
 */
class LightTest {
    /** The 1 % of the target. */
    private static final double PERCENT = 0.01;

    /** Irradiance at the origin on the plane of normal {@code n}, from {@code n} samples of the light. */
    private static double irradiance(Light light, double[] normal, int count, long seed) {
        Random rnd = new Random(seed);
        LightSample s = new LightSample();
        double sum = 0;
        for (int i = 0; i < count; i++) {
            if (light.sample(0, 0, 0, rnd.nextDouble(), rnd.nextDouble(), s)) {
                double cos = s.wx * normal[0] + s.wy * normal[1] + s.wz * normal[2];
                sum += cos > 0 ? s.r * cos / s.pdf : 0;
            }
        }
        return sum / count;
    }

    @Test
    void aSmallSphereLightGivesTheAnalyticIrradianceOnAPlaneBelow() {
        // E = π L sin²α cosβ, sin α = r / d, β the angle of the centre from the normal
        double r = 0.1, d = 2, radiance = 3;
        SphereLight above = new SphereLight(0, 0, d, r, radiance, radiance, radiance);
        double expected = Math.PI * radiance * (r / d) * (r / d);
        assertEquals(expected, irradiance(above, new double[] {0, 0, 1}, 20_000, 1), PERCENT * expected);
        double beta = Math.toRadians(50);
        SphereLight aside = new SphereLight(d * Math.sin(beta), 0, d * Math.cos(beta), r, radiance, radiance, radiance);
        double tilted = expected * Math.cos(beta);
        assertEquals(tilted, irradiance(aside, new double[] {0, 0, 1}, 20_000, 2), PERCENT * tilted);
    }

    @Test
    void aRectLightGivesTheFormFactorOfARectangle() {
        // A parallel a × b rectangle at height h with a corner above the point: E = π L F,
        // F = (1/2π)[A/√(1+A²) atan(B/√(1+A²)) + B/√(1+B²) atan(A/√(1+B²))], A = a/h, B = b/h
        double a = 1, b = 2, h = 1.5, radiance = 2;
        RectLight rect = new RectLight(new double[] {0, 0, h}, new double[] {0, b, 0}, new double[] {a, 0, 0},
                radiance, radiance, radiance);
        double ra = a / h, rb = b / h;
        double f = (ra / Math.sqrt(1 + ra * ra) * Math.atan(rb / Math.sqrt(1 + ra * ra))
                + rb / Math.sqrt(1 + rb * rb) * Math.atan(ra / Math.sqrt(1 + rb * rb))) / (2 * Math.PI);
        double expected = Math.PI * radiance * f;
        assertEquals(expected, irradiance(rect, new double[] {0, 0, 1}, 200_000, 3), PERCENT * expected);
    }

    @Test
    void aRectLightIsDarkFromBehind() {
        RectLight rect = new RectLight(new double[] {0, 0, 1}, new double[] {1, 0, 0}, new double[] {0, 1, 0}, 1, 1, 1);
        // edge1 × edge2 = +z: it emits upward, away from the origin below it
        assertEquals(0, irradiance(rect, new double[] {0, 0, 1}, 1000, 4));
        assertEquals(Double.POSITIVE_INFINITY, rect.hit(0.5, 0.5, 0, 0, 0, 1, new double[3]));
        assertEquals(1, rect.hit(0.5, 0.5, 2, 0, 0, -1, new double[3]), ROUNDING);
    }

    @Test
    void aConstantEnvironmentGivesPiTimesItsRadiance() {
        ConstantEnvironment env = new ConstantEnvironment(0.7, 0.7, 0.7);
        assertEquals(Math.PI * 0.7, irradiance(env, new double[] {0, 0.6, 0.8}, 400_000, 5), PERCENT * Math.PI * 0.7);
    }

    @Test
    void aPointSourceFallsOffWithTheSquareOfDistanceAndASpotWithItsCone() {
        PointSource p = new PointSource(0, 0, 3, 9, 9, 9);
        assertEquals(1, irradiance(p, new double[] {0, 0, 1}, 1, 6), ROUNDING);
        SpotSource inside = new SpotSource(0, 0, 3, new double[] {0, 0, -1}, 30, 20, 9, 9, 9);
        assertEquals(1, irradiance(inside, new double[] {0, 0, 1}, 1, 7), ROUNDING);
        SpotSource away = new SpotSource(0, 0, 3, new double[] {1, 0, -1}, 30, 20, 9, 9, 9);
        assertEquals(0, irradiance(away, new double[] {0, 0, 1}, 1, 8));
        double halfway = (Math.cos(Math.toRadians(60)) + Math.cos(Math.toRadians(30))) / 2;
        assertEquals(0.5, new SpotSource(0, 0, 0, new double[] {0, 0, 1}, 60, 30, 1, 1, 1)
                .falloff(Math.sqrt(1 - halfway * halfway), 0, halfway), ROUNDING, "smoothstep half way in cosine");
        assertThrows(IllegalArgumentException.class, () -> new SpotSource(0, 0, 0, new double[] {0, 0, 1}, 20, 30, 1, 1, 1));
    }

    @Test
    void eachAreaLightsPdfAndHitAgreeWithItsSamples() {
        Light[] lights = {new SphereLight(1, 2, 3, 0.5, 1, 1, 1),
            new RectLight(new double[] {-1, 2, 1}, new double[] {2, 0, 0.5}, new double[] {0, 0.5, 1.5}, 1, 1, 1),
            new ConstantEnvironment(1, 1, 1)};
        Random rnd = new Random(9);
        LightSample s = new LightSample();
        double[] le = new double[3];
        for (Light l : lights) {
            for (int i = 0; i < 2000; i++) {
                if (!l.sample(0, 0, 0, rnd.nextDouble(), rnd.nextDouble(), s)) {
                    continue;
                }
                String where = l.getClass().getSimpleName() + " sample " + i;
                assertEquals(s.pdf, l.pdf(0, 0, 0, s.wx, s.wy, s.wz), 1e-9 * s.pdf, where);
                double t = l.hit(0, 0, 0, s.wx, s.wy, s.wz, le);
                if (!l.isEnvironment()) {
                    assertEquals(s.distance, t, 1e-9 * t, where);
                }
                assertEquals(1, le[0], where);
            }
            assertFalse(l.isDelta());
        }
        assertTrue(new PointSource(0, 0, 0, 1, 1, 1).isDelta());
    }
}
