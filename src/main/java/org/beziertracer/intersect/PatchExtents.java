package org.beziertracer.intersect;

/**
 * Control-polygon lengths of a ray-space net (first two coordinates), to choose a split
 * direction: the u-polygons (v-polygons) of the net's first and last rows (columns). Every edge
 * counts, not just the end chords: a row whose ends line up along the ray (the parabolic trough
 * z = (u − ½)² seen along its x axis) still bends in ray space, and measuring only its chord
 * made the subdivision solver halve the other direction forever and miss the surface.
 */
final class PatchExtents {
    private PatchExtents() {}

    /** Sum of the lengths of the u-polygons of the first and last rows. */
    static double rayLengthU(double[] net, int base, int n, int m) {
        return polygon(net, base, n, 3) + polygon(net, base + 3 * (n + 1) * m, n, 3);
    }

    /** Sum of the lengths of the v-polygons of the first and last columns. */
    static double rayLengthV(double[] net, int base, int n, int m) {
        int row = 3 * (n + 1);
        return polygon(net, base, m, row) + polygon(net, base + 3 * n, m, row);
    }

    /** Length of the polygon of {@code edges} edges from {@code net[p]}, points {@code stride} apart. */
    private static double polygon(double[] net, int p, int edges, int stride) {
        double length = 0;
        for (int e = 0; e < edges; e++, p += stride) {
            double x = net[p + stride] - net[p], y = net[p + stride + 1] - net[p + 1];
            length += Math.sqrt(x * x + y * y);
        }
        return length;
    }
}
