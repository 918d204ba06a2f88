package org.beziertracer.render.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.model.HdrImage;
import org.junit.jupiter.api.Test;

/**
 * {@link ImageEnvironment}: a constant image lights like a constant environment, the sampled pdf
 * is the evaluated one and integrates to 1, bright pixels draw the samples, rotation turns the sky.
 */
class ImageEnvironmentTest {

    private static HdrImage image(int w, int h, Random rnd, boolean constant) {
        float[] rgb = new float[3 * w * h];
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = constant ? 0.7f : (float) (rnd.nextDouble() * rnd.nextDouble() * 5);
        }
        return new HdrImage(w, h, rgb);
    }

    @Test
    void aConstantImageGivesPiTimesItsRadiance() {
        ImageEnvironment env = new ImageEnvironment(image(16, 8, null, true), 2, 0);
        Random rnd = new Random(1);
        LightSample s = new LightSample();
        double sum = 0;
        int n = 200_000;
        for (int i = 0; i < n; i++) {
            if (env.sample(0, 0, 0, rnd.nextDouble(), rnd.nextDouble(), s) && s.wz > 0) {
                sum += s.r * s.wz / s.pdf;
            }
        }
        double expected = Math.PI * 0.7 * 2;
        assertEquals(expected, sum / n, 0.01 * expected);
    }

    @Test
    void theSampledPdfIsTheEvaluatedOneAndIntegratesToOne() {
        Random rnd = new Random(2);
        ImageEnvironment env = new ImageEnvironment(image(12, 6, rnd, false), 1, 33);
        LightSample s = new LightSample();
        double[] le = new double[3];
        for (int i = 0; i < 5000; i++) {
            if (!env.sample(0, 0, 0, rnd.nextDouble(), rnd.nextDouble(), s)) {
                continue;
            }
            assertEquals(s.pdf, env.pdf(0, 0, 0, s.wx, s.wy, s.wz), 1e-9 * s.pdf, "sample " + i);
            env.hit(0, 0, 0, s.wx, s.wy, s.wz, le);
            assertEquals(s.r, le[0], "radiance of sample " + i);
        }
        int n = 600;
        double integral = 0;
        for (int a = 0; a < n; a++) {
            double z = 1 - 2 * (a + 0.5) / n, r = Math.sqrt(1 - z * z);
            for (int b = 0; b < 2 * n; b++) {
                double phi = 2 * Math.PI * (b + 0.5) / (2 * n);
                integral += env.pdf(0, 0, 0, r * Math.cos(phi), r * Math.sin(phi), z);
            }
        }
        integral *= 4 * Math.PI / (2.0 * n * n);
        assertEquals(1, integral, 0.01, "∫ pdf dω");
    }

    @Test
    void samplesGoWhereTheLightIsAndFollowTheRotation() {
        float[] rgb = new float[3 * 8 * 4];
        int bright = 3 * (1 * 8 + 6); // row 1 (above the horizon), column 6: azimuth −π + 2π·6.5/8
        rgb[bright] = rgb[bright + 1] = rgb[bright + 2] = 100;
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] += 0.01f;
        }
        HdrImage img = new HdrImage(8, 4, rgb);
        for (double rotate : new double[] {0, 90}) {
            ImageEnvironment env = new ImageEnvironment(img, 1, rotate);
            Random rnd = new Random(3);
            LightSample s = new LightSample();
            int inside = 0, n = 10_000;
            double centre = -Math.PI + 2 * Math.PI * 6.5 / 8 + Math.toRadians(rotate);
            for (int i = 0; i < n; i++) {
                env.sample(0, 0, 0, rnd.nextDouble(), rnd.nextDouble(), s);
                double phi = Math.atan2(s.wy, s.wx);
                double d = Math.abs(Math.IEEEremainder(phi - centre, 2 * Math.PI));
                if (d < Math.PI / 8 && s.wz > 0) {
                    inside++;
                }
            }
            assertTrue(inside > 0.95 * n, "rotate " + rotate + ": " + inside + " of " + n + " samples in the bright pixel");
        }
    }
}
