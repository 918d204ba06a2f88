package org.beziertracer.intersect;

import org.beziertracer.accel.BvhOptions;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.Tessellator;
import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;

/**
 * How a scene is intersected.
 *
 * @param method     solver at the BVH leaves (exact mode only)
 * @param bvh        true: sub-patch BVH (pre-split patches, binned-SAH BVH); false: one box per
 *                   whole patch, tested in a flat list, the solver starting on the whole patch
 *                   (in tessellated mode: the triangles tested in a flat list)
 * @param split      pre-split options used when {@code bvh} is on (exact mode only); each method
 *                   has its own default ({@link Method#defaultSplit()}: Newton refines further),
 *                   which {@link #withMethod} follows unless other options were set
 * @param bvhOptions leaf size and bin count of the BVH
 * @param tessellate 0: exact intersection of the Bézier patches; {@code K ≥ 1}: every patch is
 *                   replaced by a uniform {@code K×K} grid of cells, two triangles each
 *                   ({@link Tessellator}), intersected as a triangle mesh with interpolated
 *                   analytic vertex normals (the "fair comparator" of the exact path)
 */
public record IntersectOptions(Method method, boolean bvh, SplitOptions split, BvhOptions bvhOptions,
                               int tessellate, LaneKernel kernel) {

    public IntersectOptions {
        if (tessellate < 0 || tessellate > Tessellator.MAX_SEGMENTS) {
            throw new IllegalArgumentException("tessellate must be 0 (exact) or 1.." + Tessellator.MAX_SEGMENTS
                    + ", got " + tessellate);
        }
        java.util.Objects.requireNonNull(kernel, "kernel");
    }

    /** With the kernel chosen at start ({@link Kernels#best}). */
    public IntersectOptions(Method method, boolean bvh, SplitOptions split, BvhOptions bvhOptions, int tessellate) {
        this(method, bvh, split, bvhOptions, tessellate, Kernels.best());
    }

    /** Exact mode with the default BVH options. */
    public IntersectOptions(Method method, boolean bvh, SplitOptions split) {
        this(method, bvh, split, BvhOptions.defaults(), 0);
    }

    public static IntersectOptions defaults() {
        return new IntersectOptions(Method.CLIPPING, true, SplitOptions.defaults());
    }

    /** Another method; split options that were this method's default become the new method's. */
    public IntersectOptions withMethod(Method m) {
        SplitOptions s = split.equals(method.defaultSplit()) ? m.defaultSplit() : split;
        return new IntersectOptions(m, bvh, s, bvhOptions, tessellate, kernel);
    }

    public IntersectOptions withBvh(boolean on) { return new IntersectOptions(method, on, split, bvhOptions, tessellate, kernel); }

    public IntersectOptions withSplit(SplitOptions s) { return new IntersectOptions(method, bvh, s, bvhOptions, tessellate, kernel); }

    public IntersectOptions withBvhOptions(BvhOptions o) { return new IntersectOptions(method, bvh, split, o, tessellate, kernel); }

    /** 0 = exact; {@code K ≥ 1} = uniform {@code K×K} tessellation per patch. */
    public IntersectOptions withTessellate(int k) { return new IntersectOptions(method, bvh, split, bvhOptions, k, kernel); }

    /** The same options with another SIMD/scalar kernel (the same answers, another speed). */
    public IntersectOptions withKernel(LaneKernel k) { return new IntersectOptions(method, bvh, split, bvhOptions, tessellate, k); }

    /** True in tessellated (triangle mesh) mode. */
    public boolean tessellated() { return tessellate > 0; }

    /** The split options in force: whole patches when the BVH is off. */
    public SplitOptions effectiveSplit() { return bvh ? split : SplitOptions.wholePatches(); }
}
