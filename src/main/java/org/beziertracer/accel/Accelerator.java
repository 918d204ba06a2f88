package org.beziertracer.accel;

import org.beziertracer.math.Aabb;

/**
 * Ray queries over a set of primitive boxes, answered through leaf callbacks.
 *
 * <p>Implementations: {@link Bvh} (binned-SAH hierarchy) and {@link FlatList} (every box tested,
 * for the "sub-patch BVH off" switch and for measuring the speed-up). Both are immutable once
 * built and may be shared by any number of render threads; each thread passes its own stack
 * ({@code int[stackSize()]}, see {@link #newStack()}) and its own per-query state {@code query},
 * which the leaf callback receives with every primitive (the callback itself may be shared).
 *
 * <p>Rays are {@code origin + t * direction}, given as origin and reciprocal direction
 * {@code invD = 1 / d} per axis; zero components ({@code invD = ±Infinity}) are allowed and handled
 * as described in {@link RayBox}. Only {@code t} in {@code [tMin, tMax]} is considered.
 */
public interface Accelerator {

    /**
     * Closest hit: visits primitives whose boxes the ray enters before the current {@code tMax},
     * near boxes first, feeding each callback result back as the new {@code tMax}.
     *
     * @param query per-query state passed to every {@code leaf} call
     * @param stack caller-owned scratch of length {@code >= stackSize()}, overwritten
     * @return the final {@code tMax}; smaller than the argument exactly when the callback reported
     *     a closer hit
     */
    <Q> double closestHit(double ox, double oy, double oz, double invDx, double invDy, double invDz,
            double tMin, double tMax, LeafIntersector<Q> leaf, Q query, int[] stack);

    /**
     * Any hit: true as soon as the callback says a primitive occludes; false when none does.
     *
     * @param query per-query state passed to every {@code leaf} call
     * @param stack caller-owned scratch of length {@code >= stackSize()}, overwritten
     */
    <Q> boolean occluded(double ox, double oy, double oz, double invDx, double invDy, double invDz,
            double tMin, double tMax, LeafOccluder<Q> leaf, Q query, int[] stack);

    /**
     * Traverses once for a whole packet of rays ({@link RayPacket}): lists the leaves any of its
     * rays may meet between {@code tMin} and {@code tMax}, for {@link Bvh#closestHitsIn} and
     * {@link Bvh#occludedAllIn} with rays whose own interval lies within those bounds. Returns false when the
     * packet cannot be traversed together (then trace its rays one at a time); an accelerator
     * without a hierarchy always returns false.
     *
     * @param stack as for {@link #closestHit}
     */
    default boolean gather(RayPacket packet, double tMin, double tMax, int[] stack) {
        return false;
    }

    /** Minimum length of the traversal stack a caller must pass. */
    int stackSize();

    /** A fresh stack of the right size, for one thread's scratch. */
    default int[] newStack() {
        return new int[stackSize()];
    }

    /** Number of hierarchy nodes (0 for {@link FlatList}). */
    int nodeCount();

    /** Number of node levels, root alone = 1 (0 for {@link FlatList}). */
    int depth();

    int primCount();

    /** Heap held by this structure's arrays, in bytes (what it keeps, not what its build used). */
    long bytes();

    /** Wall-clock time spent building (or refitting) this instance, in milliseconds. */
    double buildMillis();

    /** Union of all primitive boxes; {@link Aabb#EMPTY} when there are none. */
    Aabb bounds();

    /**
     * A new accelerator over new boxes for the same primitives (same count, same indices). This
     * instance is left unchanged, so threads still using it are unaffected.
     */
    Accelerator refit(double[] newPrimBounds);
}
