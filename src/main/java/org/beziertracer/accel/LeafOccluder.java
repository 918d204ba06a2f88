package org.beziertracer.accel;

/**
 * Any-hit leaf callback for shadow rays: called for primitives in visited leaves until one
 * occludes. Same ownership rules as {@link LeafIntersector}.
 *
 * @param <Q> the per-query state handed back to every call
 */
@FunctionalInterface
public interface LeafOccluder<Q> {

    /** True when primitive {@code prim} blocks the current ray of {@code query} before {@code tMax}. */
    boolean occludes(Q query, int prim, double tMax);
}
