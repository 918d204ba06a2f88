package org.beziertracer.render;

/**
 * The random numbers of one path: a SplitMix64 stream (G. L. Steele, D. Lea, C. H. Flood, "Fast
 * splittable pseudorandom number generators", OOPSLA 2014) started from a hash of the seed, the
 * pixel and the sample index, so a path's numbers depend on nothing else: the same picture for
 * any thread count, tile size or order of work. Mutable, one per worker; allocation-free.
 */
final class PathRandom {
    private static final long GOLDEN = 0x9E3779B97F4A7C15L;
    private long state;

    /** Starts the stream of sample {@code s} of pixel {@code (x, y)}. */
    void start(long seed, int x, int y, int s) {
        long z = mix(seed ^ 0x5DEECE66DL);
        z = mix(z + GOLDEN * (x + 1L));
        z = mix(z + GOLDEN * (y + 1L));
        state = mix(z + GOLDEN * (s + 1L));
    }

    /** The next uniform double in [0, 1). */
    double next() {
        state += GOLDEN;
        return (mix(state) >>> 11) * 0x1.0p-53;
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
