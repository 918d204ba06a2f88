package org.beziertracer.intersect;

import java.util.Random;

import org.beziertracer.model.BezierPatch;

/** Seeded random test patches. */
final class RandomPatches {
    private RandomPatches() {}

    /**
     * A wavy height field over {@code [-size/2, size/2]²}: a jittered grid in x and y, random
     * heights up to {@code relief·size}. Does not fold over itself seen from above.
     */
    static BezierPatch heightField(Random rnd, int n, int m, double size, double relief) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                net[k] = size * ((double) i / n - 0.5) + 0.1 * size / n * (rnd.nextDouble() - 0.5);
                net[k + 1] = size * ((double) j / m - 0.5) + 0.1 * size / m * (rnd.nextDouble() - 0.5);
                net[k + 2] = relief * size * (rnd.nextDouble() - 0.5);
            }
        }
        return new BezierPatch(n, m, net);
    }

    /** A patch with every control point random in a cube: may fold, twist and self-intersect. */
    static BezierPatch wild(Random rnd, int n, int m, double size) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int k = 0; k < net.length; k++) {
            net[k] = size * (rnd.nextDouble() - 0.5);
        }
        return new BezierPatch(n, m, net);
    }
}
