package org.beziertracer.render.bsdf;

import java.util.Random;

/**
 * Pearson's chi-square test of a sampling routine against its own pdf over the sphere of
 * directions, as pbrt-v3/v4 ({@code bsdfs_test}) and Mitsuba's {@code ChiSquare} do: histogram
 * sampled directions in (θ, φ) bins, integrate the evaluated pdf over each bin numerically, pool
 * the bins whose expected count is below 5, and return the p-value of the statistic (upper tail
 * of the χ² distribution, regularised incomplete gamma function from Numerical Recipes, 3rd ed., §6.2).
 */
final class ChiSquare {
    static final int THETA_BINS = 10, PHI_BINS = 20;
    /**
     * Midpoint-rule cells per bin: fine in θ, where a rough glass's transmitted lobe ends in a sharp
     * edge (its critical cone) that a coarse rule would misjudge by far more than the noise.
     */
    static final int SUB_THETA = 384, SUB_PHI = 16;

    interface Sampler { boolean sample(double u0, double u1, double u2, double[] wi); }

    interface Pdf { double pdf(double x, double y, double z); }

    private ChiSquare() {}

    /** The p-value of {@code samples} draws of {@code s} against {@code pdf}. */
    static double pValue(Sampler s, Pdf pdf, int samples, long seed) {
        Random rnd = new Random(seed);
        double[] observed = new double[THETA_BINS * PHI_BINS];
        double[] wi = new double[3];
        for (int i = 0; i < samples; i++) {
            if (!s.sample(rnd.nextDouble(), rnd.nextDouble(), rnd.nextDouble(), wi)) {
                continue;
            }
            double theta = Math.acos(Math.max(-1, Math.min(1, wi[2])));
            double phi = Math.atan2(wi[1], wi[0]);
            if (phi < 0) {
                phi += 2 * Math.PI;
            }
            int tb = Math.min(THETA_BINS - 1, (int) (theta / Math.PI * THETA_BINS));
            int pb = Math.min(PHI_BINS - 1, (int) (phi / (2 * Math.PI) * PHI_BINS));
            observed[tb * PHI_BINS + pb]++;
        }
        double[] expected = new double[observed.length];
        double dt = Math.PI / THETA_BINS, dp = 2 * Math.PI / PHI_BINS;
        for (int tb = 0; tb < THETA_BINS; tb++) {
            for (int pb = 0; pb < PHI_BINS; pb++) {
                double sum = 0;
                for (int a = 0; a < SUB_THETA; a++) {
                    double theta = (tb + (a + 0.5) / SUB_THETA) * dt;
                    double st = Math.sin(theta), ct = Math.cos(theta);
                    for (int b = 0; b < SUB_PHI; b++) {
                        double phi = (pb + (b + 0.5) / SUB_PHI) * dp;
                        sum += pdf.pdf(st * Math.cos(phi), st * Math.sin(phi), ct) * st;
                    }
                }
                expected[tb * PHI_BINS + pb] = sum * dt * dp / (SUB_THETA * SUB_PHI) * samples;
            }
        }
        return pValue(observed, expected);
    }

    /** The p-value of the observed counts against the expected ones, pooling bins expected below 5. */
    static double pValue(double[] observed, double[] expected) {
        double chi2 = 0, pooledObs = 0, pooledExp = 0;
        int dof = 0;
        for (int i = 0; i < observed.length; i++) {
            if (expected[i] < 5) {
                pooledObs += observed[i];
                pooledExp += expected[i];
            } else {
                double d = observed[i] - expected[i];
                chi2 += d * d / expected[i];
                dof++;
            }
        }
        if (pooledExp > 0) {
            double d = pooledObs - pooledExp;
            chi2 += d * d / pooledExp;
            dof++;
        } else if (pooledObs > 0) {
            return 0; // samples where the pdf says there are none
        }
        return gammaQ((dof - 1) / 2.0, chi2 / 2);
    }

    /** The regularised upper incomplete gamma function Q(a, x). */
    static double gammaQ(double a, double x) {
        if (x < a + 1) {
            double ap = a, sum = 1 / a, del = sum;
            for (int n = 0; n < 1000; n++) {
                ap++;
                del *= x / ap;
                sum += del;
                if (Math.abs(del) < Math.abs(sum) * 1e-15) {
                    break;
                }
            }
            return 1 - sum * Math.exp(-x + a * Math.log(x) - lnGamma(a));
        }
        double b = x + 1 - a, c = 1 / 1e-300, d = 1 / b, h = d;
        for (int i = 1; i < 1000; i++) {
            double an = -i * (i - a);
            b += 2;
            d = an * d + b;
            if (Math.abs(d) < 1e-300) {
                d = 1e-300;
            }
            c = b + an / c;
            if (Math.abs(c) < 1e-300) {
                c = 1e-300;
            }
            d = 1 / d;
            double del = d * c;
            h *= del;
            if (Math.abs(del - 1) < 1e-15) {
                break;
            }
        }
        return Math.exp(-x + a * Math.log(x) - lnGamma(a)) * h;
    }

    /** ln Γ(x) by Lanczos' approximation (g = 7, 9 terms). */
    static double lnGamma(double x) {
        double[] c = {0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
                -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6,
                1.5056327351493116e-7};
        x -= 1;
        double a = c[0], t = x + 7.5;
        for (int i = 1; i < 9; i++) {
            a += c[i] / (x + i);
        }
        return 0.5 * Math.log(2 * Math.PI) + (x + 0.5) * Math.log(t) - t + Math.log(a);
    }
}
