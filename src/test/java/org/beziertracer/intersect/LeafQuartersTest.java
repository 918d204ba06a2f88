package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CompletableFuture;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link LeafQuarters}: the quarter-by-quarter proof against the slow reference (every leaf
 * clipped, no records) on seeded random patches of degree 1..15 and the teapot, with rays aimed at
 * the leaves from random directions and grazing them; the quarters' enclosures hold their pieces
 * of the patch; quarters made by two threads at once are the quarters one thread makes.
 *
 * <p>Not reached by these rays: two settled quarters that both hold a root (a probe of 800,000
 * shallow rays through degree-4..9 leaves found none: between two roots the ray's plane meets the
 * surface where it is parallel to the ray, and the quarter that holds that point fails its
 * single-root test). {@link LeafQuarters#solve} keeps the nearer root all the same.
 */
class LeafQuartersTest {

    @Test
    void aLeafSettledQuarterByQuarterHasTheReferencesAnswer() {
        Random rnd = new Random(9_2026_12_03L);
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int tried = 0, settled = 0, roots = 0;
        long windings = 0;
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            LeafRays aimer = LeafRays.of(patches);
            SubPatchTable table = aimer.table;
            LeafQuarters quarters = LeafQuarters.of(table);
            boolean above = patches.stream().anyMatch(p -> p.degreeU() + p.degreeV() > 6);
            String model = patches.size() + " patches of degree " + patches.get(0).degreeU() + "x" + patches.get(0).degreeV();
            if (!above) {
                assertNull(quarters, model);
                continue;
            }
            assertNotNull(quarters, model);
            double tol = aimer.tolerance, size = aimer.size;
            TraceContext ctx = new TraceContext();
            for (int s = 0; s < table.count; s++) {
                for (int r = 0; r < 16; r++) {
                    double a = rnd.nextDouble(), b = rnd.nextDouble();
                    if (r % 2 == 0) {
                        aimer.aim(ctx, s, a, b, r % 4 == 2 ? 0.05 * table.diagonal[s] : 0, rnd);
                    } else {
                        graze(ctx, table, s, a, b, r % 4 == 1 ? 0.01 : 0.2, size, e, scratch, rnd);
                    }
                    if (NewtonSolver.start(ctx, aimer.records, NewtonLeafRecords.STRIDE * s, 0, Double.POSITIVE_INFINITY,
                            tol) != NewtonSolver.MAYBE_SEVERAL) {
                        continue; // the leaf's own record settles these rays; quarters are not asked
                    }
                    boolean reference = BezierClipper.intersect(ctx, table, null, s, 0, Double.POSITIVE_INFINITY, tol);
                    double tRef = ctx.rootT;
                    String where = model + ", leaf " + s + ", ray " + r;
                    int outcome = quarters.solve(ctx, table, s, 0, Double.POSITIVE_INFINITY, tol);
                    tried++;
                    if (outcome != LeafQuarters.UNDECIDED) {
                        settled++;
                        assertEquals(reference, outcome == LeafQuarters.ROOT, where);
                        if (reference) {
                            assertEquals(tRef, ctx.rootT, 1e-9 * size, where);
                            roots++;
                        }
                    }
                    windings += ctx.quarterWindings;
                    ctx.quarterWindings = 0;
                    // and through the leaf solver, quarters and all
                    boolean fast = BezierClipper.intersect(ctx, table, aimer.records, null, quarters, null, s, 0,
                            Double.POSITIVE_INFINITY, tol);
                    assertEquals(reference, fast, where);
                    if (fast) {
                        assertEquals(tRef, ctx.rootT, 1e-9 * size, where);
                    }
                }
            }
        }
        // (most asked leaves are the folded nets' and the grazing rays': hard for quarters too)
        assertTrue(settled > 3000 && roots > 0.3 * settled,
                tried + " leaves asked, " + settled + " settled by their quarters, " + roots + " of them with a root");
        // quarters whose Newton attempt failed were settled by their borders' winding on the way
        assertTrue(windings > 500, windings + " quarters' windings asked");
    }

    /** A quarter's border is the border rows and columns of the quarter's net split from the leaf's. */
    @Test
    void aQuartersBorderIsTheBorderOfItsSplitNet() {
        Random rnd = new Random(1203);
        int len = TraceContext.NET_LENGTH;
        double[] split = new double[4 * len], border = new double[6 * LeafQuarters.BORDER];
        for (int trial = 0; trial < 60; trial++) {
            int n = 1 + rnd.nextInt(15), m = 1 + rnd.nextInt(15);
            BezierPatch patch = trial % 2 == 0 ? RandomPatches.heightField(rnd, n, m, 4, 0.5) : RandomPatches.wild(rnd, n, m, 4);
            SubPatchTable table = SubPatchTable.build(List.of(patch), SplitOptions.defaults());
            double size = table.diagonal[0];
            for (int s = 0; s < table.count; s += 1 + table.count / 7) {
                DeCasteljau.splitU(table.nets, table.netOffset[s], n, m, 3, 0.5, split, 0, split, len);
                for (int q = 0; q < 4; q++) {
                    DeCasteljau.splitV(split, (q & 1) * len, n, m, 3, 0.5, split, 2 * len, split, 3 * len);
                    int quarter = (2 + (q >> 1)) * len, row = 3 * (n + 1);
                    LeafQuarters.borders(table, s, q, border);
                    String where = "degree " + n + "x" + m + ", leaf " + s + ", quarter " + q;
                    for (int i = 0; i <= Math.max(n, m); i++) {
                        for (int c = 0; c < 3; c++) {
                            if (i <= n) { // v = v0 and v = v1, along u
                                assertEquals(split[quarter + 3 * i + c], border[3 * i + c], 1e-13 * size, where);
                                assertEquals(split[quarter + m * row + 3 * i + c], border[2 * LeafQuarters.BORDER + 3 * i + c],
                                        1e-13 * size, where);
                            }
                            if (i <= m) { // u = u1 and u = u0, along v
                                assertEquals(split[quarter + i * row + 3 * n + c], border[LeafQuarters.BORDER + 3 * i + c],
                                        1e-13 * size, where);
                                assertEquals(split[quarter + i * row + c], border[3 * LeafQuarters.BORDER + 3 * i + c],
                                        1e-13 * size, where);
                            }
                        }
                    }
                }
            }
        }
    }

    @Test
    void everyQuartersEnclosureHoldsItsPieceOfThePatch() {
        Random rnd = new Random(31);
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < 24; trial++) {
            int n = 4 + rnd.nextInt(12), m = 3 + rnd.nextInt(13);
            BezierPatch patch = trial % 2 == 0 ? RandomPatches.heightField(rnd, n, m, 4, 0.5) : RandomPatches.wild(rnd, n, m, 4);
            SubPatchTable table = SubPatchTable.build(List.of(patch), SplitOptions.defaults());
            LeafQuarters quarters = LeafQuarters.of(table);
            TraceContext ctx = new TraceContext();
            for (int s = 0; s < table.count; s++) {
                quarters.ensure(ctx, table, s);
                for (int q = 0; q < 4; q++) {
                    int o = LeafQuarters.STRIDE * s + NewtonLeafRecords.STRIDE * q;
                    float[] rec = quarters.records;
                    for (int k = 0; k < 6; k++) {
                        double a = rnd.nextDouble(), b = rnd.nextDouble();
                        double u = rec[o + NewtonLeafRecords.U0] + a * rec[o + NewtonLeafRecords.DU];
                        double v = rec[o + NewtonLeafRecords.V0] + b * rec[o + NewtonLeafRecords.DV];
                        DeCasteljau.evaluateWithDerivatives(table.patchNets, 0, n, m, u, v, e, scratch);
                        double sq = 0;
                        for (int c = 0; c < 3; c++) {
                            double d = e[c] - (rec[o + NewtonLeafRecords.C + c] + (a - 0.5) * rec[o + NewtonLeafRecords.A + c]
                                    + (b - 0.5) * rec[o + NewtonLeafRecords.B + c]);
                            sq += d * d;
                        }
                        double reach = rec[o + NewtonLeafRecords.R];
                        assertTrue(Math.sqrt(sq) <= reach * (1 + 1e-9) + 1e-12,
                                "degree " + n + "x" + m + ", leaf " + s + ", quarter " + q + ": " + Math.sqrt(sq) + " > R " + reach);
                    }
                    // the quarters tile the leaf
                    float[] box = table.boxes;
                    assertEquals(box[4 * s] + (q % 2) * 0.5 * (box[4 * s + 1] - box[4 * s]), rec[o + NewtonLeafRecords.U0], 0);
                    assertEquals(box[4 * s + 2] + (q / 2) * 0.5 * (box[4 * s + 3] - box[4 * s + 2]), rec[o + NewtonLeafRecords.V0], 0);
                }
            }
        }
    }

    @Test
    void onlyTablesOfAtMostMostLeavesWithLeavesAboveBicubicGetQuarters() {
        Random rnd = new Random(8);
        assertNull(LeafQuarters.of(SubPatchTable.build(Models.teapot().patches(), SplitOptions.defaults())), "bicubic");
        assertNotNull(LeafQuarters.of(SubPatchTable.build(List.of(RandomPatches.wild(rnd, 4, 3, 4)), SplitOptions.defaults())),
                "degree 4x3");
        List<BezierPatch> many = new ArrayList<>();
        for (int k = 0; k < 160; k++) {
            many.add(RandomPatches.wild(rnd, 4, 4, 4));
        }
        SubPatchTable fine = SubPatchTable.build(many, new SplitOptions(true, 1e-9, 7));
        assertTrue(fine.count > LeafQuarters.MOST_LEAVES, fine.count + " leaves");
        assertNull(LeafQuarters.of(fine), fine.count + " leaves");
    }

    @Test
    void quartersMadeByTwoThreadsAtOnceAreTheQuartersOneThreadMakes() {
        Random rnd = new Random(5);
        BezierPatch patch = RandomPatches.wild(rnd, 9, 9, 4);
        SubPatchTable table = SubPatchTable.build(List.of(patch), SplitOptions.defaults());
        LeafQuarters alone = LeafQuarters.of(table), together = LeafQuarters.of(table);
        TraceContext ctx = new TraceContext();
        for (int s = 0; s < table.count; s++) {
            alone.ensure(ctx, table, s);
        }
        List<CompletableFuture<Void>> both = new ArrayList<>();
        for (int t = 0; t < 2; t++) {
            List<Integer> order = new ArrayList<>();
            for (int s = 0; s < table.count; s++) {
                order.add(s);
            }
            Collections.shuffle(order, new Random(t));
            both.add(CompletableFuture.runAsync(() -> {
                TraceContext own = new TraceContext();
                for (int s : order) {
                    together.ensure(own, table, s);
                }
            }));
        }
        both.forEach(CompletableFuture::join);
        assertTrue(table.count > 50, table.count + " leaves");
        assertArrayEquals(alone.records, together.records);
    }

    /**
     * Sets a ray that grazes leaf {@code s} at its point {@code (a, b)}: along a random tangent
     * direction tilted off the tangent plane by a normal deviate of {@code tilt} (radians, about),
     * from {@code 2·size} away; a tilt of a fifth crosses a wave of the leaf twice now and then.
     */
    private static void graze(TraceContext ctx, SubPatchTable table, int s, double a, double b, double tilt, double size,
                              double[] e,
                              double[] scratch, Random rnd) {
        int k = table.parent[s];
        float[] box = table.boxes;
        double u = box[4 * s] + a * (box[4 * s + 1] - box[4 * s]), v = box[4 * s + 2] + b * (box[4 * s + 3] - box[4 * s + 2]);
        DeCasteljau.evaluateWithDerivatives(table.patchNets, table.patchNetOffset[k], table.patchDegreeU[k],
                table.patchDegreeV[k], u, v, e, scratch);
        double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
        double nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double su = Math.sqrt(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]), sv = Math.sqrt(e[6] * e[6] + e[7] * e[7] + e[8] * e[8]);
        if (!(nl > 0 && su > 0 && sv > 0)) {
            ctx.setRay(e[0] - 2 * size, e[1], e[2], 1, 0, 0);
            return;
        }
        double angle = 2 * Math.PI * rnd.nextDouble(), lift = tilt * rnd.nextGaussian();
        double dx = Math.cos(angle) * e[3] / su + Math.sin(angle) * e[6] / sv + lift * nx / nl;
        double dy = Math.cos(angle) * e[4] / su + Math.sin(angle) * e[7] / sv + lift * ny / nl;
        double dz = Math.cos(angle) * e[5] / su + Math.sin(angle) * e[8] / sv + lift * nz / nl;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        ctx.setRay(e[0] - 2 * size * dx / len, e[1] - 2 * size * dy / len, e[2] - 2 * size * dz / len, dx / len, dy / len,
                dz / len);
    }
}
