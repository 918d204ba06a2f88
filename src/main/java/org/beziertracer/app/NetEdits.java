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
     * Reset Control Points: the patches are replaced by one flat square grid of
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
     * patches (the teapot) get the offsets added to their current points.
     */
    public static Scene randomize(Scene scene, long seed) {
        Random random = new Random(seed);
        List<BezierPatch> patches = new ArrayList<>();
        double scale = scene.patchCount() == 1 ? 1 : Math.max(1e-9, scene.controlBounds().diagonal() / 4.243) * 0.1;
        for (BezierPatch p : scene.patches()) {
            BezierPatch base = scene.patchCount() == 1 ? Models.flatGrid(p.degreeU() + 1, p.degreeV() + 1) : p;
            double[] net = base.copyNet();
            for (int k = 2; k < net.length; k += 3) {
                net[k] += (2 * random.nextDouble() - 1) * RANDOM_Z_RANGE * scale;
            }
            patches.add(new BezierPatch(p.degreeU(), p.degreeV(), net));
        }
        return scene.toBuilder().patches(patches).build();
    }

    /** The scene with control point {@code ref} moved to {@code (x, y, z)}. */
    public static Scene movePoint(Scene scene, PointRef ref, double x, double y, double z) {
        BezierPatch p = scene.patches().get(ref.patch());
        return scene.withPatch(ref.patch(), p.withPoint(ref.i(), ref.j(), x, y, z));
    }

    /**
     * The scene with every point of {@code selection} moved by {@code (dx, dy, dz)}: one new patch
     * per touched patch, the others shared.
     */
    public static Scene moveBy(Scene scene, Selection selection, double dx, double dy, double dz) {
        List<BezierPatch> patches = null;
        var groups = selection.byPatch();
        for (List<PointRef> group : groups) {
            int k = group.get(0).patch();
            BezierPatch p = scene.patches().get(k);
            double[] net = p.copyNet();
            for (PointRef r : group) {
                net[p.index(r.i(), r.j(), 0)] += dx;
                net[p.index(r.i(), r.j(), 1)] += dy;
                net[p.index(r.i(), r.j(), 2)] += dz;
            }
            BezierPatch moved = new BezierPatch(p.degreeU(), p.degreeV(), net);
            if (groups.size() == 1) {
                return scene.withPatch(k, moved);
            }
            if (patches == null) {
                patches = new ArrayList<>(scene.patches());
            }
            patches.set(k, moved);
        }
        return patches == null ? scene : scene.toBuilder().patches(patches).build();
    }
}
