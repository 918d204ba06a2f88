package org.beziertracer.render.bsdf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.MetalPresets;

import org.junit.jupiter.api.Test;

/**
 * Each BSDF's sampling against its own evaluation: the chi-square test of sampled directions
 * against the evaluated pdf, {@code eval} and {@code sample} agreeing on f and pdf, reciprocity,
 * and energy: no BSDF reflects (or, for glass, scatters) more than it receives.
 */
class BsdfSamplingTest {
    private static final double[] WHITE = {1, 1, 1};
    /** Significance of one chi-square test; Šidák-corrected over the cases. */
    private static final double ALPHA = 0.01;
    private static final int SAMPLES = 200_000;

    private static List<Object[]> cases() {
        List<Object[]> out = new ArrayList<>();
        out.add(new Object[] {"diffuse", Diffuse.INSTANCE});
        out.add(new Object[] {"rough gold 0.5", new Conductor(MetalPresets.GOLD.eta(), MetalPresets.GOLD.k(), 0.5)});
        out.add(new Object[] {"rough silver 0.8", new Conductor(MetalPresets.SILVER.eta(), MetalPresets.SILVER.k(), 0.8)});
        out.add(new Object[] {"rough glass 0.5", new Dielectric(1.5, 0.5)});
        out.add(new Object[] {"rough glass 0.8", new Dielectric(1.33, 0.8)});
        out.add(new Object[] {"plastic 0.5", new Plastic(1.5, 0.5)});
        return out;
    }

    /** Directions of wo: head-on, oblique, grazing; below the surface too for glass. */
    private static double[][] views(Bsdf b) {
        double[] cos = b.transmits() ? new double[] {0.9, 0.4, -0.7, -0.25} : new double[] {0.95, 0.5, 0.15};
        double[][] out = new double[cos.length][];
        for (int i = 0; i < cos.length; i++) {
            double s = Math.sqrt(1 - cos[i] * cos[i]);
            out[i] = new double[] {s * 0.6, s * 0.8, cos[i]};
        }
        return out;
    }

    @Test
    void sampledDirectionsFollowTheEvaluatedPdf() {
        List<Object[]> all = cases();
        int tests = 0;
        for (Object[] c : all) {
            tests += views((Bsdf) c[1]).length;
        }
        double threshold = 1 - Math.pow(1 - ALPHA, 1.0 / tests);
        long seed = 1;
        for (Object[] c : all) {
            Bsdf b = (Bsdf) c[1];
            for (double[] wo : views(b)) {
                BsdfSample s = new BsdfSample();
                double p = ChiSquare.pValue((u0, u1, u2, wi) -> {
                    if (!b.sample(wo[0], wo[1], wo[2], u0, u1, u2, WHITE, s)) {
                        return false;
                    }
                    wi[0] = s.wx; wi[1] = s.wy; wi[2] = s.wz;
                    return true;
                }, (x, y, z) -> b.pdf(wo[0], wo[1], wo[2], x, y, z), SAMPLES, seed++);
                assertTrue(p > threshold, c[0] + " wo " + java.util.Arrays.toString(wo) + ": p-value " + p
                        + " below " + threshold);
            }
        }
    }

    @Test
    void aDistortedPdfFailsTheChiSquareTest() {
        // The test must be able to fail: a sampler whose pdf is misreported by 10 % in one half
        Bsdf b = Diffuse.INSTANCE;
        BsdfSample s = new BsdfSample();
        double p = ChiSquare.pValue((u0, u1, u2, wi) -> {
            b.sample(0, 0, 1, u0, u1, u2, WHITE, s);
            wi[0] = s.wx; wi[1] = s.wy; wi[2] = s.wz;
            return true;
        }, (x, y, z) -> b.pdf(0, 0, 1, x, y, z) * (x > 0 ? 1.1 : 0.9), SAMPLES, 7);
        assertTrue(p < 1e-6, "p-value " + p);
    }

    @Test
    void sampleAndEvalAgreeOnValueAndPdf() {
        Random rnd = new Random(3);
        double[] base = {0.8, 0.5, 0.3}, f = new double[3];
        BsdfSample s = new BsdfSample();
        for (Object[] c : cases()) {
            Bsdf b = (Bsdf) c[1];
            for (double[] wo : views(b)) {
                for (int i = 0; i < 2000; i++) {
                    if (!b.sample(wo[0], wo[1], wo[2], rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), base, s)) {
                        continue;
                    }
                    double pdf = b.eval(wo[0], wo[1], wo[2], s.wx, s.wy, s.wz, base, f);
                    String where = c[0] + " wo " + java.util.Arrays.toString(wo) + " wi " + s.wx + "," + s.wy + "," + s.wz;
                    assertEquals(s.pdf, pdf, 1e-7 * Math.max(1, pdf), where);
                    assertEquals(pdf, b.pdf(wo[0], wo[1], wo[2], s.wx, s.wy, s.wz), 1e-7 * Math.max(1, pdf), where);
                    assertEquals(s.fr, f[0], 1e-7 * Math.max(1, f[0]), where);
                    assertEquals(s.fb, f[2], 1e-7 * Math.max(1, f[2]), where);
                }
            }
        }
    }

    @Test
    void reflectionIsReciprocal() {
        Random rnd = new Random(5);
        double[] base = {0.8, 0.5, 0.3}, f1 = new double[3], f2 = new double[3];
        for (Object[] c : cases()) {
            Bsdf b = (Bsdf) c[1];
            for (int i = 0; i < 5000; i++) {
                double[] wo = upper(rnd), wi = upper(rnd);
                b.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], base, f1);
                b.eval(wi[0], wi[1], wi[2], wo[0], wo[1], wo[2], base, f2);
                for (int k = 0; k < 3; k++) {
                    assertEquals(f1[k], f2[k], 1e-9 * Math.max(1, f1[k]), c[0] + " channel " + k);
                }
            }
        }
    }

    @Test
    void noBsdfScattersMoreThanItReceives() {
        // Every sample's weight f cos / pdf is at most 1 for conductors of reflectance ≤ 1 and for
        // glass (G / G1 ≤ 1 times F or 1 − F chosen with that probability); the diffuse and plastic
        // weights are their albedo and its coat-weighted share
        Random rnd = new Random(11);
        BsdfSample s = new BsdfSample();
        Bsdf[] bsdfs = {Diffuse.INSTANCE, new Conductor(new double[] {1, 1, 1}, new double[] {1e4, 1e4, 1e4}, 0.7),
            new Conductor(MetalPresets.ALUMINIUM.eta(), MetalPresets.ALUMINIUM.k(), 0.3),
            new Dielectric(1.5, 0.0), new Dielectric(1.5, 0.3), new Dielectric(1.5, 0.9), new Plastic(1.5, 0.4)};
        for (Bsdf b : bsdfs) {
            for (int v = 0; v < 20; v++) {
                double[] wo = b.transmits() && v % 2 == 1 ? lower(rnd) : upper(rnd);
                double sum = 0;
                int n = 20_000;
                for (int i = 0; i < n; i++) {
                    if (!b.sample(wo[0], wo[1], wo[2], rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), WHITE, s)) {
                        continue;
                    }
                    double w = s.fr * Math.abs(s.wz) / s.pdf;
                    if (!(b instanceof Plastic)) { // a mixture's single weights may exceed 1, its mean not
                        assertTrue(w <= 1 + 1e-9, b.getClass().getSimpleName() + " weight " + w);
                    }
                    sum += w;
                }
                assertTrue(sum / n <= 1 + 1e-9, b.getClass().getSimpleName() + " albedo " + sum / n);
            }
        }
    }

    @Test
    void aRoughMirrorsAlbedoFromSamplesMatchesItsQuadrature() {
        // F = 1 (k huge): the albedo is ∫ G/G1 < 1, what single scattering loses; sampling and a
        // quadrature of eval (independent of the sampler) must agree on it
        Conductor mirror = new Conductor(new double[] {1, 1, 1}, new double[] {1e6, 1e6, 1e6}, 0.5);
        for (double[] wo : new double[][] {{0, 0, 1}, {0.8, 0, 0.6}}) {
            double sampled = albedo(mirror, wo, 200_000, new Random(2));
            double quadrature = quadrature(mirror, wo);
            assertTrue(sampled <= 1 && quadrature <= 1, "albedo " + sampled + ", " + quadrature);
            assertEquals(quadrature, sampled, 0.01 * quadrature, "sampled against quadrature");
        }
        Dielectric glass = new Dielectric(1.5, 0.0);
        assertEquals(1, albedo(glass, new double[] {0.6, 0, 0.8}, 10_000, new Random(3)), 1e-12,
                "smooth glass neither gains nor loses");
    }

    /** ∫ f cos over the upper hemisphere by the midpoint rule in (cos θ, φ). */
    private static double quadrature(Bsdf b, double[] wo) {
        int n = 400;
        double[] f = new double[3];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double z = (i + 0.5) / n, r = Math.sqrt(1 - z * z);
            for (int j = 0; j < 2 * n; j++) {
                double phi = (j + 0.5) / (2 * n) * 2 * Math.PI;
                b.eval(wo[0], wo[1], wo[2], r * Math.cos(phi), r * Math.sin(phi), z, WHITE, f);
                sum += f[0] * z;
            }
        }
        return sum * (1.0 / n) * (Math.PI / n);
    }

    /** ∫ f |cos| over the sphere, from the BSDF's own samples. */
    private static double albedo(Bsdf b, double[] wo, int n, Random rnd) {
        BsdfSample s = new BsdfSample();
        double sum = 0;
        for (int i = 0; i < n; i++) {
            if (b.sample(wo[0], wo[1], wo[2], rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), WHITE, s)) {
                sum += s.fr * Math.abs(s.wz) / s.pdf;
            }
        }
        return sum / n;
    }

    private static double[] upper(Random rnd) {
        double z = 0.02 + 0.98 * rnd.nextDouble(), phi = 2 * Math.PI * rnd.nextDouble(), r = Math.sqrt(1 - z * z);
        return new double[] {r * Math.cos(phi), r * Math.sin(phi), z};
    }

    private static double[] lower(Random rnd) {
        double[] w = upper(rnd);
        w[2] = -w[2];
        return w;
    }
}
