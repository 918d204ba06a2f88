package org.beziertracer.render.bsdf;

/**
 * A bidirectional scattering distribution function in the local shading frame: unit vectors, z
 * along the surface normal, {@code wo} toward the viewer, {@code wi} toward the light, both
 * pointing away from the surface (pbrt-v4's conventions, M. Pharr, W. Jakob, G. Humphreys,
 * "Physically Based Rendering", 4th ed., 2023, ch. 9).
 *
 * <p>{@code base} is the material's colour at the hit (albedo of a diffuse or plastic surface, a
 * tint of a conductor or dielectric), so a texture needs no BSDF of its own. Radiance is not
 * rescaled by η² across a dielectric boundary: paths enter and leave closed objects, and the
 * camera is never inside glass, so the factors cancel (docs/rendering.md).
 *
 * <p>Implementations are immutable and thread-safe; no method allocates.
 */
public interface Bsdf {

    /**
     * {@code f(wo, wi)} per channel into {@code f[0..2]}; returns the pdf with which {@link #sample}
     * picks {@code wi} (solid angle), 0 for a delta BSDF (whose value here is 0).
     */
    double eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] base, double[] f);

    /** The pdf (solid angle) with which {@link #sample} picks {@code wi} given {@code wo}; 0 for delta lobes. */
    double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz);

    /**
     * Samples {@code wi} from three uniform numbers ({@code uc} picks a lobe, {@code u1, u2} the
     * direction); false when no direction was found (the path ends).
     */
    boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, double[] base, BsdfSample out);

    /** True when every lobe is a delta: light sampling is pointless at such a hit. */
    boolean isDelta();

    /** True when light may pass through (the integrator must then keep the true normal's side). */
    default boolean transmits() { return false; }
}
