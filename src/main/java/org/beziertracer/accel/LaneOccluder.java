package org.beziertracer.accel;

/**
 * The any-hit leaf callback of a batch query ({@link Bvh#occludedAllIn}): one primitive against
 * several lanes of a batch of shadow rays at once.
 *
 * @param <Q> the per-thread query state that holds the batch's rays
 */
@FunctionalInterface
public interface LaneOccluder<Q> {

    /**
     * Tests primitive {@code prim} against the lanes {@code lanes[0..count)} (ascending lane numbers)
     * of {@code query}'s batch, each on its open interval ending at {@code tMax[lane]}; sets
     * {@code occluded[lane]} for every lane the primitive blocks and leaves the others as they were.
     */
    void occludes(Q query, int prim, int[] lanes, int count, double[] tMax, boolean[] occluded);
}
