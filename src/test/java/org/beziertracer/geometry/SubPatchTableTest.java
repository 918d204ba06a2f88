package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link SubPatchTable}: its flat arrays hold, for every sub-patch, exactly what
 * {@link PatchSplitter} made of its parent (with the table's scene-relative stop), with consistent
 * indices, boxes and per-patch data; each net is stored once (a leaf that is its whole patch shares
 * the patch's net); an edit re-splits one patch and leaves the others' leaves as they were.
 */
class SubPatchTableTest {

    static List<BezierPatch> randomPatches(Random rnd, int count) {
        List<BezierPatch> list = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            list.add(PatchSplitterTest.randomPatch(rnd));
        }
        return list;
    }

    /** Every array of {@code tab} against an independent split of each patch. */
    static void assertTableOf(List<BezierPatch> patches, SplitOptions options, SubPatchTable tab) {
        double[] box = new double[6];
        double[] uniqueness = new double[HodographBounds.STRIDE];
        assertEquals(patches.size(), tab.patchCount());
        assertEquals(patches, tab.patches());
        assertSame(tab.nets, tab.patchNets, "one array of nets");
        int s = 0;
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch patch = patches.get(k);
            PatchPieces pieces = PatchSplitter.split(patch, options, tab.minSize());
            assertEquals(s, tab.firstOf[k], "first sub-patch of patch " + k);
            assertEquals(pieces.count(), tab.countOf(k), "pieces of patch " + k);
            assertEquals(patch.degreeU(), tab.patchDegreeU[k]);
            assertEquals(patch.degreeV(), tab.patchDegreeV[k]);
            double[] net = patch.copyNet();
            assertArrayEquals(net, Arrays.copyOfRange(tab.patchNets, tab.patchNetOffset[k],
                    tab.patchNetOffset[k] + net.length), 0, "whole net of patch " + k);
            assertEquals(PatchNormals.squaredExtent(net, 0, patch.degreeU(), patch.degreeV()),
                    tab.patchSquaredExtent[k], 0);
            assertPowerForm(patch, patches.size(), tab, k);
            double[] leafBounds = tab.bounds(s, pieces.count());
            for (int p = 0; p < pieces.count(); p++, s++) {
                String where = "sub-patch " + s + " (patch " + k + " piece " + p + ")";
                assertEquals(k, tab.parent[s], where);
                assertEquals(patch.degreeU(), tab.degreeU[s], where);
                assertEquals(patch.degreeV(), tab.degreeV[s], where);
                int len = pieces.netLength();
                if (pieces.count() == 1) {
                    assertEquals(tab.patchNetOffset[k], tab.netOffset[s], "a whole-patch leaf shares the net: " + where);
                }
                assertArrayEquals(Arrays.copyOfRange(pieces.nets(), p * len, (p + 1) * len),
                        Arrays.copyOfRange(tab.nets, tab.netOffset[s], tab.netOffset[s] + len), 0, "net of " + where);
                for (int c = 0; c < 4; c++) {
                    assertEquals(pieces.boxes()[4 * p + c], tab.boxes[4 * s + c], 0, "parameter box of " + where);
                }
                NetMeasures.controlBounds(tab.nets, tab.netOffset[s], patch.degreeU(), patch.degreeV(), box);
                assertArrayEquals(box, Arrays.copyOfRange(leafBounds, 6 * p, 6 * p + 6), 0, "control box of " + where);
                double dx = box[3] - box[0], dy = box[4] - box[1], dz = box[5] - box[2];
                assertEquals(Math.sqrt(dx * dx + dy * dy + dz * dz), tab.diagonal[s], 0, "diagonal of " + where);
                HodographBounds.compute(tab.nets, tab.netOffset[s], patch.degreeU(), patch.degreeV(), uniqueness, 0,
                        new double[6]);
                assertArrayEquals(uniqueness, Arrays.copyOfRange(tab.uniqueness, HodographBounds.STRIDE * s,
                        HodographBounds.STRIDE * (s + 1)), 0, "uniqueness data of " + where);
            }
        }
        assertEquals(s, tab.count);
        assertEquals(s, tab.firstOf[patches.size()]);
        assertEquals(HodographBounds.STRIDE * s, tab.uniqueness.length);
    }

    /**
     * Patch {@code k}'s {@link PowerForm} in {@code tab}: there, as {@link PowerForm#fromBezier}
     * makes it, exactly when the patch is polynomial of degree up to 9 in a scene of at most
     * {@link SubPatchTable#POWER_PATCHES} patches; and {@link SubPatchTable#evaluatePatch} is the
     * patch itself, against de Casteljau.
     */
    static void assertPowerForm(BezierPatch patch, int patchCount, SubPatchTable tab, int k) {
        int n = patch.degreeU(), m = patch.degreeV();
        double[] net = patch.copyNet();
        int power = tab.patchPowerOffset[k];
        double[] expected = new double[net.length];
        if (patchCount <= SubPatchTable.POWER_PATCHES && !patch.isRational() && Math.max(n, m) <= 9
                && PowerForm.fromBezier(net, 0, n, m, expected, 0)) {
            assertTrue(power >= tab.patchNetOffset[k] + net.length, "patch " + k + "'s power form follows its net");
            assertArrayEquals(expected, Arrays.copyOfRange(tab.nets, power, power + net.length), 0,
                    "power form of patch " + k);
        } else {
            assertEquals(-1, power, "patch " + k + " has no power form");
        }
        double[] got = new double[9], want = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        double size = TestNets.size(net, 0, net.length);
        for (double[] uv : new double[][] {{0, 0}, {1, 1}, {0.3, 0.8}, {0.5, 0.5}, {0.9, 0.1}}) {
            tab.evaluatePatch(k, uv[0], uv[1], got, scratch);
            DeCasteljau.evaluateWithDerivatives(net, 0, n, m, uv[0], uv[1], want, scratch);
            for (int c = 0; c < 9; c++) {
                assertEquals(want[c], got[c], (c < 3 ? 1e-12 : 1e-10) * size, "patch " + k + " at " + Arrays.toString(uv));
            }
        }
    }

    @Test
    void theArraysHoldEachPatchsPieces() {
        Random rnd = new Random(42);
        for (int trial = 0; trial < 30; trial++) {
            List<BezierPatch> patches = randomPatches(rnd, 1 + rnd.nextInt(6));
            SplitOptions options = new SplitOptions(true, 0.05 + 0.2 * rnd.nextDouble(), rnd.nextInt(6));
            SubPatchTable tab = SubPatchTable.build(patches, options);
            assertEquals(SubPatchTable.minSize(patches, options), tab.minSize(), 0);
            assertTableOf(patches, options, tab);
        }
        List<BezierPatch> some = randomPatches(rnd, 3);
        assertTableOf(some, SplitOptions.wholePatches(), SubPatchTable.build(some, SplitOptions.wholePatches()));
    }

    @Test
    void largeScenesSplitInParallelToTheSameTable() {
        Random rnd = new Random(43);
        List<BezierPatch> patches = randomPatches(rnd, SubPatchTable.PARALLEL_PATCHES + 5);
        assertTableOf(patches, SplitOptions.defaults(), SubPatchTable.build(patches, SplitOptions.defaults()));
    }

    @Test
    void eachNetIsStoredOnce() {
        Random rnd = new Random(45);
        List<BezierPatch> patches = randomPatches(rnd, 40);
        SubPatchTable tab = SubPatchTable.build(patches, SplitOptions.defaults());
        long expected = 0;
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch p = patches.get(k);
            int len = 3 * p.pointCount();
            expected += tab.countOf(k) == 1 ? len : (long) len * (1 + tab.countOf(k));
            expected += PowerForm.has(p.degreeU(), p.degreeV()) ? len : 0;
        }
        assertEquals(expected, tab.nets.length, "whole nets, power forms and the nets of split patches' leaves");
        assertTrue(tab.count > patches.size(), "some patches were split");
    }

    @Test
    void bytesCountEveryArray() {
        SubPatchTable tab = SubPatchTable.build(randomPatches(new Random(46), 12), SplitOptions.defaults());
        long expected = HeapBytes.array(tab.count, 4) * 2 + HeapBytes.array(tab.count, 1) * 2
                + HeapBytes.array(4L * tab.count, 4) + HeapBytes.array(tab.count, 8)
                + HeapBytes.array((long) HodographBounds.STRIDE * tab.count, 8) + HeapBytes.array(tab.nets.length, 8)
                + HeapBytes.array(tab.patchCount() + 1, 4) + 6 * HeapBytes.array(tab.patchCount(), 4)
                + HeapBytes.array(tab.patchCount(), 8) + HeapBytes.array(4L * tab.patchCount(), 8);
        assertEquals(expected, tab.bytes());
        long perLeaf = (tab.bytes() - HeapBytes.array(tab.nets.length, 8)) / tab.count;
        assertTrue(perLeaf <= SubPatchTable.LEAF_BYTES + 16, "bytes a leaf besides its net: " + perLeaf);
    }

    /**
     * The scene-relative stop: with τ² = Σ d² / budget, a few patches are split as the options
     * say, while in {@code budget / 8} copies of the same 8 patches (the same shapes, a scene of
     * over 100,000 patches) a patch smaller than τ is one leaf and the mean is a few leaves a patch.
     */
    @Test
    void manyPatchesAreSplitLessThanFew() {
        Random rnd = new Random(47);
        List<BezierPatch> few = new ArrayList<>();
        for (int k = 0; k < 8; k++) {
            int n = 3 + rnd.nextInt(3);
            few.add(new BezierPatch(n, n, TestNets.randomNet(rnd, n, n, 3, 1 + 3 * rnd.nextDouble())));
        }
        SubPatchTable small = SubPatchTable.build(few, SplitOptions.defaults());
        int splitFew = 0;
        for (int k = 0; k < few.size(); k++) {
            assertEquals(PatchSplitter.split(few.get(k), SplitOptions.defaults()).count(), small.countOf(k),
                    "a small scene is split as the options say, patch " + k);
            splitFew += small.countOf(k);
        }
        List<BezierPatch> many = new ArrayList<>();
        for (int c = 0; c < SubPatchTable.LEAF_BUDGET / few.size(); c++) {
            many.addAll(few);
        }
        double tau = SubPatchTable.minSize(many, SplitOptions.defaults());
        double meanSquare = 0;
        for (BezierPatch p : few) {
            meanSquare += Math.pow(p.controlBounds().diagonal(), 2) / few.size();
        }
        assertEquals(Math.sqrt(meanSquare * many.size() / SubPatchTable.LEAF_BUDGET), tau, 1e-9 * tau);
        int splitMany = 0;
        for (BezierPatch p : few) {
            int leaves = PatchSplitter.split(p, SplitOptions.defaults(), tau).count();
            splitMany += leaves;
            if (p.controlBounds().diagonal() < tau) {
                assertEquals(1, leaves, "a patch smaller than τ is one leaf");
            }
        }
        assertTrue(splitMany <= 4 * few.size() && splitMany < splitFew,
                "leaves of the 8 shapes: " + splitMany + " in the big scene, " + splitFew + " alone");
    }

    @Test
    void anEditReSplitsOnlyThatPatchWhereverItIs() {
        Random rnd = new Random(44);
        for (int index = 0; index < 5; index++) {
            List<BezierPatch> patches = randomPatches(rnd, 5);
            SplitOptions options = new SplitOptions(true, 0.1, 5);
            SubPatchTable tab = SubPatchTable.build(patches, options);
            double[] before = tab.nets.clone();
            // A flat patch (one leaf) or a wavy one (several): the region grows or shrinks
            BezierPatch moved = index % 2 == 0 ? PatchSplitterTest.randomPatch(rnd) : flat(patches.get(index));
            SubPatchTable edited = tab.withPatch(index, moved);
            List<BezierPatch> expected = new ArrayList<>(patches);
            expected.set(index, moved);
            assertTableOf(expected, options, edited);
            assertSame(options, edited.options());
            assertEquals(tab.minSize(), edited.minSize(), 0, "an edit keeps the scene's stop");
            assertArrayEquals(before, tab.nets, 0, "the old table is unchanged");
            assertEquals(patches, tab.patches());
            for (int k = 0; k < 5; k++) {
                if (k != index) {
                    assertEquals(tab.countOf(k), edited.countOf(k));
                    int a = tab.patchNetOffset[k], b = edited.patchNetOffset[k];
                    int net = 3 * patches.get(k).pointCount();
                    int len = tab.countOf(k) == 1 ? net : net * (1 + tab.countOf(k));
                    len += tab.patchPowerOffset[k] >= 0 ? net : 0;
                    assertArrayEquals(Arrays.copyOfRange(tab.nets, a, a + len), Arrays.copyOfRange(edited.nets, b, b + len),
                            0, "patch " + k);
                }
            }
        }
    }

    /** A net near the largest doubles, whose power form overflows, keeps de Casteljau: its evaluation stays finite. */
    @Test
    void aNetWhosePowerFormOverflowsKeepsDeCasteljau() {
        Random rnd = new Random(49);
        BezierPatch huge = new BezierPatch(5, 5, TestNets.randomNet(rnd, 5, 5, 3, 1e307));
        BezierPatch small = new BezierPatch(3, 3, TestNets.randomNet(rnd, 3, 3, 3, 1));
        SubPatchTable tab = SubPatchTable.build(List.of(small, huge), SplitOptions.wholePatches());
        assertEquals(-1, tab.patchPowerOffset[1], "no power form");
        assertTrue(tab.patchPowerOffset[0] >= 0, "the small patch keeps its own");
        double[] out = new double[9];
        tab.evaluatePatch(1, 0.3, 0.6, out, new double[DeCasteljau.SCRATCH_LENGTH]);
        for (double x : Arrays.copyOf(out, 3)) {
            assertTrue(Double.isFinite(x), "a finite point: " + Arrays.toString(out));
        }
        assertPowerForm(small, 2, tab, 0);
        assertPowerForm(huge, 2, tab, 1);
    }

    /** A scene of more than {@link SubPatchTable#POWER_PATCHES} patches keeps no power forms (their memory). */
    @Test
    void aHugeSceneKeepsNoPowerForms() {
        Random rnd = new Random(48);
        List<BezierPatch> patches = new ArrayList<>();
        for (int k = 0; k <= SubPatchTable.POWER_PATCHES; k++) {
            patches.add(new BezierPatch(1, 1, TestNets.randomNet(rnd, 1, 1, 3, 1)));
        }
        SubPatchTable tab = SubPatchTable.build(patches, SplitOptions.defaults());
        assertTrue(Arrays.stream(tab.patchPowerOffset).allMatch(o -> o == -1), "no power forms");
        long nets = 0;
        for (int k = 0; k < patches.size(); k++) {
            nets += 12L * (tab.countOf(k) == 1 ? 1 : 1 + tab.countOf(k));
        }
        assertEquals(nets, tab.nets.length, "the nets alone");
        assertPowerForm(patches.get(7), patches.size(), tab, 7);
        List<BezierPatch> fewer = patches.subList(0, SubPatchTable.POWER_PATCHES);
        SubPatchTable kept = SubPatchTable.build(fewer, SplitOptions.defaults());
        assertTrue(Arrays.stream(kept.patchPowerOffset).allMatch(o -> o >= 0), "one patch fewer: every power form");
        assertPowerForm(fewer.get(7), fewer.size(), kept, 7);
    }

    /** The corners of {@code p} with a bilinear net between them: flat, one leaf. */
    static BezierPatch flat(BezierPatch p) {
        int n = p.degreeU(), m = p.degreeV();
        double[] net = new double[3 * p.pointCount()];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                double u = (double) i / n, v = (double) j / m;
                for (int c = 0; c < 3; c++) {
                    net[p.index(i, j, c)] = (1 - u) * (1 - v) * p.get(0, 0, c) + u * (1 - v) * p.get(n, 0, c)
                            + (1 - u) * v * p.get(0, m, c) + u * v * p.get(n, m, c);
                }
            }
        }
        return new BezierPatch(n, m, net);
    }
}
