package org.beziertracer.render;

/**
 * The random numbers of one path, by dimension: the {@code d}-th number a path asks for is
 * dimension {@code d} of a low-discrepancy sequence over the pixel's samples, so the first
 * {@code 2^k} samples of a pixel spread each bounce's light sample, BSDF sample and choices evenly
 * instead of clumping as independent random numbers do. A pair ({@link #next2}) is a 2-D point of
 * the Owen-scrambled Sobol sequence ({@link OwenSobol}), a single number its first coordinate;
 * each dimension has its own scramble and shuffle of the sample index, hashed from the seed, the
 * pixel and the dimension ("padding", as pbrt-v4's {@code PaddedSobolSampler}; M. Pharr, W. Jakob,
 * G. Humphreys, <i>Physically Based Rendering</i>, 4th ed., 2023, §8.7), so dimensions and pixels
 * are decorrelated. A path's numbers depend on the seed, the pixel, the sample index and the
 * dimension only: the same picture for any thread count, tile size, pass split or order of work.
 * Mutable, one per worker; allocation-free.
 */
final class PathRandom {
    private int pixelSeed;
    private int index;
    private int dimension;
    private double second;

    /** Starts the numbers of sample {@code s} of pixel {@code (x, y)}. */
    void start(long seed, int x, int y, int s) {
        int h = OwenSobol.hash((int) seed ^ (int) (seed >>> 32), 0x5DEECE66);
        h = OwenSobol.hash(h, x);
        pixelSeed = OwenSobol.hash(h, y);
        index = s;
        dimension = 0;
    }

    /** The next number, in [0, 1): one dimension. */
    double next() {
        int seed = OwenSobol.hash(pixelSeed, dimension++);
        return OwenSobol.sample(index, 0, seed);
    }

    /** The next 2-D point's first coordinate, in [0, 1); {@link #second()} is its other. One dimension. */
    double next2() {
        int seed = OwenSobol.hash(pixelSeed, dimension++), shuffled = OwenSobol.shuffle(index, seed);
        second = OwenSobol.coordinate(shuffled, 1, seed);
        return OwenSobol.coordinate(shuffled, 0, seed);
    }

    /** The second coordinate of the last {@link #next2} point. */
    double second() {
        return second;
    }

    /** Passes over {@code k} dimensions unused, so later numbers keep their dimension. */
    void skip(int k) {
        dimension += k;
    }
}
