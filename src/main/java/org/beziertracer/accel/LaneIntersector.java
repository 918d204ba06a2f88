package org.beziertracer.accel;

/**
 * The leaf callback of a batch query ({@link Bvh#closestHitsIn}): one primitive against several
 * lanes of a ray batch at once, so that a leaf can solve them together (the same stages, the
 * evaluations of all lanes in SIMD registers).
 *
 * @param <Q> the per-thread query state that holds the batch's rays and results
 */
@FunctionalInterface
public interface LaneIntersector<Q> {

    /**
     * Tests primitive {@code prim} against the lanes {@code lanes[0..count)} (ascending lane
     * numbers) of {@code query}'s batch, each on its open interval ending at {@code tMax[lane]};
     * lowers {@code tMax[lane]} to the hit's t for every lane that hits closer (and records that hit
     * in {@code query}), and leaves the other lanes' {@code tMax} exactly as they were.
     */
    void intersect(Q query, int prim, int[] lanes, int count, double[] tMax);
}
