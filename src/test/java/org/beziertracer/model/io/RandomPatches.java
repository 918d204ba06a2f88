package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;

/** Seeded random patches for round-trip tests: degrees 1..15, awkward doubles included. */
final class RandomPatches {
    private RandomPatches() {}

    static List<BezierPatch> scene(Random random, int patchCount) {
        List<BezierPatch> patches = new ArrayList<>();
        for (int p = 0; p < patchCount; p++) {
            patches.add(patch(random));
        }
        return patches;
    }

    static BezierPatch patch(Random random) {
        int n = 1 + random.nextInt(BezierPatch.MAX_DEGREE);
        int m = 1 + random.nextInt(BezierPatch.MAX_DEGREE);
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int k = 0; k < net.length; k++) {
            net[k] = coordinate(random);
        }
        return new BezierPatch(n, m, net);
    }

    /** Mixes plain, huge, tiny, whole, negative-zero and subnormal values. */
    static double coordinate(Random random) {
        return switch (random.nextInt(8)) {
            case 0 -> random.nextInt(2001) - 1000;
            case 1 -> (random.nextDouble() - 0.5) * 1e300;
            case 2 -> (random.nextDouble() - 0.5) * 1e-300;
            case 3 -> -0.0;
            case 4 -> Double.MIN_VALUE * random.nextInt(100);
            case 5 -> Math.nextUp(random.nextInt(10));
            default -> (random.nextDouble() - 0.5) * 200;
        };
    }
}
