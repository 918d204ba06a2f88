package org.beziertracer.render.light;

/**
 * The answer of {@link Light#sample}: the unit direction {@code w} from the shaded point toward
 * the light, the distance to the sampled point ({@code +∞} for the environment), the incident
 * radiance {@code L} (for a point or spot source: intensity / distance²) and the pdf with respect
 * to solid angle (1 for a delta light). Mutable scratch, one per thread.
 */
public final class LightSample {
    public double wx, wy, wz, distance;
    public double r, g, b;
    public double pdf;
    public boolean delta;

    void set(double x, double y, double z, double dist, double lr, double lg, double lb, double p, boolean isDelta) {
        wx = x; wy = y; wz = z;
        distance = dist;
        r = lr; g = lg; b = lb;
        pdf = p;
        delta = isDelta;
    }
}
