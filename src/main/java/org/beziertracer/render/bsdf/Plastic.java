package org.beziertracer.render.bsdf;

/**
 * Plastic: a Lambertian base of the material colour under a clear dielectric coat with a
 * Trowbridge–Reitz surface. {@code f = D G F(wo·h) / (4 cosθo cosθi) + (1 − F(cosθo)) (1 − F(cosθi))
 * albedo / π}: the coat's microfacet reflection (Walter et al., EGSR 2007) plus the base seen
 * through the coat's Fresnel transmittance in and out (the coupling of A. Weidlich, A. Wilkie,
 * "Arbitrarily layered micro-facet surfaces", GRAPHITE 2007, without the light reflected back
 * inside the coat: energy-conserving, slightly darker than a full layered model). Sampled as a
 * mixture: the coat by visible normals (Heitz 2018) with probability {@code max(F(cosθo), 1/4)},
 * else the cosine-weighted base. The caller turns the frame so that {@code wo.z > 0}. Immutable.
 */
public final class Plastic implements Bsdf {
    /** The smallest perceptual roughness of the coat (α = 0.0025): a smooth coat would need a delta lobe. */
    public static final double MIN_ROUGHNESS = 0.05;

    private final double eta;
    private final Ggx ggx;

    /** @param eta the coat's index of refraction (> 1); @param roughness the coat's, 0..1, raised to {@link #MIN_ROUGHNESS} */
    public Plastic(double eta, double roughness) {
        if (!(eta > 1) || !Double.isFinite(eta)) {
            throw new IllegalArgumentException("a plastic coat's index of refraction must be > 1, got " + eta);
        }
        this.eta = eta;
        this.ggx = Ggx.ofRoughness(Math.max(MIN_ROUGHNESS, roughness));
    }

    private double specularProbability(double woz) {
        return Math.max(0.25, Fresnel.dielectric(woz, eta));
    }

    @Override
    public double eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] base,
                       double[] f) {
        f[0] = 0; f[1] = 0; f[2] = 0;
        if (woz <= 0 || wiz <= 0) {
            return 0;
        }
        double hx = wox + wix, hy = woy + wiy, hz = woz + wiz;
        double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
        hx /= hl; hy /= hl; hz /= hl;
        double oh = wox * hx + woy * hy + woz * hz;
        double spec = ggx.d(hx, hy, hz) * ggx.g(wox, woy, woz, wix, wiy, wiz) * Fresnel.dielectric(oh, eta)
                / (4 * woz * wiz);
        double diff = (1 - Fresnel.dielectric(woz, eta)) * (1 - Fresnel.dielectric(wiz, eta)) / Math.PI;
        f[0] = spec + diff * base[0]; f[1] = spec + diff * base[1]; f[2] = spec + diff * base[2];
        double p = specularProbability(woz);
        return p * ggx.visible(wox, woy, woz, hx, hy, hz) / (4 * oh) + (1 - p) * wiz / Math.PI;
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        if (woz <= 0 || wiz <= 0) {
            return 0;
        }
        double hx = wox + wix, hy = woy + wiy, hz = woz + wiz;
        double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
        hx /= hl; hy /= hl; hz /= hl;
        double oh = wox * hx + woy * hy + woz * hz;
        double p = specularProbability(woz);
        return p * ggx.visible(wox, woy, woz, hx, hy, hz) / (4 * oh) + (1 - p) * wiz / Math.PI;
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, double[] base,
                          BsdfSample out) {
        if (woz <= 0) {
            return false;
        }
        double ix, iy, iz;
        if (uc < specularProbability(woz)) {
            double[] m = out.m;
            ggx.sampleVisible(wox, woy, woz, u1, u2, m);
            double om = wox * m[0] + woy * m[1] + woz * m[2];
            ix = 2 * om * m[0] - wox; iy = 2 * om * m[1] - woy; iz = 2 * om * m[2] - woz;
        } else {
            double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
            ix = r * Math.cos(phi); iy = r * Math.sin(phi); iz = Math.sqrt(Math.max(0, 1 - u1));
        }
        if (iz <= 0) {
            return false;
        }
        double[] f = out.m;
        double pdf = eval(wox, woy, woz, ix, iy, iz, base, f);
        out.set(ix, iy, iz, f[0], f[1], f[2], pdf, false, false);
        return pdf > 0;
    }

    @Override
    public boolean isDelta() { return false; }
}
