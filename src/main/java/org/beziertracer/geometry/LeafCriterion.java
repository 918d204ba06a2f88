package org.beziertracer.geometry;

/**
 * An extra test a sub-patch must pass, besides flatness, before the pre-split keeps it as a
 * leaf ({@link PatchSplitter}); a sub-patch that fails is halved again, up to
 * {@link SplitOptions#maxDepth()}. Lets a solver refine the leaves by its own needs (Newton's:
 * "converges from the leaf's start") without the geometry layer knowing the solver.
 *
 * <p>Implementations must be stateless (or thread-safe): large scenes are split in parallel.
 */
@FunctionalInterface
public interface LeafCriterion {

    /** Accepts every sub-patch (flatness alone decides). */
    LeafCriterion NONE = (net, n, m, size, depth) -> true;

    /**
     * True when the degree {@code n}×{@code m} sub-patch whose control net is {@code net[0..]}
     * (layout of {@link DeCasteljau}) may be a leaf; {@code size} is its control-box diagonal,
     * {@code depth} the number of halvings that made it.
     */
    boolean accepts(double[] net, int n, int m, double size, int depth);
}
