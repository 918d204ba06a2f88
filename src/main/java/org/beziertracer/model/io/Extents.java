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

    /**
     * The widest box (diagonal) a scene may span: framing it puts the camera a few diagonals away
     * ({@code render.Camera.fit}), which must stay a finite number; intersection is tested up to 1e200.
     */
    static final double MAX_SIZE = 1e300;

    /** @throws IllegalArgumentException naming the box, when its size overflows */
    static void requireFinite(Scene scene) {
        if (scene.patches().isEmpty() && scene.meshes().isEmpty()) {
            return;
        }
        Aabb b = scene.bounds();
        String span = "the control points span x[" + NumberText.show(b.minX()) + ","
                + NumberText.show(b.maxX()) + "] y[" + NumberText.show(b.minY()) + "," + NumberText.show(b.maxY())
                + "] z[" + NumberText.show(b.minZ()) + "," + NumberText.show(b.maxZ()) + "]";
        if (!Double.isFinite(b.diagonal())) {
            throw new IllegalArgumentException(span + ", a size that overflows (" + NumberText.BEYOND + ")");
        }
        if (b.diagonal() > MAX_SIZE) {
            throw new IllegalArgumentException(span + ", wider than " + NumberText.show(MAX_SIZE)
                    + ": a camera framing it would stand beyond the largest number");
        }
    }
}
