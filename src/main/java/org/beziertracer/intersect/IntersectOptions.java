package org.beziertracer.intersect;

import org.beziertracer.geometry.SplitOptions;

/**
 * How a scene is intersected.
 *
 * @param method solver at the BVH leaves
 * @param bvh    true: sub-patch BVH (pre-split patches, binned-SAH BVH); false: one box per whole
 *               patch, tested in a flat list, the solver starting on the whole patch
 * @param split  pre-split options used when {@code bvh} is on
 */
public record IntersectOptions(Method method, boolean bvh, SplitOptions split) {
    public static IntersectOptions defaults() {
        return new IntersectOptions(Method.CLIPPING, true, SplitOptions.defaults());
    }

    public IntersectOptions withMethod(Method m) { return new IntersectOptions(m, bvh, split); }

    public IntersectOptions withBvh(boolean on) { return new IntersectOptions(method, on, split); }

    /** The split options in force: whole patches when the BVH is off. */
    public SplitOptions effectiveSplit() { return bvh ? split : SplitOptions.wholePatches(); }
}
