package org.beziertracer.render.light;

/**
 * A spherical area light of uniform radiance {@code L} on its surface, sampled uniformly in the
 * cone it subtends from the shaded point (J. Arvo's cone sampling as in pbrt-v4 §6.2.4,
 * Sphere::Sample(ctx, u)): pdf {@code 1 / (2π (1 − cosθmax))}, {@code sin²θmax = r² / d²}. A point
 * inside the sphere gets no light (the sphere emits outward).
 */
public final class SphereLight implements Light {
    private final double cx, cy, cz, radius, lr, lg, lb;

    public SphereLight(double cx, double cy, double cz, double radius, double lr, double lg, double lb) {
        if (!Double.isFinite(cx + cy + cz) || !(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("a sphere light needs a finite centre and a radius > 0");
        }
        if (!(lr >= 0 && lg >= 0 && lb >= 0) || !Double.isFinite(lr + lg + lb)) {
            throw new IllegalArgumentException("a light's radiance must be finite and >= 0");
        }
        this.cx = cx; this.cy = cy; this.cz = cz;
        this.radius = radius;
        this.lr = lr; this.lg = lg; this.lb = lb;
    }

    @Override
    public boolean sample(double px, double py, double pz, double u1, double u2, LightSample out) {
        double dx = cx - px, dy = cy - py, dz = cz - pz;
        double d2 = dx * dx + dy * dy + dz * dz;
        double r2 = radius * radius;
        if (d2 <= r2) {
            return false;
        }
        double d = Math.sqrt(d2);
        double wcx = dx / d, wcy = dy / d, wcz = dz / d;
        double sin2Max = r2 / d2, cosMax = Math.sqrt(Math.max(0, 1 - sin2Max));
        double oneMinusCosMax = sin2Max / (1 + cosMax); // 1 − cosθmax without cancellation
        double cos = 1 - u1 * oneMinusCosMax, sin = Math.sqrt(Math.max(0, 1 - cos * cos));
        double phi = 2 * Math.PI * u2;
        // A frame around the direction to the centre (Duff et al., JCGT 6(1), 2017)
        double sign = Math.copySign(1, wcz), a = -1 / (sign + wcz), b = wcx * wcy * a;
        double t1x = 1 + sign * wcx * wcx * a, t1y = sign * b, t1z = -sign * wcx;
        double t2x = b, t2y = sign + wcy * wcy * a, t2z = -wcy;
        double sc = sin * Math.cos(phi), ss = sin * Math.sin(phi);
        double wx = sc * t1x + ss * t2x + cos * wcx, wy = sc * t1y + ss * t2y + cos * wcy, wz = sc * t1z + ss * t2z + cos * wcz;
        double t = nearT(px, py, pz, wx, wy, wz);
        if (!(t < Double.POSITIVE_INFINITY)) {
            t = d * cos; // grazing the rim: the tangent point
        }
        out.set(wx, wy, wz, t, lr, lg, lb, 1 / (2 * Math.PI * oneMinusCosMax), false);
        return true;
    }

    @Override
    public double pdf(double px, double py, double pz, double wx, double wy, double wz) {
        double dx = cx - px, dy = cy - py, dz = cz - pz;
        double d2 = dx * dx + dy * dy + dz * dz, r2 = radius * radius;
        if (d2 <= r2) {
            return 0;
        }
        double sin2Max = r2 / d2, cosMax = Math.sqrt(Math.max(0, 1 - sin2Max));
        double d = Math.sqrt(d2);
        if ((dx * wx + dy * wy + dz * wz) / d < cosMax) {
            return 0;
        }
        return 1 / (2 * Math.PI * sin2Max / (1 + cosMax));
    }

    @Override
    public double hit(double ox, double oy, double oz, double wx, double wy, double wz, double[] le) {
        double t = nearT(ox, oy, oz, wx, wy, wz);
        if (t < Double.POSITIVE_INFINITY) {
            le[0] = lr; le[1] = lg; le[2] = lb;
        }
        return t;
    }

    /** The nearer positive root of the ray–sphere quadratic for a unit direction, from outside; +∞ when none. */
    private double nearT(double ox, double oy, double oz, double wx, double wy, double wz) {
        double fx = ox - cx, fy = oy - cy, fz = oz - cz;
        double b = fx * wx + fy * wy + fz * wz;
        double c = fx * fx + fy * fy + fz * fz - radius * radius;
        if (c <= 0) {
            return Double.POSITIVE_INFINITY; // inside: the sphere emits outward only
        }
        // the discriminant as b² − c, with the closest approach computed directly to keep precision
        double qx = fx - b * wx, qy = fy - b * wy, qz = fz - b * wz;
        double disc = radius * radius - (qx * qx + qy * qy + qz * qz);
        if (disc < 0 || b > 0) {
            return Double.POSITIVE_INFINITY;
        }
        double q = -b + Math.sqrt(disc);
        double t = c / q;
        return t > 0 ? t : Double.POSITIVE_INFINITY;
    }
}
