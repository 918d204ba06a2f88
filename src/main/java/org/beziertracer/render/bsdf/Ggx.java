package org.beziertracer.render.bsdf;

/**
 * The isotropic Trowbridge–Reitz (GGX) microfacet distribution and its Smith masking–shadowing
 * (T. S. Trowbridge, K. P. Reitz, JOSA 65(5), 1975; B. Walter, S. Marschner, H. Li, K. Torrance,
 * "Microfacet models for refraction through rough surfaces", EGSR 2007), with sampling of the
 * visible normals (E. Heitz, "Sampling the GGX distribution of visible normals", JCGT 7(4), 2018).
 * Directions are in the local frame (z = macro normal). Immutable; no method allocates.
 *
 * <p>The roughness a user gives is perceptual: {@code α = roughness²}.
 */
public final class Ggx {
    /** Below this α a surface is treated as perfectly smooth (a delta lobe), as pbrt-v4 does. */
    public static final double SMOOTH_ALPHA = 1e-3;

    final double alpha;

    public Ggx(double alpha) {
        if (!(alpha >= 0) || !(alpha <= 1)) {
            throw new IllegalArgumentException("GGX alpha must be in 0..1, got " + alpha);
        }
        this.alpha = Math.max(alpha, SMOOTH_ALPHA);
    }

    /** The distribution of a perceptual roughness in 0..1 ({@code α = roughness²}). */
    public static Ggx ofRoughness(double roughness) { return new Ggx(roughness * roughness); }

    public double alpha() { return alpha; }

    /** D(m) for the unit microfacet normal {@code (mx, my, mz)}. */
    public double d(double mx, double my, double mz) {
        if (mz <= 0) {
            return 0;
        }
        double a2 = alpha * alpha;
        double t = (mx * mx + my * my) / a2 + mz * mz;
        return 1 / (Math.PI * a2 * t * t);
    }

    /** Smith's Λ(w). */
    public double lambda(double wx, double wy, double wz) {
        double z2 = wz * wz;
        if (z2 == 0) {
            return Double.POSITIVE_INFINITY;
        }
        double tan2 = (wx * wx + wy * wy) / z2;
        return 0.5 * (Math.sqrt(1 + alpha * alpha * tan2) - 1);
    }

    /** Smith's masking G1(w) = 1 / (1 + Λ(w)). */
    public double g1(double wx, double wy, double wz) { return 1 / (1 + lambda(wx, wy, wz)); }

    /** The height-correlated masking–shadowing G(wo, wi) = 1 / (1 + Λ(wo) + Λ(wi)). */
    public double g(double ox, double oy, double oz, double ix, double iy, double iz) {
        return 1 / (1 + lambda(ox, oy, oz) + lambda(ix, iy, iz));
    }

    /**
     * The density of visible normals {@code D_w(m) = G1(w) max(0, w·m) D(m) / |w_z|}, with {@code w}
     * flipped to the upper hemisphere (as {@link #sampleVisible} samples it).
     */
    public double visible(double wx, double wy, double wz, double mx, double my, double mz) {
        if (wz < 0) {
            wx = -wx; wy = -wy; wz = -wz;
        }
        if (wz == 0) {
            return 0;
        }
        double wm = wx * mx + wy * my + wz * mz;
        return wm <= 0 ? 0 : g1(wx, wy, wz) * wm * d(mx, my, mz) / wz;
    }

    /**
     * Samples a visible normal for the view direction {@code w} (flipped to the upper hemisphere)
     * from {@code u1, u2} in [0,1) and writes it into {@code m[0..2]} (Heitz 2018, listing 1).
     */
    public void sampleVisible(double wx, double wy, double wz, double u1, double u2, double[] m) {
        if (wz < 0) {
            wx = -wx; wy = -wy; wz = -wz;
        }
        // Stretch the view direction to the hemisphere configuration
        double vx = alpha * wx, vy = alpha * wy, vz = wz;
        double vl = 1 / Math.sqrt(vx * vx + vy * vy + vz * vz);
        vx *= vl; vy *= vl; vz *= vl;
        // An orthonormal basis around it
        double lensq = vx * vx + vy * vy;
        double t1x = 1, t1y = 0;
        if (lensq > 0) {
            double inv = 1 / Math.sqrt(lensq);
            t1x = -vy * inv;
            t1y = vx * inv;
        }
        double t2x = vy * 0 - vz * t1y, t2y = vz * t1x, t2z = vx * t1y - vy * t1x;
        // A point on the projected disk, warped toward the visible half
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double p1 = r * Math.cos(phi), p2 = r * Math.sin(phi);
        double s = 0.5 * (1 + vz);
        p2 = (1 - s) * Math.sqrt(Math.max(0, 1 - p1 * p1)) + s * p2;
        double p3 = Math.sqrt(Math.max(0, 1 - p1 * p1 - p2 * p2));
        double nx = p1 * t1x + p2 * t2x + p3 * vx;
        double ny = p1 * t1y + p2 * t2y + p3 * vy;
        double nz = p2 * t2z + p3 * vz;
        // Unstretch
        double ex = alpha * nx, ey = alpha * ny, ez = Math.max(1e-12, nz);
        double el = 1 / Math.sqrt(ex * ex + ey * ey + ez * ez);
        m[0] = ex * el; m[1] = ey * el; m[2] = ez * el;
    }
}
