package org.beziertracer.intersect;

/** Control-polygon lengths of a ray-space net (first two coordinates), to choose a split direction. */
final class PatchExtents {
    private PatchExtents() {}

    /** Sum of the u-edge lengths of the rows' end chords. */
    static double rayLengthU(double[] net, int base, int n, int m) {
        int row = 3 * (n + 1);
        double a = chord(net, base, base + 3 * n), b = chord(net, base + row * m, base + row * m + 3 * n);
        return a + b;
    }

    static double rayLengthV(double[] net, int base, int n, int m) {
        int row = 3 * (n + 1);
        double a = chord(net, base, base + row * m), b = chord(net, base + 3 * n, base + row * m + 3 * n);
        return a + b;
    }

    private static double chord(double[] net, int p, int q) {
        double x = net[q] - net[p], y = net[q + 1] - net[p + 1];
        return Math.sqrt(x * x + y * y);
    }
}
