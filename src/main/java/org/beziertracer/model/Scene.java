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
    private final List<Plane> planes;
    private final List<Sphere> spheres;

    /** A scene of Bézier patches only (at least one). */
    public Scene(List<BezierPatch> patches) {
        this(patches, List.of(), List.of());
        if (patches.isEmpty()) {
            throw new IllegalArgumentException("a model needs at least one patch");
        }
    }

    /** A scene of patches, planes and spheres; at least one primitive in all. */
    public Scene(List<BezierPatch> patches, List<Plane> planes, List<Sphere> spheres) {
        this.patches = List.copyOf(patches);
        this.planes = List.copyOf(planes);
        this.spheres = List.copyOf(spheres);
        if (this.patches.isEmpty() && this.planes.isEmpty() && this.spheres.isEmpty()) {
            throw new IllegalArgumentException("a scene needs at least one patch, plane or sphere");
        }
    }

    public List<BezierPatch> patches() { return patches; }

    public List<Plane> planes() { return planes; }

    public List<Sphere> spheres() { return spheres; }

    public int patchCount() { return patches.size(); }

    /** A copy of this scene with patch {@code index} replaced. */
    public Scene withPatch(int index, BezierPatch patch) {
        var copy = new java.util.ArrayList<>(patches);
        copy.set(index, patch);
        return new Scene(copy, planes, spheres);
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
