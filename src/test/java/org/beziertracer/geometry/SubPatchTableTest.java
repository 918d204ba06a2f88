package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link SubPatchTable}: its flat arrays hold, for every sub-patch, exactly what
 * {@link PatchSplitter} made of its parent, with consistent indices, boxes and per-patch data;
 * an edit re-splits one patch and leaves the others' pieces as they were.
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
        assertEquals(patches.size(), tab.patchCount());
        assertEquals(patches, tab.patches());
        int s = 0;
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch patch = patches.get(k);
            PatchPieces pieces = PatchSplitter.split(patch, options);
            assertEquals(s, tab.firstOf[k], "first sub-patch of patch " + k);
            assertEquals(pieces.count(), tab.countOf(k), "pieces of patch " + k);
            assertEquals(patch.degreeU(), tab.patchDegreeU[k]);
            assertEquals(patch.degreeV(), tab.patchDegreeV[k]);
            double[] net = patch.copyNet();
            assertArrayEquals(net, Arrays.copyOfRange(tab.patchNets, tab.patchNetOffset[k],
                    tab.patchNetOffset[k] + net.length), 0, "whole net of patch " + k);
            for (int p = 0; p < pieces.count(); p++, s++) {
                String where = "sub-patch " + s + " (patch " + k + " piece " + p + ")";
                assertEquals(k, tab.parent[s], where);
                assertEquals(patch.degreeU(), tab.degreeU[s], where);
                assertEquals(patch.degreeV(), tab.degreeV[s], where);
                int len = pieces.netLength();
                assertArrayEquals(Arrays.copyOfRange(pieces.nets(), p * len, (p + 1) * len),
                        Arrays.copyOfRange(tab.nets, tab.netOffset[s], tab.netOffset[s] + len), 0, "net of " + where);
                assertArrayEquals(Arrays.copyOfRange(pieces.boxes(), 4 * p, 4 * p + 4),
                        Arrays.copyOfRange(tab.boxes, 4 * s, 4 * s + 4), 0, "parameter box of " + where);
                NetMeasures.controlBounds(tab.nets, tab.netOffset[s], patch.degreeU(), patch.degreeV(), box);
                assertArrayEquals(box, Arrays.copyOfRange(tab.bounds, 6 * s, 6 * s + 6), 0, "control box of " + where);
            }
        }
        assertEquals(s, tab.count);
        assertEquals(s, tab.firstOf[patches.size()]);
        assertEquals(HodographBounds.STRIDE * s, tab.uniqueness.length);
    }

    @Test
    void theArraysHoldEachPatchsPieces() {
        Random rnd = new Random(42);
        for (int trial = 0; trial < 30; trial++) {
            List<BezierPatch> patches = randomPatches(rnd, 1 + rnd.nextInt(6));
            SplitOptions options = new SplitOptions(true, 0.05 + 0.2 * rnd.nextDouble(), rnd.nextInt(6));
            assertTableOf(patches, options, SubPatchTable.build(patches, options));
        }
    }

    @Test
    void largeScenesSplitInParallelToTheSameTable() {
        Random rnd = new Random(43);
        List<BezierPatch> patches = randomPatches(rnd, SubPatchTable.PARALLEL_PATCHES + 5);
        assertTableOf(patches, SplitOptions.defaults(), SubPatchTable.build(patches, SplitOptions.defaults()));
    }

    @Test
    void anEditReSplitsOnlyThatPatch() {
        Random rnd = new Random(44);
        List<BezierPatch> patches = randomPatches(rnd, 5);
        SplitOptions options = new SplitOptions(true, 0.1, 5);
        SubPatchTable tab = SubPatchTable.build(patches, options);
        double[] before = tab.nets.clone();
        BezierPatch moved = PatchSplitterTest.randomPatch(rnd);
        SubPatchTable edited = tab.withPatch(2, moved);
        List<BezierPatch> expected = new ArrayList<>(patches);
        expected.set(2, moved);
        assertTableOf(expected, options, edited);
        assertSame(options, edited.options());
        assertArrayEquals(before, tab.nets, 0, "the old table is unchanged");
        assertEquals(patches, tab.patches());
        // The other patches' pieces are the same nets (not re-split differently)
        for (int k : new int[] {0, 1, 3, 4}) {
            assertEquals(tab.countOf(k), edited.countOf(k));
            int a = tab.netOffset[tab.firstOf[k]], b = edited.netOffset[edited.firstOf[k]];
            int len = tab.countOf(k) * 3 * (patches.get(k).degreeU() + 1) * (patches.get(k).degreeV() + 1);
            assertArrayEquals(Arrays.copyOfRange(tab.nets, a, a + len), Arrays.copyOfRange(edited.nets, b, b + len), 0,
                    "patch " + k);
        }
        assertTrue(edited.count > 0);
    }
}
