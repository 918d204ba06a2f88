package org.beziertracer.model.io;

import org.beziertracer.math.Aabb;
import org.beziertracer.model.Scene;

/**
 * Refuses a scene whose size cannot be represented: control points so far apart that the width
 * of their box, or its diagonal, overflows a {@code double}. Every later step (framing, ray-space
 * tolerances, BVH boxes) measures the scene by that diagonal, so such a file would render wrong in
 * silence. Stateless.
 */
final class Extents {
    private Extents() {}

    /** @throws IllegalArgumentException naming the box, when its size overflows */
    static void requireFinite(Scene scene) {
        if (scene.patches().isEmpty() && scene.meshes().isEmpty()) {
            return;
        }
        Aabb b = scene.bounds();
        if (!Double.isFinite(b.diagonal())) {
            throw new IllegalArgumentException("the control points span x[" + NumberText.show(b.minX()) + ","
                    + NumberText.show(b.maxX()) + "] y[" + NumberText.show(b.minY()) + "," + NumberText.show(b.maxY())
                    + "] z[" + NumberText.show(b.minZ()) + "," + NumberText.show(b.maxZ())
                    + "], a size that overflows (" + NumberText.BEYOND + ")");
        }
    }
}
