package org.beziertracer.intersect;

import org.beziertracer.model.Scene;

/**
 * Leaves of a kind that an edit of patches does not touch (mesh triangles, spheres): an edited
 * snapshot keeps this very object ({@link MixedLeaves#withPatches} remakes the patch part only).
 */
interface FixedLeaves extends Leaves {

    @Override
    default Leaves withPatch(Scene edited, int index, double sceneSize) { return this; }

    @Override
    default Leaves withPatches(Scene edited, int[] indices, double sceneSize, boolean keepSplit) { return this; }

    @Override
    default boolean keepsUntouchedLeaves(Leaves before) { return before == this; }
}
