package org.beziertracer.render.bsdf;

/**
 * A metal: Fresnel reflection of a conductor of complex index {@code η + iκ} per channel
 * ({@link Fresnel#conductor}) on a Trowbridge–Reitz microfacet surface (Walter et al., EGSR 2007),
 * {@code f = D(h) G(wo, wi) F(wo·h) / (4 cosθo cosθi)}, sampled by visible normals (Heitz, JCGT
 * 2018; pdf {@code D_wo(h) / (4 wo·h)}); below {@link Ggx#SMOOTH_ALPHA} a perfect mirror. The
 * material colour tints the reflectance (white for the presets of {@link org.beziertracer.model.MetalPresets}). The
 * caller turns the frame so that {@code wo.z > 0}. Immutable.
 */
public final class Conductor implements Bsdf {
    private final double[] eta, k;
    private final Ggx ggx;
    private final boolean smooth;

    /**
     * @param eta       real part of the index per channel (r, g, b)
     * @param k         absorption (imaginary part) per channel
     * @param roughness perceptual roughness 0..1 ({@code α = roughness²})
     */
    public Conductor(double[] eta, double[] k, double roughness) {
        if (eta.length != 3 || k.length != 3) {
            throw new IllegalArgumentException("a conductor needs 3 values of eta and of k");
        }
        for (int c = 0; c < 3; c++) {
            if (!(eta[c] > 0) || !(k[c] >= 0) || !Double.isFinite(eta[c] + k[c])) {
                throw new IllegalArgumentException("conductor eta must be > 0 and k >= 0, got " + eta[c] + ", " + k[c]);
            }
        }
        this.eta = eta.clone();
        this.k = k.clone();
        this.ggx = Ggx.ofRoughness(roughness);
        this.smooth = roughness * roughness < Ggx.SMOOTH_ALPHA;
    }

    @Override
    public double eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] base,
                       double[] f) {
        f[0] = 0; f[1] = 0; f[2] = 0;
        if (smooth || woz <= 0 || wiz <= 0) {
            return 0;
        }
        double hx = wox + wix, hy = woy + wiy, hz = woz + wiz;
        double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (hl == 0) {
            return 0;
        }
        hx /= hl; hy /= hl; hz /= hl;
        double oh = wox * hx + woy * hy + woz * hz;
        double common = ggx.d(hx, hy, hz) * ggx.g(wox, woy, woz, wix, wiy, wiz) / (4 * woz * wiz);
        fresnel(oh, base, common, f);
        return ggx.visible(wox, woy, woz, hx, hy, hz) / (4 * oh);
    }

    private void fresnel(double cos, double[] base, double scale, double[] f) {
        f[0] = scale * base[0] * Fresnel.conductor(cos, eta[0], k[0]);
        f[1] = scale * base[1] * Fresnel.conductor(cos, eta[1], k[1]);
        f[2] = scale * base[2] * Fresnel.conductor(cos, eta[2], k[2]);
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        if (smooth || woz <= 0 || wiz <= 0) {
            return 0;
        }
        double hx = wox + wix, hy = woy + wiy, hz = woz + wiz;
        double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (hl == 0) {
            return 0;
        }
        hx /= hl; hy /= hl; hz /= hl;
        return ggx.visible(wox, woy, woz, hx, hy, hz) / (4 * (wox * hx + woy * hy + woz * hz));
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, double[] base,
                          BsdfSample out) {
        if (woz <= 0) {
            return false;
        }
        if (smooth) {
            double[] f = out.m;
            fresnel(woz, base, 1 / woz, f);
            out.set(-wox, -woy, woz, f[0], f[1], f[2], 1, true, false);
            return true;
        }
        double[] m = out.m;
        ggx.sampleVisible(wox, woy, woz, u1, u2, m);
        double om = wox * m[0] + woy * m[1] + woz * m[2];
        double ix = 2 * om * m[0] - wox, iy = 2 * om * m[1] - woy, iz = 2 * om * m[2] - woz;
        if (iz <= 0 || om <= 0) {
            return false;
        }
        double pdf = ggx.visible(wox, woy, woz, m[0], m[1], m[2]) / (4 * om);
        double common = ggx.d(m[0], m[1], m[2]) * ggx.g(wox, woy, woz, ix, iy, iz) / (4 * woz * iz);
        double fr = common * base[0] * Fresnel.conductor(om, eta[0], k[0]);
        double fg = common * base[1] * Fresnel.conductor(om, eta[1], k[1]);
        double fb = common * base[2] * Fresnel.conductor(om, eta[2], k[2]);
        out.set(ix, iy, iz, fr, fg, fb, pdf, false, false);
        return pdf > 0;
    }

    @Override
    public boolean isDelta() { return smooth; }
}
