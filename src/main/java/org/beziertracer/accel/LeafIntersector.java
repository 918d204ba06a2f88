package org.beziertracer.accel;

/**
 * Closest-hit leaf callback: called once for each primitive in every leaf the traversal visits.
 *
 * <p>The implementation owns the current ray (typically a per-thread mutable object set up before
 * the query) and records its own best hit; the accelerator only tracks {@code tMax}. Implement it
 * on a long-lived object, not as a capturing lambda per ray, to keep the hot path allocation-free.
 */
@FunctionalInterface
public interface LeafIntersector {

    /**
     * Tests primitive {@code prim} against the current ray on the open interval ending at
     * {@code tMax}.
     *
     * @return the new {@code tMax}: a value {@code < tMax} when a closer hit was found (and recorded
     *     by the implementation), otherwise exactly the {@code tMax} passed in
     */
    double intersect(int prim, double tMax);
}
