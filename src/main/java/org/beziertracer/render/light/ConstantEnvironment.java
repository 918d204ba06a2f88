package org.beziertracer.render.light;

/**
 * A uniform environment of radiance {@code L} around the scene, at infinity: every ray that leaves
 * the scene sees it. Sampled uniformly over the sphere (pdf {@code 1 / 4π}; with MIS the BSDF's
 * own samples carry the rest).
 */
public final class ConstantEnvironment implements Light {
    private static final double PDF = 1 / (4 * Math.PI);
    private final double lr, lg, lb;

    public ConstantEnvironment(double lr, double lg, double lb) {
        if (!(lr >= 0 && lg >= 0 && lb >= 0) || !Double.isFinite(lr + lg + lb)) {
            throw new IllegalArgumentException("an environment's radiance must be finite and >= 0");
        }
        this.lr = lr; this.lg = lg; this.lb = lb;
    }

    @Override
    public boolean sample(double px, double py, double pz, double u1, double u2, LightSample out) {
        double z = 1 - 2 * u1, r = Math.sqrt(Math.max(0, 1 - z * z)), phi = 2 * Math.PI * u2;
        out.set(r * Math.cos(phi), r * Math.sin(phi), z, Double.POSITIVE_INFINITY, lr, lg, lb, PDF, false);
        return true;
    }

    @Override
    public double pdf(double px, double py, double pz, double wx, double wy, double wz) { return PDF; }

    @Override
    public double hit(double ox, double oy, double oz, double wx, double wy, double wz, double[] le) {
        le[0] = lr; le[1] = lg; le[2] = lb;
        return Double.MAX_VALUE;
    }

    @Override
    public boolean isEnvironment() { return true; }
}
