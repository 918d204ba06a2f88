package org.beziertracer.intersect;

import org.beziertracer.model.Scene;

/**
 * The kinds of primitive that share one BVH ({@link MixedLeaves}), in the order of their ranges:
 * each constant makes its kind's {@link Leaves} for a scene (null when the scene has none) and
 * names the {@link Hit#kind} its hits record. A new kind of primitive is one {@link Leaves} class
 * and one constant here; the composite, the queries and the batch path derive the rest.
 */
enum LeafKind {
    /** The patches: sub-patches solved by the options' {@link Method}, or the tessellated mode's triangles. */
    PATCHES(Hit.PATCH, (scene, options, size) -> scene.patches().isEmpty() ? null
            : Leaves.patchLeaves(scene, options, size)),
    /** The triangles of the scene's meshes ({@link MeshLeaves}). */
    TRIANGLES(Hit.TRIANGLE, (scene, options, size) -> MeshLeaves.build(scene)),
    /** The scene's spheres ({@link SphereLeaves}); planes are unbounded and stay outside the BVH. */
    SPHERES(Hit.SPHERE, (scene, options, size) -> SphereLeaves.build(scene));

    /** Makes a kind's leaves; null when the scene has none of it. */
    @FunctionalInterface
    interface Factory {
        Leaves build(Scene scene, IntersectOptions options, double sceneSize);
    }

    /** The {@link Hit#kind} of this kind's hits. */
    final int hitKind;
    final Factory factory;

    LeafKind(int hitKind, Factory factory) {
        this.hitKind = hitKind;
        this.factory = factory;
    }
}
