package org.beziertracer.accel;

/**
 * Build parameters of {@link Bvh#build}.
 *
 * @param maxLeafSize at most this many primitives per leaf ({@code >= 1}); the SAH may stop earlier
 * @param binCount number of centroid bins per axis for the binned SAH ({@code 2..256}; 12–16 is the
 *     usual choice, see Wald 2007)
 */
public record BvhOptions(int maxLeafSize, int binCount) {

    /** Largest accepted {@link #binCount()}. */
    public static final int MAX_BIN_COUNT = 256;

    public BvhOptions {
        if (maxLeafSize < 1) {
            throw new IllegalArgumentException("maxLeafSize must be >= 1, got " + maxLeafSize);
        }
        if (binCount < 2 || binCount > MAX_BIN_COUNT) {
            throw new IllegalArgumentException(
                    "binCount must be in 2.." + MAX_BIN_COUNT + ", got " + binCount);
        }
    }

    /** Four primitives per leaf at most, sixteen bins. */
    public static BvhOptions defaults() {
        return new BvhOptions(4, 16);
    }
}
