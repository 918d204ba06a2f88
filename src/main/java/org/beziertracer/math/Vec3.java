package org.beziertracer.math;

/**
 * Immutable 3-vector of doubles, for scene description and set-up code.
 *
 * <p>The per-ray hot path does not use this class (it works on plain {@code double}s and flat
 * arrays); {@code Vec3} is for camera set-up, scene files, lights and tests.
 */
public record Vec3(double x, double y, double z) {

    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    public static final Vec3 X = new Vec3(1, 0, 0);
    public static final Vec3 Y = new Vec3(0, 1, 0);
    public static final Vec3 Z = new Vec3(0, 0, 1);

    public Vec3 add(Vec3 o) { return new Vec3(x + o.x, y + o.y, z + o.z); }

    public Vec3 sub(Vec3 o) { return new Vec3(x - o.x, y - o.y, z - o.z); }

    public Vec3 scale(double s) { return new Vec3(x * s, y * s, z * s); }

    public double dot(Vec3 o) { return x * o.x + y * o.y + z * o.z; }

    public Vec3 cross(Vec3 o) {
        return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x);
    }

    public double length() { return Math.sqrt(dot(this)); }

    /** Unit vector in the same direction; throws for the zero vector. */
    public Vec3 normalize() {
        double len = length();
        if (!(len > 0) || !Double.isFinite(len)) {
            throw new IllegalArgumentException("cannot normalise vector " + this);
        }
        return scale(1.0 / len);
    }

    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    public double get(int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    @Override
    public String toString() { return "(" + x + ", " + y + ", " + z + ")"; }
}
