package org.beziertracer.accel;

/**
 * Closest-hit leaf callback: called once for each primitive in every leaf the traversal visits.
 *
 * <p>The accelerator only tracks {@code tMax}; the implementation records its own best hit in the
 * per-query state {@code Q} that the caller passes to {@link Accelerator#closestHit} along with
 * the callback (typically a per-thread mutable object holding the current ray). The callback
 * itself can then be an immutable object shared by every thread. Implement it on a long-lived
 * object, not as a capturing lambda per ray, to keep the hot path allocation-free.
 *
 * @param <Q> the per-query state handed back to every call
 */
@FunctionalInterface
public interface LeafIntersector<Q> {

    /**
     * Tests primitive {@code prim} against the current ray of {@code query} on the open interval
     * ending at {@code tMax}.
     *
     * @return the new {@code tMax}: a value {@code < tMax} when a closer hit was found (and recorded
     *     by the implementation in {@code query}), otherwise exactly the {@code tMax} passed in
     */
    double intersect(Q query, int prim, double tMax);
}
