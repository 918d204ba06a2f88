package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.TrimRegion;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link PatchSplitter#resplit}: an edited patch re-split along its old halvings ({@link SplitGuide}).
 * Replaying a patch's own split remakes it bit for bit; after a drag the pieces still tile the
 * square and are the new patch restricted to their boxes; a kept leaf is within the slack of flat;
 * boxes that are not such a split are refused.
 */
class PatchResplitTest {

    private static final SplitOptions OPTIONS = SplitOptions.defaults();

    /** The pieces' boxes as a table holds them (floats, 4 a piece). */
    static float[] boxes(PatchPieces p) {
        float[] out = new float[p.boxes().length];
        for (int i = 0; i < out.length; i++) {
            out[i] = (float) p.boxes()[i];
        }
        return out;
    }

    /** The wavy height field of issue [1 of 5] on a {@code points}×{@code points} grid, times {@code amplitude}. */
    static BezierPatch wavy(int points, double amplitude) {
        double[] net = Models.flatGrid(points, points).copyNet();
        for (int k = 0; k < net.length; k += 3) {
            double x = net[k], y = net[k + 1];
            net[k + 2] = amplitude * (0.5 * Math.sin(2.6 * x + 1.2 * y) * Math.cos(1.7 * y - 0.9 * x)
                    + 0.25 * Math.sin(2.0 * x * y));
        }
        return new BezierPatch(points - 1, points - 1, net);
    }

    /** Patches of degree 1..15, random, wavy (hundreds of pieces: the two-thread path), rational, the teapot's. */
    static List<BezierPatch> patches(Random rnd) {
        List<BezierPatch> out = new ArrayList<>(TestNets.teapot());
        for (int trial = 0; trial < 60; trial++) {
            int n = 1 + rnd.nextInt(15), m = 1 + rnd.nextInt(15);
            out.add(new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, Math.pow(10, rnd.nextInt(5) - 2))));
        }
        for (int points : new int[] {2, 4, 6, 10, 16}) {
            out.add(wavy(points, 0.5 + rnd.nextDouble()));
        }
        for (int trial = 0; trial < 10; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            double[] weights = new double[(n + 1) * (m + 1)];
            for (int k = 0; k < weights.length; k++) {
                weights[k] = 0.3 + 3 * rnd.nextDouble();
            }
            out.add(new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 1), weights, PatchDomain.UNIT, null));
        }
        return out;
    }

    @Test
    void replayingAnUnchangedPatchRemakesItsSplitBitForBit() {
        Random rnd = new Random(4401);
        int parallel = 0;
        for (BezierPatch patch : patches(rnd)) {
            PatchPieces fresh = PatchSplitter.split(patch, OPTIONS);
            PatchPieces replay = PatchSplitter.resplit(patch, OPTIONS, 0, new PatchSplitter.Workspace(), boxes(fresh), 0,
                    fresh.count());
            String where = TestNets.degrees(patch.degreeU(), patch.degreeV(), patch.isRational() ? 4 : 3) + ", "
                    + fresh.count() + " pieces";
            assertNotNull(replay, where);
            assertEquals(fresh.count(), replay.count(), where);
            assertArrayEquals(fresh.boxes(), replay.boxes(), 0, where);
            assertArrayEquals(fresh.nets(), replay.nets(), 0, where);
            assertArrayEquals(fresh.weights(), replay.weights(), 0, where);
            parallel += fresh.count() >= PatchSplitter.PARALLEL_LEAVES ? 1 : 0;
        }
        assertTrue(parallel >= 2, "patches re-split on two threads: " + parallel);
    }

    @Test
    void aDraggedPatchKeepsItsLeavesWhichAreItsRestrictions() {
        Random rnd = new Random(4402);
        int kept = 0, all = 0;
        for (BezierPatch patch : patches(rnd)) {
            if (patch.isRational()) {
                continue;
            }
            PatchPieces before = PatchSplitter.split(patch, OPTIONS);
            int n = patch.degreeU(), m = patch.degreeV();
            double size = patch.controlBounds().diagonal();
            // A drag: one inner point (or a corner of a bilinear net) moved by 1 % of the patch's size
            int i = n / 2, j = m / 2;
            BezierPatch dragged = patch.withPoint(i, j, patch.get(i, j, 0) + 0.01 * size, patch.get(i, j, 1) - 0.005 * size,
                    patch.get(i, j, 2) + 0.01 * size);
            PatchPieces after = PatchSplitter.resplit(dragged, OPTIONS, 0, new PatchSplitter.Workspace(), boxes(before), 0,
                    before.count());
            String where = TestNets.degrees(n, m, 3) + ", " + before.count() + " pieces";
            assertNotNull(after, where);
            assertTrue(after.count() >= before.count(), where);
            assertPiecesOf(dragged, after, where);
            kept += after.count() == before.count() ? 1 : 0;
            all++;
        }
        assertTrue(kept >= 0.9 * all, "a small drag keeps the leaf count of most patches: " + kept + " of " + all);
    }

    @Test
    void aLeafBentPastTheSlackIsSplitOn() {
        BezierPatch flat = wavy(6, 0.01);
        PatchPieces before = PatchSplitter.split(flat, OPTIONS);
        BezierPatch bent = wavy(6, 1);
        PatchPieces after = PatchSplitter.resplit(bent, OPTIONS, 0, new PatchSplitter.Workspace(), boxes(before), 0,
                before.count());
        assertNotNull(after);
        assertTrue(after.count() > before.count(), before.count() + " -> " + after.count());
        assertPiecesOf(bent, after, "bent");
        // Every piece below the base cap is within the slack of flat
        for (int p = 0; p < after.count(); p++) {
            double du = after.boxes()[4 * p + 1] - after.boxes()[4 * p], dv = after.boxes()[4 * p + 3] - after.boxes()[4 * p + 2];
            int depth = (int) Math.round(-Math.log(du * dv) / Math.log(2));
            double[] net = java.util.Arrays.copyOfRange(after.nets(), p * after.netLength(), (p + 1) * after.netLength());
            double diagonal = org.beziertracer.math.Aabb.ofPoints(net).diagonal();
            if (depth < OPTIONS.maxDepth()) {
                assertTrue(PatchSplitter.flatness(net, 0, 5, 5) <= PatchSplitter.KEPT_SLACK * OPTIONS.flatnessFor(5, 5) * diagonal,
                        "piece " + p);
            }
        }
    }

    @Test
    void boxesThatAreNotASplitOfThePatchAreRefused() {
        BezierPatch patch = wavy(4, 1);
        PatchPieces pieces = PatchSplitter.split(patch, OPTIONS);
        float[] boxes = boxes(pieces);
        int count = pieces.count();
        assertTrue(count > 4);
        var w = new PatchSplitter.Workspace();
        // the first half of the leaves only
        assertNull(PatchSplitter.resplit(patch, OPTIONS, 0, w, boxes, 0, count / 2));
        // the leaves in reverse order
        float[] reversed = new float[boxes.length];
        for (int s = 0; s < count; s++) {
            System.arraycopy(boxes, 4 * (count - 1 - s), reversed, 4 * s, 4);
        }
        assertNull(PatchSplitter.resplit(patch, OPTIONS, 0, w, reversed, 0, count));
        // a leaf missing in the middle
        float[] gap = java.util.Arrays.copyOf(boxes, boxes.length);
        System.arraycopy(boxes, 4 * (count / 2 + 1), gap, 4 * (count / 2), 4 * (count - count / 2 - 1));
        assertNull(PatchSplitter.resplit(patch, OPTIONS, 0, w, gap, 0, count - 1));
        // a trimmed patch is split afresh
        TrimRegion region = new TrimRegion(List.of(TrimShapes.circle(0.5, 0.5, 0.35, true)), List.of());
        BezierPatch trimmed = new BezierPatch(3, 3, wavy(4, 1).copyNet(), null, new PatchDomain(0, 1, 0, 1, region), null);
        assertNull(PatchSplitter.resplit(trimmed, OPTIONS, 0, w, boxes, 0, count));
        // and the intact boxes still replay
        assertNotNull(PatchSplitter.resplit(patch, OPTIONS, 0, w, boxes, 0, count));
    }

    /** The pieces tile the square and each is {@code patch} restricted to its box. */
    private static void assertPiecesOf(BezierPatch patch, PatchPieces pieces, String where) {
        int n = patch.degreeU(), m = patch.degreeV();
        double[] net = patch.copyNet();
        double tol = ROUNDING * TestNets.size(net, 0, net.length);
        double area = 0;
        double[] expected = new double[pieces.netLength()];
        for (int p = 0; p < pieces.count(); p++) {
            double u0 = pieces.boxes()[4 * p], u1 = pieces.boxes()[4 * p + 1];
            double v0 = pieces.boxes()[4 * p + 2], v1 = pieces.boxes()[4 * p + 3];
            area += (u1 - u0) * (v1 - v0);
            DeCasteljau.subPatch(net, 0, n, m, 3, u0, u1, v0, v1, expected, 0);
            for (int k = 0; k < expected.length; k++) {
                assertEquals(expected[k], pieces.nets()[p * pieces.netLength() + k], tol, "piece " + p + ": " + where);
            }
        }
        assertEquals(1, area, 0, "the pieces tile the square: " + where);
    }
}
