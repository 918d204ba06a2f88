package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/**
 * The two shortcuts of the clipping leaves (issue 9), each against the slow reference on seeded
 * random patches of degree 1..15 and on the teapot, rays aimed at points of every leaf up to and
 * on its borders (so along every border two teapot patches share) and rays through the leaves'
 * boxes that may miss:
 * <ul>
 *   <li>the leaf records' enclosure rejects a leaf before any evaluation
 *       ({@link BezierClipper#intersect} with {@link NewtonLeafRecords}): the same answer as the
 *       search of every leaf without records, hit for hit;</li>
 *   <li>Newton's last step taken without an evaluation when the patch's second-derivative bound
 *       makes it exact ({@link RayPatchNewton#extrapolate}): the root is the aimed point, and the
 *       evaluation kept for the hit is within that bound of a fresh one.</li>
 * </ul>
 */
class ClippingShortcutsTest {

    @Test
    void theEnclosureRejectsOnlyLeavesWithoutARootAndTheAnswersAreTheReferencesOwn() {
        Random rnd = new Random(9_2026_12_02L);
        int rays = 0, hits = 0, rejected = 0;
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            LeafRays aimer = LeafRays.of(patches);
            SubPatchTable table = aimer.table;
            float[] records = aimer.records;
            double size = aimer.size, tolerance = aimer.tolerance;
            TraceContext ctx = new TraceContext();
            for (int s = 0; s < table.count; s++) {
                for (int r = 0; r < 12; r++) {
                    // a point of the leaf (borders included), and a ray to it from a random direction;
                    // every third ray is shifted off the surface by up to a tenth of the leaf: it may miss
                    double a = r < 4 ? r % 2 : rnd.nextDouble(), b = r < 4 ? r / 2 : rnd.nextDouble();
                    aimer.aim(ctx, s, a, b, r % 3 == 2 ? 0.1 * table.diagonal[s] : 0, rnd);
                    boolean reference = BezierClipper.intersect(ctx, table, null, s, 0, Double.POSITIVE_INFINITY, tolerance);
                    double tRef = ctx.rootT;
                    boolean fast = BezierClipper.intersect(ctx, table, records, s, 0, Double.POSITIVE_INFINITY, tolerance);
                    String where = "leaf " + s + " of " + table.count + ", ray " + r;
                    assertEquals(reference, fast, where);
                    if (fast) {
                        assertEquals(tRef, ctx.rootT, 1e-9 * size, where);
                        hits++;
                    } else if (NewtonSolver.start(ctx, records, NewtonLeafRecords.STRIDE * s, 0,
                            Double.POSITIVE_INFINITY, tolerance) == NewtonSolver.MISS) {
                        rejected++;
                    }
                    rays++;
                }
            }
        }
        assertTrue(hits > 0.5 * rays && rejected > 0.02 * rays,
                rays + " rays: " + hits + " hits, " + rejected + " leaves rejected by the enclosure");
    }

    @Test
    void aSingleRootLeafWhoseModelMissesItIsSettledByTheWindingFirstAsTheReferenceWould() {
        // Above bicubic, a single-root leaf whose quadratic model's start lies outside it is tried
        // by the winding test before Newton: the same answers, root for root, as the search
        // without records or models, and the order is taken (the counter)
        Random rnd = new Random(9_2026_12_03L);
        int rays = 0, hits = 0;
        long beside = 0;
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            LeafRays aimer = LeafRays.of(patches);
            SubPatchTable table = aimer.table;
            float[] quadratics = LeafQuadratics.build(table);
            double size = aimer.size, tolerance = aimer.tolerance;
            TraceContext ctx = new TraceContext();
            for (int s = 0; s < table.count; s++) {
                for (int r = 0; r < 8; r++) {
                    // near the leaf's border, half of them shifted off the surface: many pass beside
                    double a = rnd.nextBoolean() ? rnd.nextDouble() : (r % 2) * 1.0;
                    double b = rnd.nextBoolean() ? rnd.nextDouble() : (r / 2 % 2) * 1.0;
                    aimer.aim(ctx, s, a, b, r % 2 == 1 ? 0.1 * table.diagonal[s] : 0, rnd);
                    boolean reference = BezierClipper.intersect(ctx, table, null, s, 0, Double.POSITIVE_INFINITY, tolerance);
                    double tRef = ctx.rootT;
                    boolean fast = BezierClipper.intersect(ctx, table, aimer.records, quadratics, s, 0,
                            Double.POSITIVE_INFINITY, tolerance);
                    String where = "leaf " + s + " of " + table.count + ", ray " + r;
                    assertEquals(reference, fast, where);
                    if (fast) {
                        assertEquals(tRef, ctx.rootT, 1e-9 * size, where);
                        hits++;
                    }
                    rays++;
                }
            }
            beside += ctx.besideFirst;
        }
        assertTrue(hits > 0.3 * rays && beside > 0.01 * rays, rays + " rays: " + hits + " hits, " + beside
                + " leaves settled by the winding before Newton");
    }

    @Test
    void anUnevaluatedLastStepGivesTheAimedRootAndAnEvaluationWithinItsBound() {
        Random rnd = new Random(20261202L);
        int roots = 0, extrapolated = 0;
        double[] fresh = new double[9], scratch = new double[4096];
        for (int trial = 0; trial < 120; trial++) {
            int n = 1 + trial % 15, m = 1 + rnd.nextInt(15);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, 4, 0.4);
            SubPatchTable table = SubPatchTable.build(List.of(patch), SplitOptions.defaults());
            double size = new Scene(List.of(patch)).controlBounds().diagonal();
            double tolerance = PatchLeaves.RELATIVE_TOLERANCE * size;
            double curvature = table.patchCurvature[0];
            TraceContext ctx = new TraceContext();
            for (int r = 0; r < 40; r++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                DeCasteljau.evaluateWithDerivatives(table.patchNets, 0, n, m, u, v, fresh, scratch);
                double dx = 0.3 * rnd.nextGaussian(), dy = 0.3 * rnd.nextGaussian(), dz = -1;
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                ctx.setRay(fresh[0] - 5 * dx / len, fresh[1] - 5 * dy / len, fresh[2] - 5 * dz / len, dx / len, dy / len,
                        dz / len);
                int s = leafOf(table, u, v);
                float[] box = table.boxes;
                double su = (u - box[4 * s]) / (box[4 * s + 1] - box[4 * s]) + 0.05 * rnd.nextGaussian();
                double sv = (v - box[4 * s + 2]) / (box[4 * s + 3] - box[4 * s + 2]) + 0.05 * rnd.nextGaussian();
                if (!BezierClipper.newtonFrom(ctx, table, s, Math.min(1, Math.max(0, su)), Math.min(1, Math.max(0, sv)),
                        tolerance)) {
                    continue; // a start outside the basin (the clipping search takes over); not this test's subject
                }
                roots++;
                String where = "degree " + n + "x" + m + ", ray " + r;
                assertEquals(5, ctx.rootT, 1e-9 * size, where);
                assertEquals(u, ctx.rootU, 1e-7, where);
                assertEquals(v, ctx.rootV, 1e-7, where);
                assertEquals(ctx.rootU, ctx.evalU, 0, where);
                assertEquals(ctx.rootV, ctx.evalV, 0, where);
                double[] kept = ctx.eval;
                DeCasteljau.evaluateWithDerivatives(table.patchNets, 0, n, m, ctx.rootU, ctx.rootV, fresh, scratch);
                boolean same = true;
                for (int c = 0; c < 9; c++) {
                    same &= kept[c] == fresh[c];
                }
                if (!same) {
                    extrapolated++;
                    // position: the remainder bound was within EXTRAPOLATED × tolerance
                    for (int c = 0; c < 3; c++) {
                        assertEquals(fresh[c], kept[c], RayPatchNewton.EXTRAPOLATED * tolerance + 1e-14 * size, where);
                    }
                    // derivatives: they moved by at most M·(|du|+|dv|), where ½·M·(|du|+|dv|)² ≤ 1e-3·tolerance
                    double moved = Math.sqrt(2 * curvature * RayPatchNewton.EXTRAPOLATED * tolerance) + 1e-12 * size;
                    for (int c = 3; c < 9; c++) {
                        assertEquals(fresh[c], kept[c], moved * (1 + 1e-9) + 1e-12 * Math.abs(fresh[c]), where);
                    }
                }
            }
        }
        assertTrue(roots > 3000 && extrapolated > 0.3 * roots,
                roots + " roots, " + extrapolated + " ended on an unevaluated step");
    }

    /**
     * An any-hit query stops the clipping search at its first root: on folded and wavy nets of
     * degree 1..15 and the teapot, for segments of random length, {@code occluded} answers as the
     * closest hit within the segment does; the same context then answers closest-hit queries as a
     * cold one (the flag does not leak), and nothing occludes the segment before that closest hit
     * (a closest-hit query never stops at a farther root).
     */
    @Test
    void anAnyHitQueryStoppedAtItsFirstRootAnswersAsTheClosestHit() {
        Random rnd = new Random(777);
        int rays = 0, occluded = 0;
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            Scene scene = new Scene(patches);
            SceneIntersector si = SceneIntersector.build(scene, IntersectOptions.defaults());
            double size = si.sceneSize();
            var box = scene.controlBounds();
            TraceContext shared = si.newContext(), cold = si.newContext();
            Hit hit = new Hit(), coldHit = new Hit();
            for (int r = 0; r < 400; r++) {
                double px = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX());
                double py = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY());
                double pz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ());
                double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                dx /= len;
                dy /= len;
                dz /= len;
                double ox = px - size * dx, oy = py - size * dy, oz = pz - size * dz, tMax = 2 * size * rnd.nextDouble();
                boolean any = si.occluded(shared, ox, oy, oz, dx, dy, dz, 0, tMax);
                boolean closest = si.closestHit(cold, ox, oy, oz, dx, dy, dz, 0, tMax, coldHit);
                String where = patches.size() + " patches of degree " + patches.get(0).degreeU() + "x"
                        + patches.get(0).degreeV() + ", ray " + r;
                assertEquals(closest, any, where);
                boolean again = si.closestHit(shared, ox, oy, oz, dx, dy, dz, 0, tMax, hit);
                assertEquals(closest, again, where);
                if (closest) {
                    assertEquals(coldHit.t, hit.t, 1e-9 * size, where);
                    // the closest hit is the nearest root: nothing occludes the segment before it
                    assertFalse(si.occluded(shared, ox, oy, oz, dx, dy, dz, 0, hit.t - 1e-7 * size), where);
                    occluded++;
                }
                rays++;
            }
        }
        assertTrue(occluded > 0.2 * rays && occluded < 0.9 * rays, occluded + " of " + rays + " segments occluded");
    }

    /**
     * Shadow rays leaving surface points at grazing angles, on nets of degree 1..15 and the teapot,
     * meet leaves that may hold several roots, where an any-hit query takes the first root Newton
     * finds: it answers as the closest hit within the segment does, and nothing occludes the
     * segment before that closest hit. The shortcut is taken, not skipped.
     */
    @Test
    void anyHitQueriesAnsweredByNewtonOnFoldedLeavesAnswerAsTheClosestHit() {
        Random rnd = new Random(778);
        long[] tally = new long[3];
        for (List<BezierPatch> patches : RandomPatches.everyDegreeAndTheTeapot(rnd)) {
            grazingShadowRays(new Scene(patches), IntersectOptions.defaults(), rnd, 400, tally);
        }
        assertTrue(tally[0] > 3000 && tally[1] > tally[0] / 10, tally[1] + " of " + tally[0] + " grazing rays occluded");
        assertTrue(tally[2] > 100, tally[2] + " any-hit answers by Newton on folded leaves");
    }

    /**
     * The same on folded bicubic patches with holes: there a root Newton finds may be cut away by
     * the trim, and the query must go on to the roots the trim keeps, nearer ones included (so a
     * trimmed leaf is searched as for a closest hit).
     */
    @Test
    void anyHitQueriesOnTrimmedFoldsFindTheRootsTheTrimKeeps() {
        Random rnd = new Random(779);
        long[] tally = new long[3];
        for (int p = 0; p < 60; p++) {
            BezierPatch fold = RandomPatches.wild(rnd, 3, 3, 4);
            List<TrimLoop> holes = new ArrayList<>();
            for (int h = 0; h < 3; h++) {
                holes.add(TrimLoop.circle(0.2 + 0.6 * rnd.nextDouble(), 0.2 + 0.6 * rnd.nextDouble(),
                        0.1 + 0.1 * rnd.nextDouble(), false));
            }
            TrimRegion region = new TrimRegion(List.of(TrimLoop.circle(0.5, 0.5, 0.7, true)), holes);
            BezierPatch trimmed = new BezierPatch(3, 3, fold.copyNet(), null, new PatchDomain(0, 1, 0, 1, region), null);
            // split or whole (one leaf with all its folds, where the nearer root is often not Newton's)
            IntersectOptions options = p % 2 == 0 ? IntersectOptions.defaults()
                    : IntersectOptions.defaults().withSplit(SplitOptions.wholePatches());
            grazingShadowRays(new Scene(List.of(trimmed)), options, rnd, 300, tally);
        }
        assertTrue(tally[0] > 3000 && tally[1] > tally[0] / 10, tally[1] + " of " + tally[0] + " grazing rays occluded");
    }

    /**
     * {@code rays} camera-like rays at random points of the scene; from each hit a shadow ray leaves
     * at a grazing angle, its any-hit answer checked against the closest hit. Adds to {@code tally}:
     * shadow rays, occluded ones, any-hit answers by Newton.
     */
    private static void grazingShadowRays(Scene scene, IntersectOptions options, Random rnd, int rays, long[] tally) {
        SceneIntersector si = SceneIntersector.build(scene, options);
        double size = si.sceneSize();
        var box = scene.controlBounds();
        TraceContext any = si.newContext(), closest = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        for (int r = 0; r < rays; r++) {
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
            double px = box.minX() + rnd.nextDouble() * (box.maxX() - box.minX());
            double py = box.minY() + rnd.nextDouble() * (box.maxY() - box.minY());
            double pz = box.minZ() + rnd.nextDouble() * (box.maxZ() - box.minZ());
            if (!si.closestHit(closest, px - 2 * size * dx, py - 2 * size * dy, pz - 2 * size * dz, dx, dy, dz,
                    0, Double.POSITIVE_INFINITY, hit)) {
                continue;
            }
            si.surfacePoint(closest, hit, sp);
            double[] n = ShadowRays.facing(sp, dx, dy, dz);
            double nx = n[0], ny = n[1], nz = n[2];
            // a direction on the normal's side, at most about 17° above the tangent plane
            double lx = rnd.nextGaussian(), ly = rnd.nextGaussian(), lz = rnd.nextGaussian();
            double along = lx * nx + ly * ny + lz * nz, up = 0.3 * rnd.nextDouble();
            lx += (up - along) * nx;
            ly += (up - along) * ny;
            lz += (up - along) * nz;
            double eps = 1e-6 * size, ox = sp.px + eps * nx, oy = sp.py + eps * ny, oz = sp.pz + eps * nz;
            double tMax = 3 * size / Math.sqrt(lx * lx + ly * ly + lz * lz);
            boolean blocked = si.occluded(any, ox, oy, oz, lx, ly, lz, 0, tMax);
            boolean met = si.closestHit(closest, ox, oy, oz, lx, ly, lz, 0, tMax, hit);
            String where = scene.patches().size() + " patches of degree " + scene.patches().get(0).degreeU() + "x"
                    + scene.patches().get(0).degreeV() + ", ray " + r;
            assertEquals(met, blocked, where);
            if (met) {
                assertFalse(si.occluded(any, ox, oy, oz, lx, ly, lz, 0, hit.t * (1 - 1e-7)), where);
                tally[1]++;
            }
            tally[0]++;
        }
        tally[2] += any.anyRootsByNewton;
    }

    /** The leaf of the single-patch table that holds {@code (u, v)}. */
    private static int leafOf(SubPatchTable table, double u, double v) {
        for (int s = 0; s < table.count; s++) {
            float[] b = table.boxes;
            if (u >= b[4 * s] && u <= b[4 * s + 1] && v >= b[4 * s + 2] && v <= b[4 * s + 3]) {
                return s;
            }
        }
        throw new AssertionError("no leaf holds (" + u + ", " + v + ")");
    }
}
