package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link LeafQuadratics}, the quadratic model's start for Newton on leaves above bicubic, against
 * the slow reference on seeded random patches of degree 1..15 and on the teapot: the same answers
 * as the search of every leaf without records, and a start nearer the root than the enclosure's
 * parallelogram gives.
 */
class LeafQuadraticsTest {

    @Test
    void theModelsStartChangesNoAnswer() {
        Random rnd = new Random(9_2026_12_03L);
        int rays = 0, hits = 0, modelled = 0;
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            LeafRays aimer = LeafRays.of(patches);
            SubPatchTable table = aimer.table;
            float[] records = aimer.records;
            float[] quadratics = LeafQuadratics.build(table);
            double size = aimer.size, tolerance = aimer.tolerance;
            TraceContext ctx = new TraceContext();
            for (int s = 0; s < table.count; s++) {
                int k = table.parent[s];
                for (int r = 0; r < 12; r++) {
                    // a point of the leaf (borders included), and a ray to it from a random direction;
                    // every third ray shifted off the surface by up to a tenth of the leaf: it may miss
                    double a = r < 4 ? r % 2 : rnd.nextDouble(), b = r < 4 ? r / 2 : rnd.nextDouble();
                    aimer.aim(ctx, s, a, b, r % 3 == 2 ? 0.1 * table.diagonal[s] : 0, rnd);
                    boolean reference = BezierClipper.intersect(ctx, table, null, s, 0, Double.POSITIVE_INFINITY, tolerance);
                    double tRef = ctx.rootT;
                    boolean fast = BezierClipper.intersect(ctx, table, records, quadratics, s, 0, Double.POSITIVE_INFINITY,
                            tolerance);
                    String where = "degree " + table.patchDegreeU[k] + "x" + table.patchDegreeV[k] + ", leaf " + s
                            + " of " + table.count + ", ray " + r;
                    assertEquals(reference, fast, where);
                    if (fast) {
                        assertEquals(tRef, ctx.rootT, 1e-9 * size, where);
                        hits++;
                    }
                    if (quadratics != null && !Float.isNaN(quadratics[LeafQuadratics.STRIDE * s])) {
                        modelled++;
                    }
                    rays++;
                }
            }
        }
        assertTrue(hits > 0.5 * rays && modelled > 0.3 * rays, rays + " rays: " + hits + " hits, " + modelled
                + " on leaves with a model");
    }

    @Test
    void theModelsStartIsNearerTheRootThanTheParallelograms() {
        Random rnd = new Random(9_2026_12_04L);
        for (int degree : new int[] {4, 5, 9, 12}) {
            BezierPatch patch = RandomPatches.heightField(rnd, degree, degree, 4, 0.3);
            SubPatchTable table = SubPatchTable.build(List.of(patch), SplitOptions.defaults());
            float[] records = NewtonLeafRecords.build(table);
            float[] quadratics = LeafQuadratics.build(table);
            assertNotNull(quadratics, "degree " + degree);
            double size = new Scene(List.of(patch)).controlBounds().diagonal();
            TraceContext ctx = new TraceContext();
            double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
            int n = 0, nearer = 0;
            double[] ratios = new double[8 * table.count];
            for (int s = 0; s < table.count; s++) {
                float[] box = table.boxes;
                for (int r = 0; r < 8; r++) {
                    double a = 0.1 + 0.8 * rnd.nextDouble(), b = 0.1 + 0.8 * rnd.nextDouble();
                    double u = box[4 * s] + a * (box[4 * s + 1] - box[4 * s]);
                    double v = box[4 * s + 2] + b * (box[4 * s + 3] - box[4 * s + 2]);
                    DeCasteljau.evaluateWithDerivatives(table.patchNets, 0, degree, degree, u, v, e, scratch);
                    // from above, tilted by up to about 45 degrees
                    double dx = 0.5 * rnd.nextGaussian(), dy = 0.5 * rnd.nextGaussian(), dz = -1;
                    double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                    ctx.setRay(e[0] - 2 * size * dx / len, e[1] - 2 * size * dy / len, e[2] - 2 * size * dz / len,
                            dx / len, dy / len, dz / len);
                    if (NewtonSolver.start(ctx, records, NewtonLeafRecords.STRIDE * s, 0, Double.POSITIVE_INFINITY,
                            PatchLeaves.RELATIVE_TOLERANCE * size) == NewtonSolver.MISS) {
                        continue; // (cannot happen for a point of the leaf; counted below if it did)
                    }
                    double parallelogram = Math.hypot(ctx.clip[0] - a, ctx.clip[1] - b);
                    if (!LeafQuadratics.start(ctx, quadratics, s)) {
                        continue;
                    }
                    double model = Math.hypot(ctx.clip[0] - a, ctx.clip[1] - b);
                    ratios[n++] = model / Math.max(parallelogram, 1e-300);
                    if (model < parallelogram) {
                        nearer++;
                    }
                }
            }
            Arrays.sort(ratios, 0, n);
            double median = ratios[n / 2];
            String what = "degree " + degree + ": " + n + " starts of " + 8 * table.count + " rays, " + nearer
                    + " nearer, median ratio " + median;
            assertTrue(n > 0.9 * 8 * table.count, what);
            assertTrue(nearer > 0.9 * n && median < 0.1, what);
        }
    }

    @Test
    void onlyLeavesOfPolynomialPatchesAboveBicubicGetAModel() {
        assertTrue(LeafQuadratics.build(SubPatchTable.build(Models.teapot().patches(), SplitOptions.defaults())) == null,
                "the teapot is all bicubic: no models");
        Random rnd = new Random(5);
        BezierPatch cubic = RandomPatches.heightField(rnd, 3, 3, 4, 0.5);
        BezierPatch quartic = RandomPatches.heightField(rnd, 4, 3, 4, 0.5);
        SubPatchTable table = SubPatchTable.build(List.of(cubic, quartic), SplitOptions.defaults());
        float[] quadratics = LeafQuadratics.build(table);
        assertNotNull(quadratics);
        for (int s = 0; s < table.count; s++) {
            boolean model = !Float.isNaN(quadratics[LeafQuadratics.STRIDE * s]);
            assertEquals(table.parent[s] == 1, model, "leaf " + s + " of patch " + table.parent[s]);
        }
    }
}
