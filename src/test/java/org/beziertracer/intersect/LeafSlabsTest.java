package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/**
 * {@link LeafSlabs}: a ray through a point of a leaf never misses the leaf's slabs (any direction,
 * grazing ones too, the point anywhere on the leaf), and a leaf whose slabs a ray misses holds no
 * root for it (the reference clipping search of the leaf finds none), on seeded random wavy and
 * folded nets of degree 1..15 and the teapot; and the slabs reject at least a third of the leaves
 * whose record's enclosure such a ray meets while it passes beside them (the work they save).
 */
class LeafSlabsTest {

    @Test
    void aRayThroughALeafMeetsItsSlabsAndALeafWhoseSlabsTheRayMissesHoldsNoRoot() {
        Random rnd = new Random(1986_2026L);
        int through = 0, rejected = 0, enclosedEmpty = 0, enclosedEmptyRejected = 0;
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            SubPatchTable table = SubPatchTable.build(patches, SplitOptions.defaults());
            float[] slabs = LeafSlabs.build(table), records = NewtonLeafRecords.build(table);
            double size = new Scene(patches).controlBounds().diagonal();
            double tolerance = PatchLeaves.RELATIVE_TOLERANCE * size;
            TraceContext ctx = new TraceContext();
            double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
            for (int s = 0; s < table.count; s++) {
                int k = table.parent[s];
                float[] box = table.boxes;
                double du = box[4 * s + 1] - box[4 * s], dv = box[4 * s + 3] - box[4 * s + 2];
                for (int r = 0; r < 8; r++) {
                    // through a point of the leaf (its border included), in any direction
                    double u = box[4 * s] + (r == 0 ? 0 : r == 1 ? 1 : rnd.nextDouble()) * du;
                    double v = box[4 * s + 2] + (r == 0 ? 1 : r == 1 ? 0 : rnd.nextDouble()) * dv;
                    DeCasteljau.evaluateWithDerivatives(table.patchNets, table.patchNetOffset[k], table.patchDegreeU[k],
                            table.patchDegreeV[k], u, v, e, scratch);
                    double[] d = direction(rnd, r % 3 == 0 ? e : null);
                    ctx.setRay(e[0] - 2 * size * d[0], e[1] - 2 * size * d[1], e[2] - 2 * size * d[2], d[0], d[1], d[2]);
                    through++;
                    assertFalse(LeafSlabs.misses(ctx, slabs, s, 0, Double.POSITIVE_INFINITY,
                            BezierClipper.windingMargin(ctx, tolerance)), "leaf " + s + " missed by a ray through ("
                            + u + ", " + v + ")");
                    // beside it: a point of the patch up to a fifth of the leaf's width beyond its border
                    u = Math.min(1, Math.max(0, box[4 * s] + (-0.2 + 1.4 * rnd.nextDouble()) * du));
                    v = Math.min(1, Math.max(0, box[4 * s + 2] + (-0.2 + 1.4 * rnd.nextDouble()) * dv));
                    DeCasteljau.evaluateWithDerivatives(table.patchNets, table.patchNetOffset[k], table.patchDegreeU[k],
                            table.patchDegreeV[k], u, v, e, scratch);
                    d = direction(rnd, r % 2 == 0 ? e : null);
                    ctx.setRay(e[0] - 2 * size * d[0], e[1] - 2 * size * d[1], e[2] - 2 * size * d[2], d[0], d[1], d[2]);
                    ctx.ensurePlanes();
                    boolean miss = LeafSlabs.misses(ctx, slabs, s, 0, Double.POSITIVE_INFINITY,
                            BezierClipper.windingMargin(ctx, tolerance));
                    boolean enclosed = NewtonSolver.start(ctx, records, NewtonLeafRecords.STRIDE * s, 0,
                            Double.POSITIVE_INFINITY, tolerance) != NewtonSolver.MISS;
                    boolean found = BezierClipper.intersect(ctx, table, null, s, 0, Double.POSITIVE_INFINITY, tolerance);
                    assertFalse(miss && found, "leaf " + s + " rejected by its slabs, but has a root at t = "
                            + ctx.rootT + " (" + ctx.rootU + ", " + ctx.rootV + ")");
                    rejected += miss ? 1 : 0;
                    if (enclosed && !found) {
                        enclosedEmpty++;
                        enclosedEmptyRejected += miss ? 1 : 0;
                    }
                }
            }
        }
        assertTrue(through > 5000 && rejected > 0, through + " rays through leaves, " + rejected + " rejected beside");
        assertTrue(enclosedEmptyRejected > enclosedEmpty / 3, enclosedEmptyRejected + " of " + enclosedEmpty
                + " empty leaves whose enclosure the ray meets rejected by their slabs");
    }

    /** A random unit direction; with {@code e} (a point and its derivatives), mostly along its normal, at times grazing. */
    private static double[] direction(Random rnd, double[] e) {
        double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
        if (e != null) {
            double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
            double nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (nl > 0) {
                double spread = rnd.nextBoolean() ? 0.3 : 3;
                dx = nx / nl + spread * dx;
                dy = ny / nl + spread * dy;
                dz = nz / nl + spread * dz;
            }
        }
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return new double[] {dx / len, dy / len, dz / len};
    }
}
