package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link EditedLeafData}: after an edit, the solver's per-leaf data (Newton records, leaf
 * quadratics, slabs) with the untouched patches' data copied equals the data computed afresh for every
 * leaf of the edited table, bit for bit: for edits that keep or change a patch's leaf count, one
 * patch or several, the first or the last, a degree-9 patch's hundreds of leaves (filled in
 * parallel chunks), and an edit that makes the first patch above bicubic.
 */
class EditedLeafDataTest {

    /** A degree-9 wavy patch (hundreds of leaves) beside a wild scene of patches up to degree 4. */
    private static List<BezierPatch> scene(Random rnd) {
        List<BezierPatch> patches = new ArrayList<>(SceneIntersectorTest.wildScene(rnd, 10, 4).patches());
        double[] net = Models.flatGrid(10, 10).copyNet();
        for (int k = 0; k < net.length; k += 3) {
            net[k + 2] = 0.5 * Math.sin(2.6 * net[k] + 1.2 * net[k + 1]) * Math.cos(1.7 * net[k + 1] - 0.9 * net[k]);
        }
        patches.add(4, new BezierPatch(9, 9, net));
        return patches;
    }

    @Test
    void copiedDataEqualsDataComputedAfresh() {
        Random rnd = new Random(808);
        List<BezierPatch> patches = scene(rnd);
        SubPatchTable before = SubPatchTable.build(patches, SplitOptions.defaults());
        float[] records = NewtonLeafRecords.build(before), quadratics = LeafQuadratics.build(before);
        float[] slabs = LeafSlabs.build(before);
        assertNotNull(quadratics);
        int changedCount = 0;
        for (int trial = 0; trial < 24; trial++) {
            int[] indices = trial % 3 == 0 ? new int[] {4} : trial % 3 == 1 ? new int[] {0, patches.size() - 1}
                    : new int[] {rnd.nextInt(patches.size()), rnd.nextInt(patches.size()), 4};
            List<BezierPatch> replacements = new ArrayList<>();
            for (int k : indices) {
                BezierPatch p = patches.get(k);
                double scale = trial % 2 == 0 ? 0.01 : 1; // a small drag, or a big one (more leaves)
                replacements.add(p.withPoint(p.degreeU() / 2, p.degreeV() / 2, p.get(p.degreeU() / 2, p.degreeV() / 2, 0)
                        + scale * rnd.nextGaussian(), p.get(p.degreeU() / 2, p.degreeV() / 2, 1), p.get(p.degreeU() / 2,
                        p.degreeV() / 2, 2) + scale * rnd.nextGaussian()));
            }
            SubPatchTable after = before.withPatches(indices, replacements, trial % 4 != 3);
            changedCount += after.count != before.count ? 1 : 0;
            String where = "trial " + trial;
            assertArrayEquals(NewtonLeafRecords.build(after), NewtonLeafRecords.edited(records, before, after, indices), where);
            assertArrayEquals(LeafQuadratics.build(after), LeafQuadratics.edited(quadratics, before, after, indices), where);
            assertArrayEquals(LeafSlabs.build(after), LeafSlabs.edited(slabs, before, after, indices), where);
        }
        assertTrue(changedCount >= 4, "edits that change the leaf count: " + changedCount);
    }

    @Test
    void anEditThatMakesTheFirstPatchAboveBicubicComputesItsQuadratics() {
        Random rnd = new Random(809);
        List<BezierPatch> patches = SceneIntersectorTest.wildScene(rnd, 6, 3).patches();
        SubPatchTable before = SubPatchTable.build(patches, SplitOptions.defaults());
        assertNull(LeafQuadratics.build(before));
        BezierPatch quintic = scene(rnd).get(4);
        SubPatchTable after = before.withPatches(new int[] {2}, List.of(quintic), true);
        float[] expected = LeafQuadratics.build(after);
        assertNotNull(expected);
        assertArrayEquals(expected, LeafQuadratics.edited(null, before, after, new int[] {2}));
        // and back to bicubic and lower: none
        SubPatchTable back = after.withPatches(new int[] {2}, List.of(patches.get(2)), true);
        assertNull(LeafQuadratics.edited(expected, after, back, new int[] {2}));
        assertEquals(before.count, back.count, "the old patch back, split afresh (another degree)");
    }
}
