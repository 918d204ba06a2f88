package org.beziertracer.render.bsdf;

/**
 * The answer of {@link Bsdf#sample}: the sampled incident direction {@code wi} (unit, local shading
 * frame, z along the normal), the BSDF value {@code f} per channel, the pdf with respect to solid
 * angle (for a delta lobe: the discrete probability of the lobe) and whether the lobe is a delta
 * (specular) one. Mutable scratch, one per thread; nothing here is allocated per sample.
 */
public final class BsdfSample {
    public double wx, wy, wz;
    public double fr, fg, fb;
    public double pdf;
    /** A perfectly specular lobe: {@code f} and {@code pdf} hold the delta's weights, not densities. */
    public boolean delta;
    /** True when {@code wi} lies on the other side of the surface from {@code wo}. */
    public boolean transmitted;
    /** Scratch for a sampled microfacet normal. */
    final double[] m = new double[3];

    void set(double x, double y, double z, double r, double g, double b, double p, boolean isDelta, boolean through) {
        wx = x; wy = y; wz = z;
        fr = r; fg = g; fb = b;
        pdf = p;
        delta = isDelta;
        transmitted = through;
    }
}
