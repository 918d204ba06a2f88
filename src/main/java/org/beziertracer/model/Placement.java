package org.beziertracer.model;

/**
 * An affine map of model space into scene space, applied to control points: a Bézier patch
 * (rational too) is an affine combination of its control points, so mapping its net maps the
 * surface exactly. The scene file's {@code transform} is one.
 */
public interface Placement {

    /** Maps {@code count} points {@code (x, y, z)} of {@code xyz}, from {@code offset}, in place. */
    void mapPoints(double[] xyz, int offset, int count);

    /**
     * True when the map is a similarity: every distance is multiplied by one factor (rotations,
     * reflections, a uniform scale, a translation). Angles and ratios of lengths are kept, so a
     * split of the model is a split of its image by the same measures.
     */
    boolean similarity();
}
