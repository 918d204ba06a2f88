package org.beziertracer.render.bsdf;

/**
 * Glass: a dielectric boundary of relative index {@code η} (inside / outside), smooth (Fresnel
 * reflection and Snell refraction, both delta lobes chosen in proportion to F and 1 − F) or rough
 * (B. Walter, S. Marschner, H. Li, K. Torrance, "Microfacet models for refraction through rough
 * surfaces", EGSR 2007, with the generalised half vector, visible-normal sampling after Heitz,
 * JCGT 2018, and the lobe chosen by the Fresnel term as in pbrt-v4 §9.7).
 *
 * <p>The frame's z is the surface's own (outward) normal: {@code wo.z > 0} is outside. The
 * transmitted lobe is written in its flux (importance) form, without radiance's {@code 1/η²}
 * factor ({@link Bsdf}); its weight {@code f cos / pdf} is then {@code G / G1 ≤ 1}. The material
 * colour tints the transmitted light only. Immutable.
 */
public final class Dielectric implements Bsdf {
    private final double eta;
    private final Ggx ggx;
    private final boolean smooth;

    /** @param eta index of refraction (inside / outside), > 0 and ≠ 1; @param roughness 0..1 ({@code α = roughness²}) */
    public Dielectric(double eta, double roughness) {
        if (!(eta > 0) || !Double.isFinite(eta) || eta == 1) {
            throw new IllegalArgumentException("a dielectric's index of refraction must be positive and not 1, got " + eta);
        }
        this.eta = eta;
        this.ggx = Ggx.ofRoughness(roughness);
        this.smooth = roughness * roughness < Ggx.SMOOTH_ALPHA;
    }

    public double eta() { return eta; }

    @Override
    public boolean transmits() { return true; }

    @Override
    public boolean isDelta() { return smooth; }

    @Override
    public double eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] base,
                       double[] f) {
        f[0] = 0; f[1] = 0; f[2] = 0;
        if (smooth || woz == 0 || wiz == 0) {
            return 0;
        }
        boolean reflect = woz * wiz > 0;
        double etap = reflect ? 1 : woz > 0 ? eta : 1 / eta;
        // The generalised half vector, facing +z
        double mx = wix * etap + wox, my = wiy * etap + woy, mz = wiz * etap + woz;
        double ml = Math.sqrt(mx * mx + my * my + mz * mz);
        if (ml == 0) {
            return 0;
        }
        double s = mz < 0 ? -1 / ml : 1 / ml;
        mx *= s; my *= s; mz *= s;
        double im = wix * mx + wiy * my + wiz * mz, om = wox * mx + woy * my + woz * mz;
        if (im * wiz < 0 || om * woz < 0) {
            return 0; // back-facing microfacet
        }
        double r = Fresnel.dielectric(om, eta), t = 1 - r;
        double d = ggx.d(mx, my, mz), g = ggx.g(wox, woy, woz, wix, wiy, wiz);
        double vis = ggx.visible(wox, woy, woz, mx, my, mz);
        if (reflect) {
            double v = d * g * r / Math.abs(4 * woz * wiz);
            f[0] = v; f[1] = v; f[2] = v;
            return vis / (4 * Math.abs(om)) * r;
        }
        double denom = im + om / etap;
        denom *= denom;
        double v = d * t * g * Math.abs(im * om / (wiz * woz * denom));
        f[0] = v * base[0]; f[1] = v * base[1]; f[2] = v * base[2];
        return vis * Math.abs(im) / denom * t;
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        if (smooth || woz == 0 || wiz == 0) {
            return 0;
        }
        boolean reflect = woz * wiz > 0;
        double etap = reflect ? 1 : woz > 0 ? eta : 1 / eta;
        double mx = wix * etap + wox, my = wiy * etap + woy, mz = wiz * etap + woz;
        double ml = Math.sqrt(mx * mx + my * my + mz * mz);
        if (ml == 0) {
            return 0;
        }
        double s = mz < 0 ? -1 / ml : 1 / ml;
        mx *= s; my *= s; mz *= s;
        double im = wix * mx + wiy * my + wiz * mz, om = wox * mx + woy * my + woz * mz;
        if (im * wiz < 0 || om * woz < 0) {
            return 0;
        }
        double r = Fresnel.dielectric(om, eta);
        double vis = ggx.visible(wox, woy, woz, mx, my, mz);
        if (reflect) {
            return vis / (4 * Math.abs(om)) * r;
        }
        double denom = im + om / etap;
        return vis * Math.abs(im) / (denom * denom) * (1 - r);
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, double[] base,
                          BsdfSample out) {
        if (woz == 0) {
            return false;
        }
        if (smooth) {
            return sampleSmooth(wox, woy, woz, uc, base, out);
        }
        double[] m = out.m;
        ggx.sampleVisible(wox, woy, woz, u1, u2, m);
        double mx = m[0], my = m[1], mz = m[2];
        double om = wox * mx + woy * my + woz * mz;
        double r = Fresnel.dielectric(om, eta), t = 1 - r;
        double vis = ggx.visible(wox, woy, woz, mx, my, mz);
        if (uc < r) {
            double ix = 2 * om * mx - wox, iy = 2 * om * my - woy, iz = 2 * om * mz - woz;
            if (iz * woz <= 0) {
                return false;
            }
            double v = ggx.d(mx, my, mz) * ggx.g(wox, woy, woz, ix, iy, iz) * r / Math.abs(4 * woz * iz);
            out.set(ix, iy, iz, v, v, v, vis / (4 * Math.abs(om)) * r, false, false);
            return out.pdf > 0;
        }
        // Refract wo about m (Snell), the normal turned to wo's side
        double e = eta, c = om, nx = mx, ny = my, nz = mz;
        if (c < 0) {
            e = 1 / e;
            c = -c;
            nx = -nx; ny = -ny; nz = -nz;
        }
        double sin2T = Math.max(0, 1 - c * c) / (e * e);
        if (sin2T >= 1) {
            return false;
        }
        double cosT = Math.sqrt(1 - sin2T);
        double a = c / e - cosT;
        double ix = -wox / e + a * nx, iy = -woy / e + a * ny, iz = -woz / e + a * nz;
        if (iz * woz >= 0) {
            return false;
        }
        double im = ix * mx + iy * my + iz * mz;
        double denom = im + om / e;
        denom *= denom;
        double pdf = vis * Math.abs(im) / denom * t;
        double v = ggx.d(mx, my, mz) * t * ggx.g(wox, woy, woz, ix, iy, iz) * Math.abs(im * om / (iz * woz * denom));
        out.set(ix, iy, iz, v * base[0], v * base[1], v * base[2], pdf, false, true);
        return pdf > 0;
    }

    /** Fresnel reflection or Snell refraction, each with the probability of its share of the light. */
    private boolean sampleSmooth(double wox, double woy, double woz, double uc, double[] base, BsdfSample out) {
        double r = Fresnel.dielectric(woz, eta), t = 1 - r;
        double cos = Math.abs(woz);
        if (uc < r) {
            out.set(-wox, -woy, woz, r / cos, r / cos, r / cos, r, true, false);
            return true;
        }
        double e = woz > 0 ? eta : 1 / eta;
        double sin2T = (1 - cos * cos) / (e * e);
        if (sin2T >= 1) {
            return false;
        }
        double cosT = Math.sqrt(1 - sin2T);
        double sign = woz > 0 ? 1 : -1;
        double a = cos / e - cosT;
        double ix = -wox / e, iy = -woy / e, iz = -woz / e + a * sign;
        double v = t / cosT;
        out.set(ix, iy, iz, v * base[0], v * base[1], v * base[2], t, true, true);
        return true;
    }
}
