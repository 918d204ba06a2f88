package org.beziertracer.model;

import java.util.List;

import org.beziertracer.math.Aabb;

/**
 * An immutable scene: Bézier patches (each with a material index), plus — as later parts of the
 * renderer need them — analytic planes and spheres, materials, lights, a camera and settings.
 *
 * <p>All lists are copied and unmodifiable, so a {@code Scene} is a snapshot that render threads
 * may share. An edit builds a new {@code Scene}.
 */
public final class Scene {

    private final List<BezierPatch> patches;

    public Scene(List<BezierPatch> patches) {
        if (patches == null || patches.isEmpty()) {
            throw new IllegalArgumentException("a scene needs at least one patch");
        }
        this.patches = List.copyOf(patches);
    }

    public List<BezierPatch> patches() { return patches; }

    public int patchCount() { return patches.size(); }

    /** A copy of this scene with patch {@code index} replaced. */
    public Scene withPatch(int index, BezierPatch patch) {
        var copy = new java.util.ArrayList<>(patches);
        copy.set(index, patch);
        return new Scene(copy);
    }

    /** Union of the control-point boxes of every patch. */
    public Aabb controlBounds() {
        Aabb box = Aabb.EMPTY;
        for (BezierPatch p : patches) {
            box = box.union(p.controlBounds());
        }
        return box;
    }
}
