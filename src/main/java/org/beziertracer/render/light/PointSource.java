package org.beziertracer.render.light;

/**
 * An isotropic point source of radiant intensity {@code I} (per channel): irradiance
 * {@code I cosθ / d²} (the inverse-square law; pbrt-v4 §12.1). A delta light.
 */
public final class PointSource implements Light {
    final double x, y, z, ir, ig, ib;

    public PointSource(double x, double y, double z, double ir, double ig, double ib) {
        if (!Double.isFinite(x + y + z) || !(ir >= 0 && ig >= 0 && ib >= 0) || !Double.isFinite(ir + ig + ib)) {
            throw new IllegalArgumentException("a point source needs a finite position and an intensity >= 0");
        }
        this.x = x; this.y = y; this.z = z;
        this.ir = ir; this.ig = ig; this.ib = ib;
    }

    @Override
    public boolean sample(double px, double py, double pz, double u1, double u2, LightSample out) {
        double dx = x - px, dy = y - py, dz = z - pz;
        double d2 = dx * dx + dy * dy + dz * dz;
        if (!(d2 > 0)) {
            return false;
        }
        double d = Math.sqrt(d2), s = 1 / d2;
        out.set(dx / d, dy / d, dz / d, d, ir * s, ig * s, ib * s, 1, true);
        return true;
    }

    @Override
    public double pdf(double px, double py, double pz, double wx, double wy, double wz) { return 0; }

    @Override
    public double hit(double ox, double oy, double oz, double wx, double wy, double wz, double[] le) {
        return Double.POSITIVE_INFINITY;
    }

    @Override
    public boolean isDelta() { return true; }
}
