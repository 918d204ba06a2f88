package org.beziertracer.app;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.Scene;

/**
 * The render snapshot of the newest request, kept from one request to the next: the scene with its
 * light placed, and the {@link SceneIntersector}, reused when only the camera or shading changed,
 * patched when one patch changed (a dragged point: {@link SceneIntersector#withPatch} re-splits that
 * patch and refits the BVH), rebuilt otherwise. Confined to the engine's prep thread.
 */
final class SnapshotCache {

    private Scene edited;
    private LightPlacement light;
    private Scene lit;
    private SceneIntersector snapshot;

    /** The snapshot for {@code scene} lit by {@code placement}, with options {@code io}. */
    SceneIntersector prepare(Scene scene, LightPlacement placement, IntersectOptions io) {
        if (scene != edited || placement != light) {
            lit = placement.apply(scene);
            edited = scene;
            light = placement;
        }
        snapshot = update(snapshot, lit, io);
        return snapshot;
    }

    /** The snapshot for {@code scene}: reused, patched (one patch changed) or rebuilt. */
    static SceneIntersector update(SceneIntersector old, Scene scene, IntersectOptions io) {
        if (old == null || !old.options().equals(io)) {
            return SceneIntersector.build(scene, io);
        }
        Scene prev = old.scene();
        if (prev == scene) {
            return old;
        }
        if (prev.patchCount() != scene.patchCount() || !prev.planes().equals(scene.planes())
                || !prev.spheres().equals(scene.spheres()) || !prev.lights().equals(scene.lights())
                || !prev.materials().equals(scene.materials()) || !prev.camera().equals(scene.camera())) {
            return SceneIntersector.build(scene, io);
        }
        int changed = -1;
        for (int k = 0; k < scene.patchCount(); k++) {
            if (prev.patchMaterial(k) != scene.patchMaterial(k)) {
                return SceneIntersector.build(scene, io);
            }
            if (!prev.patches().get(k).equals(scene.patches().get(k))) {
                if (changed >= 0) {
                    return SceneIntersector.build(scene, io);
                }
                changed = k;
            }
        }
        return changed < 0 ? old : old.withPatch(changed, scene.patches().get(changed));
    }
}
