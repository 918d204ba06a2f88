package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/** Pre-splitting rational and trimmed patches, and what the sub-patch table keeps of them. */
class RationalTrimmedSplitTest {

    private static BezierPatch randomRational(Random rnd, int n, int m) {
        double[] w = new double[(n + 1) * (m + 1)];
        for (int k = 0; k < w.length; k++) {
            w[k] = 0.3 + 3 * rnd.nextDouble();
        }
        return new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 5), w, null, null);
    }

    @Test
    void rationalPiecesReproduceTheParentAndHaveEvenWeights() {
        Random rnd = new Random(61);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < 30; trial++) {
            BezierPatch p = randomRational(rnd, 1 + rnd.nextInt(4), 1 + rnd.nextInt(4));
            PatchPieces pieces = PatchSplitter.split(p, SplitOptions.defaults());
            assertNotNull(pieces.weights());
            int points = p.pointCount();
            for (int s = 0; s < pieces.count(); s++) {
                double[] h = new double[4 * points];
                RationalDeCasteljau.toHomogeneous(pieces.nets(), 3 * points * s, pieces.weights(), points * s, points, h, 0);
                double[] b = java.util.Arrays.copyOfRange(pieces.boxes(), 4 * s, 4 * s + 4);
                double a = rnd.nextDouble(), c = rnd.nextDouble();
                double[] piece = new double[3];
                RationalDeCasteljau.evaluate(h, 0, p.degreeU(), p.degreeV(), a, c, piece, 0, scratch);
                Vec3 parent = Patches.evaluate(p, b[0] + a * (b[1] - b[0]), b[2] + c * (b[3] - b[2]));
                assertArrayEquals(new double[] {parent.x(), parent.y(), parent.z()}, piece, 1e-11, "trial " + trial);
            }
        }
    }

    @Test
    void aTableWithoutRationalOrTrimmedPatchesKeepsNoWeightsOrTrims() {
        SubPatchTable t = SubPatchTable.build(TestNets.teapot(), SplitOptions.defaults());
        assertNull(t.weights);
        assertNull(t.trimTest);
        assertEquals(3, t.patchDim[0]);
    }

    @Test
    void theTableKeepsHomogeneousWholeNetsAndSubPatchWeights() {
        Random rnd = new Random(62);
        BezierPatch poly = new BezierPatch(2, 2, TestNets.randomNet(rnd, 2, 2, 3, 5));
        BezierPatch rat = randomRational(rnd, 2, 3);
        SubPatchTable t = SubPatchTable.build(List.of(poly, rat), SplitOptions.defaults());
        assertEquals(3, t.patchDim[0]);
        assertEquals(4, t.patchDim[1]);
        int s = t.firstOf[0];
        assertEquals(1.0, t.weights[t.netOffset[s] / 3]);
        double[] w = rat.weights();
        assertEquals(w[0] * rat.get(0, 0, 0), t.patchNets[t.patchNetOffset[1]]);
        assertEquals(w[0], t.patchNets[t.patchNetOffset[1] + 3]);
    }

    @Test
    void subPatchesOutsideTheTrimLoopsAreDroppedAndInsideOnesNeedNoTest() {
        TrimRegion region = new TrimRegion(List.of(TrimShapes.circle(0.5, 0.5, 0.3, true)),
                List.of(TrimShapes.polygon(0.45, 0.45, 0.55, 0.45, 0.55, 0.55, 0.45, 0.55)));
        BezierPatch plain = new BezierPatch(3, 3, TestNets.randomNet(new Random(63), 3, 3, 3, 1));
        BezierPatch trimmed = new BezierPatch(3, 3, plain.copyNet(), null, new PatchDomain(0, 1, 0, 1, region), null);
        SplitOptions fine = new SplitOptions(true, 1e-6, 6);
        PatchPieces all = PatchSplitter.split(plain, fine), kept = PatchSplitter.split(trimmed, fine);
        assertEquals(1 << fine.maxDepthFor(3, 3), all.count());
        assertTrue(kept.count() < all.count() && kept.count() > 0, "kept " + kept.count());
        TrimCurves curves = TrimCurves.of(region);
        double[] scratch = new double[TrimCurves.SCRATCH_LENGTH];
        int untested = 0;
        for (int s = 0; s < kept.count(); s++) {
            if (kept.trimTest()[s]) {
                continue;
            }
            untested++;
            double[] b = java.util.Arrays.copyOfRange(kept.boxes(), 4 * s, 4 * s + 4);
            for (double a = 0; a <= 1; a += 0.25) {
                for (double c = 0; c <= 1; c += 0.25) {
                    assertTrue(curves.contains(b[0] + a * (b[1] - b[0]), b[2] + c * (b[3] - b[2]), scratch));
                }
            }
        }
        assertTrue(untested > 0);
        // every kept point of the domain is in some kept piece
        Random rnd = new Random(64);
        for (int k = 0; k < 2000; k++) {
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            if (!curves.contains(u, v, scratch)) {
                continue;
            }
            boolean covered = false;
            for (int s = 0; s < kept.count() && !covered; s++) {
                covered = u >= kept.boxes()[4 * s] && u <= kept.boxes()[4 * s + 1]
                        && v >= kept.boxes()[4 * s + 2] && v <= kept.boxes()[4 * s + 3];
            }
            assertTrue(covered, "(" + u + ", " + v + ") is in the region but in no kept piece");
        }
    }

    /** Every public array of two tables, equal. */
    private static void assertSameTable(SubPatchTable a, SubPatchTable b, String where) {
        assertEquals(a.count, b.count, where);
        assertArrayEquals(a.parent, b.parent, where);
        assertArrayEquals(a.degreeU, b.degreeU, where);
        assertArrayEquals(a.degreeV, b.degreeV, where);
        assertArrayEquals(a.netOffset, b.netOffset, where);
        assertArrayEquals(a.nets, b.nets, where);
        assertArrayEquals(a.boxes, b.boxes, where);
        assertArrayEquals(a.diagonal, b.diagonal, where);
        assertArrayEquals(a.firstOf, b.firstOf, where);
        assertArrayEquals(a.patchNetOffset, b.patchNetOffset, where);
        assertArrayEquals(a.uniqueness, b.uniqueness, where);
        assertArrayEquals(a.patchSquaredExtent, b.patchSquaredExtent, where);
        assertArrayEquals(a.patchDim, b.patchDim, where);
        assertArrayEquals(a.weights, b.weights, where);
        assertArrayEquals(a.trimTest, b.trimTest, where);
        assertArrayEquals(a.patchDomain, b.patchDomain, where);
        for (int k = 0; k < a.patchCount(); k++) {
            assertEquals(a.patchTrim[k] == null, b.patchTrim[k] == null, where + ", trim of patch " + k);
        }
    }

    @Test
    void editingSeveralPatchesOfAMixedSceneGivesTheTableOfTheEditedScene() {
        // Polynomial, rational and trimmed patches; each edit moves one to three of them (rational
        // ones stay rational with new weights, trimmed ones keep their region), in any order
        Random rnd = new Random(65);
        TrimRegion region = new TrimRegion(List.of(TrimShapes.circle(0.5, 0.5, 0.4, true)), List.of());
        SplitOptions options = new SplitOptions(true, 0.05, 5);
        for (int trial = 0; trial < 40; trial++) {
            List<BezierPatch> patches = new java.util.ArrayList<>();
            for (int k = 0; k < 6; k++) {
                patches.add(mixed(rnd, k % 3, region));
            }
            SubPatchTable table = SubPatchTable.build(patches, options);
            int edits = 1 + rnd.nextInt(3);
            int[] indices = new int[edits];
            List<BezierPatch> replacements = new java.util.ArrayList<>();
            List<BezierPatch> edited = new java.util.ArrayList<>(patches);
            for (int e = 0; e < edits; e++) {
                indices[e] = rnd.nextInt(patches.size());
                BezierPatch moved = mixed(rnd, indices[e] % 3, region);
                replacements.add(moved);
                edited.set(indices[e], moved);
            }
            SubPatchTable fresh = SubPatchTable.build(edited, options);
            // the scene-relative stop (which an edit keeps from the old scene) stopped no piece
            double smallest = java.util.Arrays.stream(fresh.diagonal).min().orElse(1);
            assertTrue(Math.max(fresh.minSize(), table.minSize()) < smallest, "the stop plays no part here");
            assertSameTable(fresh, table.withPatches(indices, replacements), "trial " + trial);
        }
    }

    /** kind 0: polynomial; 1: rational; 2: trimmed by {@code region}; of random degrees up to 3. */
    private static BezierPatch mixed(Random rnd, int kind, TrimRegion region) {
        int n = 1 + rnd.nextInt(3), m = 1 + rnd.nextInt(3);
        return switch (kind) {
            case 0 -> new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 5));
            case 1 -> randomRational(rnd, n, m);
            default -> new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 5), null,
                    new PatchDomain(0, 1, 0, 1, region), null);
        };
    }

    @Test
    void anEditThatMakesTheFirstRationalPatchGivesTheTableOfTheEditedScene() {
        Random rnd = new Random(66);
        List<BezierPatch> patches = List.of(new BezierPatch(2, 2, TestNets.randomNet(rnd, 2, 2, 3, 5)),
                new BezierPatch(3, 2, TestNets.randomNet(rnd, 3, 2, 3, 5)));
        SubPatchTable table = SubPatchTable.build(patches, SplitOptions.defaults());
        assertNull(table.weights);
        BezierPatch rational = randomRational(rnd, 2, 2);
        SubPatchTable edited = table.withPatch(1, rational);
        assertNotNull(edited.weights);
        assertSameTable(SubPatchTable.build(List.of(patches.get(0), rational), SplitOptions.defaults()), edited,
                "first rational patch");
    }
}
