package org.beziertracer.accel;

/**
 * Any-hit leaf callback for shadow rays: called for primitives in visited leaves until one
 * occludes. Same ownership rules as {@link LeafIntersector}.
 */
@FunctionalInterface
public interface LeafOccluder {

    /** True when primitive {@code prim} blocks the current ray before {@code tMax}. */
    boolean occludes(int prim, double tMax);
}
