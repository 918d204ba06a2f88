package org.beziertracer.math;

/**
 * Allocation-free box helpers on flat arrays. A box is six doubles
 * {@code minX, minY, minZ, maxX, maxY, maxZ}.
 */
public final class Bounds {
    private Bounds() {}

    /**
     * Writes the box of {@code count} points stored as {@code x,y,z} triples from
     * {@code xyz[offset]} into {@code dest[0..5]}.
     */
    public static void ofPoints(double[] xyz, int offset, int count, double[] dest) {
        ofPoints(xyz, offset, count, dest, 0);
    }

    /** As {@link #ofPoints(double[], int, int, double[])}, into {@code dest[d..d+5]}. */
    public static void ofPoints(double[] xyz, int offset, int count, double[] dest, int d) {
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX;
        double maxX = Double.NEGATIVE_INFINITY, maxY = maxX, maxZ = maxX;
        for (int k = 0, p = offset; k < count; k++, p += 3) {
            double x = xyz[p], y = xyz[p + 1], z = xyz[p + 2];
            if (x < minX) minX = x;
            if (x > maxX) maxX = x;
            if (y < minY) minY = y;
            if (y > maxY) maxY = y;
            if (z < minZ) minZ = z;
            if (z > maxZ) maxZ = z;
        }
        dest[d] = minX; dest[d + 1] = minY; dest[d + 2] = minZ;
        dest[d + 3] = maxX; dest[d + 4] = maxY; dest[d + 5] = maxZ;
    }
}
