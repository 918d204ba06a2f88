package org.beziertracer.render.light;

/**
 * A spot light: a point source whose intensity falls from full inside the cone of half-angle
 * {@code falloffStart} to zero at {@code totalWidth}, by a smoothstep in the cosine (pbrt-v4
 * §12.2.1, SpotLight::I). A delta light.
 */
public final class SpotSource implements Light {
    private final PointSource point;
    private final double ax, ay, az, cosTotal, cosStart;

    /**
     * @param axis         the direction the spot points (need not be unit)
     * @param totalDegrees half-angle where the light ends, 0 < falloffStart ≤ total ≤ 90
     */
    public SpotSource(double x, double y, double z, double[] axis, double totalDegrees, double falloffDegrees,
                      double ir, double ig, double ib) {
        if (!(falloffDegrees > 0 && falloffDegrees <= totalDegrees && totalDegrees <= 90)) {
            throw new IllegalArgumentException("spot angles must satisfy 0 < falloff start <= total <= 90 degrees, got "
                    + falloffDegrees + " and " + totalDegrees);
        }
        double l = Math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
        if (!(l > 0) || !Double.isFinite(l)) {
            throw new IllegalArgumentException("a spot light needs a non-zero finite axis");
        }
        ax = axis[0] / l; ay = axis[1] / l; az = axis[2] / l;
        cosTotal = Math.cos(Math.toRadians(totalDegrees));
        cosStart = Math.cos(Math.toRadians(falloffDegrees));
        point = new PointSource(x, y, z, ir, ig, ib); // direction and distance; the falloff is applied here
    }

    /** The smoothstep falloff for the unit direction {@code w} leaving the source. */
    public double falloff(double wx, double wy, double wz) {
        double c = wx * ax + wy * ay + wz * az;
        if (c <= cosTotal) {
            return 0;
        }
        if (c >= cosStart) {
            return 1;
        }
        double t = (c - cosTotal) / (cosStart - cosTotal);
        return t * t * (3 - 2 * t);
    }

    @Override
    public boolean sample(double px, double py, double pz, double u1, double u2, LightSample out) {
        if (!point.sample(px, py, pz, u1, u2, out)) {
            return false;
        }
        double f = falloff(-out.wx, -out.wy, -out.wz);
        if (f <= 0) {
            return false;
        }
        out.r *= f; out.g *= f; out.b *= f;
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
