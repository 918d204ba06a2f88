package org.beziertracer.app;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.Scene;

/**
 * The render snapshot of the newest request, kept from one request to the next: the
 * {@link SceneIntersector}, reused when only the camera, the light or the shading changed, patched
 * when a few patches changed (a dragged point, maybe shared by several patches:
 * {@link SceneIntersector#withPatches} re-splits those patches and refits the BVH once), rebuilt
 * otherwise. Finding what changed compares the patch lists once, by identity (an edit shares the
 * patches it did not touch). Confined to the engine's prep thread.
 */
final class SnapshotCache {

    /** Most changed patches that are re-split into the old snapshot, as a share of all patches (more: rebuild). */
    static final int PATCH_SHARE = 8;

    private SceneIntersector snapshot;

    /** The snapshot for {@code scene} with options {@code io}. */
    SceneIntersector prepare(Scene scene, IntersectOptions io) {
        snapshot = update(snapshot, scene, io);
        return snapshot;
    }

    /** Lets the snapshot go (its model may be big and no longer shown). */
    void release() {
        snapshot = null;
    }

    /** The snapshot for {@code scene}: reused, patched (a few patches changed) or rebuilt. */
    static SceneIntersector update(SceneIntersector old, Scene scene, IntersectOptions io) {
        if (old == null || !old.options().equals(io)) {
            return SceneIntersector.build(scene, io);
        }
        Scene prev = old.scene();
        if (prev == scene) {
            return old;
        }
        if (prev.patchCount() != scene.patchCount() || !sameMeshes(prev, scene) || !prev.planes().equals(scene.planes())
                || !prev.spheres().equals(scene.spheres()) || !prev.lights().equals(scene.lights())
                || !prev.materials().equals(scene.materials()) || !prev.camera().equals(scene.camera())) {
            return SceneIntersector.build(scene, io);
        }
        int limit = Math.max(4, scene.patchCount() / PATCH_SHARE);
        int[] changed = new int[limit];
        int count = 0;
        for (int k = 0; k < scene.patchCount(); k++) {
            if (prev.patchMaterial(k) != scene.patchMaterial(k)) {
                return SceneIntersector.build(scene, io);
            }
            if (prev.patches().get(k) != scene.patches().get(k) && !prev.patches().get(k).equals(scene.patches().get(k))) {
                if (count == limit) {
                    return SceneIntersector.build(scene, io);
                }
                changed[count++] = k;
            }
        }
        return count == 0 ? old : old.withPatches(scene, java.util.Arrays.copyOf(changed, count));
    }

    /** True when both scenes hold the same mesh objects with the same materials (meshes are not edited). */
    private static boolean sameMeshes(Scene a, Scene b) {
        if (a.meshes().size() != b.meshes().size()) {
            return false;
        }
        for (int k = 0; k < a.meshes().size(); k++) {
            if (a.meshes().get(k) != b.meshes().get(k) || a.meshMaterial(k) != b.meshMaterial(k)) {
                return false;
            }
        }
        return true;
    }
}
