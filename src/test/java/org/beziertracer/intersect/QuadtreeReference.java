package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The slow reference of {@link ReferenceIntersector} on a {@code 2^depth × 2^depth} grid of cells,
 * found faster: the grid is reached by halving the patch in u and v with de Casteljau, and a
 * quarter whose control box the ray misses is dropped with all its cells (a cell's control points
 * are convex combinations of its ancestors', so its box lies inside theirs: exactly the cells the
 * flat grid would test are tested). In each such cell, {@link ReferenceIntersector#cellRoot}: the
 * 3×3 world-space Newton iteration from the cell centre. Independent of every solver under test
 * (no ray-space projection, no clipping, no sub-patch table). Not thread-safe; one per thread.
 */
final class QuadtreeReference {

    /** Depth 6: a 64×64 grid, finer than the 48×48 of the flat reference. */
    static final int DEFAULT_DEPTH = 6;

    private final int depth;
    private double[][] nets = new double[0][];
    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
    private final double[] e = new double[9];
    private final double[] tmp = new double[DeCasteljau.MAX_ORDER * DeCasteljau.MAX_ORDER * 3];
    private final double[] ray = new double[6];
    private double tMin, tMax;
    private double[] best;
    private double[] whole;
    private int n, m;

    QuadtreeReference(int depth) {
        this.depth = depth;
    }

    QuadtreeReference() {
        this(DEFAULT_DEPTH);
    }

    /** Nearest root {t, u, v} of the ray with patch {@code p} in (tMin, tMax), or null. */
    double[] nearest(BezierPatch p, double ox, double oy, double oz, double dx, double dy, double dz,
                     double tMin, double tMax) {
        n = p.degreeU();
        m = p.degreeV();
        whole = p.copyNet();
        if (nets.length == 0 || nets[0].length != whole.length) {
            nets = new double[4 * (depth + 1)][whole.length]; // rayMeetsBox reads whole arrays
        }
        ray[0] = ox; ray[1] = oy; ray[2] = oz; ray[3] = dx; ray[4] = dy; ray[5] = dz;
        this.tMin = tMin;
        this.tMax = tMax;
        best = null;
        System.arraycopy(whole, 0, nets[0], 0, whole.length);
        visit(0, 0, 0, 1, 0, 1);
        return best;
    }

    /**
     * Nearest root over every patch of {@code scene}: {t, u, v, patch} or null. Patches whose
     * control box the ray misses are skipped.
     */
    double[] nearest(Scene scene, double ox, double oy, double oz, double dx, double dy, double dz,
                     double tMin, double tMax) {
        double[] found = null;
        for (int k = 0; k < scene.patchCount(); k++) {
            double[] r = nearest(scene.patches().get(k), ox, oy, oz, dx, dy, dz, tMin,
                    found == null ? tMax : found[0]);
            if (r != null) {
                found = new double[] {r[0], r[1], r[2], k};
            }
        }
        return found;
    }

    private void visit(int slot, int level, double u0, double u1, double v0, double v1) {
        double[] net = nets[slot];
        int len = net.length;
        if (!ReferenceIntersector.rayMeetsBox(net, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], tMin,
                best == null ? tMax : best[0])) {
            return;
        }
        if (level == depth) {
            double[] r = ReferenceIntersector.cellRoot(whole, n, m, u0, u1, v0, v1, ray[0], ray[1], ray[2],
                    ray[3], ray[4], ray[5], tMin, tMax, e, scratch);
            if (r != null && (best == null || r[0] < best[0])) {
                best = r;
            }
            return;
        }
        // Quarters: halve in u into tmp/.., then each half in v into the next level's four slots
        int base = 4 * (level + 1);
        double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
        DeCasteljau.splitU(net, 0, n, m, 3, 0.5, tmp, 0, nets[base + 3], 0);
        DeCasteljau.splitV(tmp, 0, n, m, 3, 0.5, nets[base], 0, nets[base + 1], 0);
        System.arraycopy(nets[base + 3], 0, tmp, 0, len);
        DeCasteljau.splitV(tmp, 0, n, m, 3, 0.5, nets[base + 2], 0, nets[base + 3], 0);
        visit(base, level + 1, u0, um, v0, vm);
        visit(base + 1, level + 1, u0, um, vm, v1);
        visit(base + 2, level + 1, um, u1, v0, vm);
        visit(base + 3, level + 1, um, u1, vm, v1);
    }
}
