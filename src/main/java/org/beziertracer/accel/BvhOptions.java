package org.beziertracer.accel;

/**
 * Build parameters of {@link Bvh#build}.
 *
 * @param maxLeafSize at most this many primitives per leaf ({@code >= 1}); the SAH may stop earlier
 * @param binCount number of centroid bins per axis for the binned SAH ({@code 2..256}; 12–16 is the
 *     usual choice, see Wald 2007)
 * @param mortonPrims builds over at least this many primitives use the Morton-ordered builder
 *     ({@link MortonBuilder}) instead of the binned SAH ({@code >= 1}; {@link Integer#MAX_VALUE}:
 *     never)
 */
public record BvhOptions(int maxLeafSize, int binCount, int mortonPrims) {

    /** Largest accepted {@link #binCount()}. */
    public static final int MAX_BIN_COUNT = 256;

    /** Default {@link #mortonPrims()}: the binned SAH up to this size (see docs/performance-journal.md). */
    public static final int MORTON_PRIMS = 1 << 18;

    /**
     * Builds over at least this many primitives in groups of four or more on average (a big
     * scene's patches, split into sub-patches) use the two-level {@link Bvh#build(double[], int,
     * int[], BvhOptions)}; below it the one tree over all primitives is built fast enough and
     * traces a little faster (docs/performance-journal.md, "Fifth pass").
     */
    public static final int GROUPED_PRIMS = 1 << 16;

    /** Whether {@code primCount} primitives in {@code groupCount} groups are built in two levels ({@link #GROUPED_PRIMS}). */
    public static boolean groupsPay(int primCount, int groupCount) {
        return primCount >= GROUPED_PRIMS && groupCount >= 1 && 4L * groupCount <= primCount;
    }

    public BvhOptions {
        if (maxLeafSize < 1) {
            throw new IllegalArgumentException("maxLeafSize must be >= 1, got " + maxLeafSize);
        }
        if (binCount < 2 || binCount > MAX_BIN_COUNT) {
            throw new IllegalArgumentException(
                    "binCount must be in 2.." + MAX_BIN_COUNT + ", got " + binCount);
        }
        if (mortonPrims < 1) {
            throw new IllegalArgumentException("mortonPrims must be >= 1, got " + mortonPrims);
        }
    }

    /** These leaf and bin settings, with the default {@link #mortonPrims()}. */
    public BvhOptions(int maxLeafSize, int binCount) {
        this(maxLeafSize, binCount, MORTON_PRIMS);
    }

    /** Four primitives per leaf at most, sixteen bins, Morton order from {@value #MORTON_PRIMS} primitives. */
    public static BvhOptions defaults() {
        return new BvhOptions(4, 16);
    }

    /** These options with another {@link #mortonPrims()}. */
    public BvhOptions withMortonPrims(int prims) {
        return new BvhOptions(maxLeafSize, binCount, prims);
    }
}
