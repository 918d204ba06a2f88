package org.beziertracer.model;

import org.beziertracer.math.Vec3;

/**
 * An area light of uniform radiance: a sphere ({@code center}, {@code radius}) or a parallelogram
 * ({@code corner + s·edge1 + t·edge2}, s, t in 0..1, lit on the side of {@code edge1 × edge2}).
 * The emitted radiance is {@code color} when {@code power} is NaN (not given), else
 * {@code color · power / (π · area)}: a Lambertian emitter of that radiant flux.
 */
public record AreaLight(Shape shape, Vec3 center, double radius, Vec3 corner, Vec3 edge1, Vec3 edge2,
                        double r, double g, double b, double power) {

    public enum Shape { SPHERE, RECT }

    public AreaLight {
        if (shape == Shape.SPHERE) {
            if (center == null || !center.isFinite() || !(radius > 0) || !Double.isFinite(radius)) {
                throw new IllegalArgumentException("a sphere light needs a finite center and a radius > 0");
            }
        } else {
            if (corner == null || edge1 == null || edge2 == null || !corner.isFinite() || !edge1.isFinite()
                    || !edge2.isFinite()) {
                throw new IllegalArgumentException("a rect light needs a finite corner, edge1 and edge2");
            }
            if (!(edge1.cross(edge2).length() > 0)) {
                throw new IllegalArgumentException("a rect light's edge1 and edge2 must not be parallel");
            }
        }
        if (!(r >= 0 && g >= 0 && b >= 0) || !Double.isFinite(r + g + b)) {
            throw new IllegalArgumentException("light colour must be finite and >= 0");
        }
        if (!Double.isNaN(power) && !(power >= 0 && Double.isFinite(power))) {
            throw new IllegalArgumentException("light power must be finite and >= 0, got " + power);
        }
    }

    public static AreaLight sphere(Vec3 center, double radius, double r, double g, double b, double power) {
        return new AreaLight(Shape.SPHERE, center, radius, null, null, null, r, g, b, power);
    }

    public static AreaLight rect(Vec3 corner, Vec3 edge1, Vec3 edge2, double r, double g, double b, double power) {
        return new AreaLight(Shape.RECT, null, 0, corner, edge1, edge2, r, g, b, power);
    }

    /** The emitting surface's area. */
    public double area() {
        return shape == Shape.SPHERE ? 4 * Math.PI * radius * radius : edge1.cross(edge2).length();
    }

    /** The emitted radiance per channel (see the class comment). */
    public double[] radiance() {
        double s = Double.isNaN(power) ? 1 : power / (Math.PI * area());
        return new double[] {r * s, g * s, b * s};
    }
}
