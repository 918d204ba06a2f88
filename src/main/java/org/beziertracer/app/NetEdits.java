package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;

/**
 * The toolbox's whole-net edits, as pure functions from scene to scene (each one undoable edit).
 * Stateless.
 */
public final class NetEdits {
    private NetEdits() {}

    /** Half-range of the random Z offsets on the default-size patch (scene units). */
    public static final double RANDOM_Z_RANGE = 1.0;

    /**
     * Replace with Flat Grid: the patches are replaced by one flat square grid of
     * {@code pointsU × pointsV} control points ({@link Models#flatGrid}); planes, spheres,
     * lights, materials and camera are kept.
     */
    public static Scene resetGrid(Scene scene, int pointsU, int pointsV) {
        return scene.toBuilder().patches(List.of(Models.flatGrid(pointsU, pointsV))).build();
    }

    /**
     * Randomize Control Points: every control point gets a Z offset drawn uniformly from
     * {@code [−R, R]} with a {@link Random} seeded by {@code seed}, where
     * {@code R = }{@value #RANDOM_Z_RANGE} scaled by the model's size relative to the default patch
     * (whose control square is 3 units wide). A single patch first goes back to its flat grid, so
     * the result depends only on the seed and the grid size (the memoir's behaviour); several
     * patches (the teapot) get the offsets added to their current points, one offset per handle:
     * points that coincide ({@link WeldIndex}) move together, so shared borders stay shared.
     */
    public static Scene randomize(Scene scene, long seed) {
        Random random = new Random(seed);
        if (scene.patchCount() == 1) {
            BezierPatch p = scene.patches().get(0);
            double[] net = Models.flatGrid(p.degreeU() + 1, p.degreeV() + 1).copyNet();
            for (int k = 2; k < net.length; k += 3) {
                net[k] += (2 * random.nextDouble() - 1) * RANDOM_Z_RANGE;
            }
            return scene.toBuilder().patches(List.of(NetChange.withNet(p, net))).build();
        }
        double scale = Math.max(1e-9, scene.controlBounds().diagonal() / 4.243) * 0.1;
        WeldIndex welds = WeldIndex.build(scene);
        double[] offset = new double[welds.pointCount()];
        List<BezierPatch> patches = new ArrayList<>(scene.patchCount());
        for (int p = 0, g = 0; p < scene.patchCount(); p++) {
            BezierPatch patch = scene.patches().get(p);
            double[] net = patch.copyNet();
            for (int k = 2; k < net.length; k += 3, g++) {
                int node = welds.node(g);
                offset[g] = node == g ? (2 * random.nextDouble() - 1) * RANDOM_Z_RANGE * scale : offset[node];
                net[k] += offset[g];
            }
            patches.add(NetChange.withNet(patch, net));
        }
        return scene.toBuilder().patches(patches).build();
    }
}
