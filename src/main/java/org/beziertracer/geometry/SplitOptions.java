package org.beziertracer.geometry;

/**
 * How patches are pre-split into sub-patches.
 *
 * @param enabled            false: one sub-patch per whole patch (the "no sub-patch BVH" mode)
 * @param flatnessTolerance  a sub-patch is flat enough when {@link NetMeasures#flatness} is at
 *                           most this fraction of its control-box diagonal
 * @param maxDepth           cap on the number of successive halvings (so at most
 *                           {@code 2^maxDepth} sub-patches per patch)
 */
public record SplitOptions(boolean enabled, double flatnessTolerance, int maxDepth) {

    public SplitOptions {
        if (!(flatnessTolerance > 0) || !Double.isFinite(flatnessTolerance)) {
            throw new IllegalArgumentException("flatness tolerance must be positive, got " + flatnessTolerance);
        }
        if (maxDepth < 0 || maxDepth > 16) {
            throw new IllegalArgumentException("split depth must be 0..16, got " + maxDepth);
        }
    }

    /** Adaptive splitting with the defaults tuned for Bézier clipping (see docs/performance.md). */
    public static SplitOptions defaults() { return new SplitOptions(true, 0.05, 8); }

    /** One sub-patch per patch. */
    public static SplitOptions wholePatches() { return new SplitOptions(false, 1, 0); }
}
