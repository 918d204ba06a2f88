package org.beziertracer.math;

/**
 * Immutable axis-aligned bounding box {@code [min, max]}. An empty box has {@code min > max}.
 */
public record Aabb(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {

    public static final Aabb EMPTY = new Aabb(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.NEGATIVE_INFINITY);

    /** Box of the points in a flat {@code x,y,z,x,y,z,...} array. */
    public static Aabb ofPoints(double[] xyz) {
        double[] b = new double[6];
        Bounds.ofPoints(xyz, 0, xyz.length / 3, b);
        return new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]);
    }

    public boolean isEmpty() { return minX > maxX || minY > maxY || minZ > maxZ; }

    public Aabb union(Aabb o) {
        return new Aabb(Math.min(minX, o.minX), Math.min(minY, o.minY), Math.min(minZ, o.minZ),
                Math.max(maxX, o.maxX), Math.max(maxY, o.maxY), Math.max(maxZ, o.maxZ));
    }

    public Aabb union(Vec3 p) {
        return new Aabb(Math.min(minX, p.x()), Math.min(minY, p.y()), Math.min(minZ, p.z()),
                Math.max(maxX, p.x()), Math.max(maxY, p.y()), Math.max(maxZ, p.z()));
    }

    /** True when {@code p} lies inside the box grown by {@code eps} on every side. */
    public boolean contains(double x, double y, double z, double eps) {
        return x >= minX - eps && x <= maxX + eps && y >= minY - eps && y <= maxY + eps
                && z >= minZ - eps && z <= maxZ + eps;
    }

    public Vec3 min() { return new Vec3(minX, minY, minZ); }

    public Vec3 max() { return new Vec3(maxX, maxY, maxZ); }

    public Vec3 center() { return new Vec3(0.5 * (minX + maxX), 0.5 * (minY + maxY), 0.5 * (minZ + maxZ)); }

    /**
     * Length of the diagonal; 0 for an empty box. Without intermediate overflow: infinite only
     * when the length itself is beyond the largest double.
     */
    public double diagonal() {
        if (isEmpty()) {
            return 0;
        }
        return diagonal(maxX - minX, maxY - minY, maxZ - minZ);
    }

    /** The length of a box's diagonal from its sides, as {@link #diagonal()} computes it. */
    public static double diagonal(double dx, double dy, double dz) {
        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return Double.isFinite(d) ? d : Math.hypot(Math.hypot(dx, dy), dz);
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "x[%s,%s] y[%s,%s] z[%s,%s]", fmt(minX), fmt(maxX),
                fmt(minY), fmt(maxY), fmt(minZ), fmt(maxZ));
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
