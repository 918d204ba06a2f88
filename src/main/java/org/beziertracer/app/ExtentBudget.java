package org.beziertracer.app;

import java.util.function.IntToLongFunction;

/**
 * Chooses which patches get detail (control polygon, iso-curves) when drawing all of them would
 * cost more than a budget: the patches that look biggest on screen come first. Patches are
 * bucketed by the base-2 logarithm of their on-screen extent, and the threshold is the lower edge
 * of the smallest bucket whose patches, together with every bigger one, still fit. When everything
 * fits the threshold is 0: all visible patches. Stateless.
 */
final class ExtentBudget {
    private ExtentBudget() {}

    private static final int BUCKETS = 64;
    /** Bucket {@code b ≥ 1} holds extents in {@code [2^(b − OFFSET), 2^(b + 1 − OFFSET))}; bucket 0 all below. */
    private static final int OFFSET = 20;

    /**
     * The smallest on-screen extent (pixels) a patch needs to be drawn in detail.
     *
     * @param extent per patch, negative for a patch not drawn at all
     * @param cost   cost of patch {@code p} (segments, points)
     * @param budget the most total cost allowed
     * @return 0 when every visible patch fits; {@link Double#POSITIVE_INFINITY} when not even the
     *         biggest bucket fits
     */
    static double threshold(float[] extent, IntToLongFunction cost, long budget) {
        long[] bucketCost = new long[BUCKETS];
        for (int p = 0; p < extent.length; p++) {
            if (extent[p] >= 0) {
                bucketCost[bucket(extent[p])] += cost.applyAsLong(p);
            }
        }
        long total = 0;
        for (int b = BUCKETS - 1; b >= 0; b--) {
            if (total + bucketCost[b] > budget) {
                return total == 0 ? Double.POSITIVE_INFINITY : lowerEdge(b + 1);
            }
            total += bucketCost[b];
        }
        return 0;
    }

    static int bucket(double extent) {
        if (!(extent >= Math.scalb(1.0, 1 - OFFSET))) {
            return 0;
        }
        return Math.min(BUCKETS - 1, Math.getExponent(extent) + OFFSET);
    }

    private static double lowerEdge(int b) {
        return b == 0 ? 0 : Math.scalb(1.0, b - OFFSET);
    }
}
