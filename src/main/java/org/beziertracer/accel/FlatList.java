package org.beziertracer.accel;

import static org.beziertracer.accel.RayBox.MISS;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.HeapBytes;

/**
 * The "no hierarchy" accelerator: every query slab-tests every primitive box in index order and
 * calls back for those the ray enters before the current {@code tMax}. Used when the sub-patch BVH
 * is switched off, to measure what the {@link Bvh} buys, and as a reference in tests.
 *
 * <p>Layout: the boxes rounded outward to floats (as in {@link Bvh}), six per primitive. Immutable and shareable
 * between threads like {@link Bvh}; needs no stack ({@link #stackSize()} is 0, any array, even
 * {@code null}, may be passed).
 */
public final class FlatList implements Accelerator {

    private final float[] primBounds;
    private final int primCount;
    private final double buildMillis;

    private FlatList(float[] primBounds, int primCount, double buildMillis) {
        this.primBounds = primBounds;
        this.primCount = primCount;
        this.buildMillis = buildMillis;
    }

    /**
     * Copies {@code 6 * primCount} box values, rounded outward to floats.
     *
     * @throws IllegalArgumentException for a short array or a non-finite or inverted box
     */
    public static FlatList build(double[] primBounds, int primCount) {
        long start = System.nanoTime();
        Bvh.checkBounds(primBounds, primCount);
        float[] copy = new float[6 * primCount];
        for (int p = 0; p < primCount; p++) {
            RayBox.roundOutward(primBounds, 6 * p, copy, 6 * p);
        }
        return new FlatList(copy, primCount, (System.nanoTime() - start) * 1e-6);
    }

    @Override
    public <Q> double closestHit(double ox, double oy, double oz, double invDx, double invDy,
            double invDz, double tMin, double tMax, LeafIntersector<Q> leaf, Q query, int[] stack) {
        final int sx = RayBox.nearOffset(invDx), sy = RayBox.nearOffset(invDy),
                sz = RayBox.nearOffset(invDz);
        for (int p = 0; p < primCount; p++) {
            if (RayBox.slab(primBounds, 6 * p, ox, oy, oz, invDx, invDy, invDz, sx, sy, sz,
                    tMin, tMax) != MISS) {
                tMax = leaf.intersect(query, p, tMax);
            }
        }
        return tMax;
    }

    @Override
    public <Q> boolean occluded(double ox, double oy, double oz, double invDx, double invDy,
            double invDz, double tMin, double tMax, LeafOccluder<Q> leaf, Q query, int[] stack) {
        final int sx = RayBox.nearOffset(invDx), sy = RayBox.nearOffset(invDy),
                sz = RayBox.nearOffset(invDz);
        for (int p = 0; p < primCount; p++) {
            if (RayBox.slab(primBounds, 6 * p, ox, oy, oz, invDx, invDy, invDz, sx, sy, sz,
                    tMin, tMax) != MISS && leaf.occludes(query, p, tMax)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public int stackSize() {
        return 0;
    }

    @Override
    public int nodeCount() {
        return 0;
    }

    @Override
    public int depth() {
        return 0;
    }

    @Override
    public int primCount() {
        return primCount;
    }

    @Override
    public long bytes() {
        return HeapBytes.of(primBounds);
    }

    @Override
    public double buildMillis() {
        return buildMillis;
    }

    @Override
    public Aabb bounds() {
        if (primCount == 0) {
            return Aabb.EMPTY;
        }
        float[] box = new float[6];
        BvhBuild.setEmpty(box, 0);
        for (int p = 0; p < primCount; p++) {
            BvhBuild.grow(box, 0, primBounds, 6 * p);
        }
        return new Aabb(box[0], box[1], box[2], box[3], box[4], box[5]);
    }

    @Override
    public FlatList refit(double[] newPrimBounds) {
        if (newPrimBounds.length < 6 * (long) primCount) {
            throw new IllegalArgumentException("need 6 doubles for each of " + primCount
                    + " primitives, got an array of " + newPrimBounds.length);
        }
        return build(newPrimBounds, primCount);
    }

    @Override
    public String toString() {
        return "FlatList[prims=" + primCount + "]";
    }
}
