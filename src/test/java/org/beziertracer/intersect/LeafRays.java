package org.beziertracer.intersect;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Patches split into leaves with their records, and rays aimed at points of those leaves: the
 * set-up of the seeded tests of the leaf solvers' shortcuts.
 */
final class LeafRays {
    final SubPatchTable table;
    final float[] records;
    /** Diagonal of the patches' control box, and the leaves' tolerance for it. */
    final double size, tolerance;
    private final double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];

    private LeafRays(List<BezierPatch> patches) {
        table = SubPatchTable.build(patches, SplitOptions.defaults());
        records = NewtonLeafRecords.build(table);
        size = new Scene(patches).controlBounds().diagonal();
        tolerance = PatchLeaves.RELATIVE_TOLERANCE * size;
    }

    /** The default split of {@code patches}, its records and tolerance. */
    static LeafRays of(List<BezierPatch> patches) {
        return new LeafRays(patches);
    }

    /**
     * Sets {@code ctx}'s ray: aimed, from a random direction and {@code 2·size} away, at the point
     * of leaf {@code s} at leaf parameters {@code (a, b)}; when {@code shiftSigma > 0} its origin
     * is moved along x by a normal deviate of that size (the ray may then miss).
     */
    void aim(TraceContext ctx, int s, double a, double b, double shiftSigma, Random rnd) {
        int k = table.parent[s];
        float[] box = table.boxes;
        double u = box[4 * s] + a * (box[4 * s + 1] - box[4 * s]);
        double v = box[4 * s + 2] + b * (box[4 * s + 3] - box[4 * s + 2]);
        DeCasteljau.evaluateWithDerivatives(table.patchNets, table.patchNetOffset[k], table.patchDegreeU[k],
                table.patchDegreeV[k], u, v, e, scratch);
        double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double shift = shiftSigma > 0 ? shiftSigma * rnd.nextGaussian() : 0;
        ctx.setRay(e[0] - 2 * size * dx / len + shift, e[1] - 2 * size * dy / len, e[2] - 2 * size * dz / len,
                dx / len, dy / len, dz / len);
    }
}
