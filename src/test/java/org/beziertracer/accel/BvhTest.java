package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.function.Supplier;

import org.beziertracer.UserMessages;
import org.beziertracer.math.Aabb;
import org.junit.jupiter.api.Test;

/** Queries and refit of {@link Bvh}; structure is covered by {@link BinnedSahBuilderTest}. */
class BvhTest {

    private static final int RAYS = 2000;

    /**
     * For {@code RAYS} random rays: closestHit equals the brute-force loop, the callback never ran
     * for a primitive twice, occluded agrees with closestHit, and the stack was big enough.
     */
    static void checkQueries(Accelerator acc, BoxScene scene, Random rnd, String in) {
        int[] stack = acc.newStack();
        int hits = 0;
        for (int r = 0; r < RAYS; r++) {
            scene.randomRay(rnd);
            double tMax = rnd.nextInt(3) == 0 ? 5 + 20 * rnd.nextDouble() : Double.POSITIVE_INFINITY;
            int rayIndex = r;
            double tMaxIn = tMax;
            Supplier<String> ray = () -> in + ", ray " + rayIndex + ": " + scene.ray() + " tMax=" + tMaxIn;
            double expected = scene.bruteForce(tMax);
            scene.resetCalls();
            double got = acc.closestHit(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                    scene.invDz, scene.tMin, tMax, scene, scene, stack);
            assertEquals(expected, got, 0, ray);
            assertEquals(-1, scene.calledTwice, () -> ray.get() + ": a prim was called twice");
            if (got < tMax) {
                hits++;
                assertEquals(got, scene.entry(scene.closestPrim, tMax), 0, () -> ray.get() + ": recorded prim");
            }
            boolean occluded = acc.occluded(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                    scene.invDz, scene.tMin, tMax, scene, scene, stack);
            assertEquals(got < tMax, occluded, () -> ray.get() + ": occluded vs closestHit " + got);
        }
        if (scene.primCount >= 100) {
            assertTrue(hits > RAYS / 20, in + ": too few hits to mean anything: " + hits);
        }
    }

    @Test
    void closestHitAndOccludedMatchBruteForceOnRandomBoxesAndRays() {
        Random rnd = new Random(7);
        for (int n : new int[] {1, 2, 7, 1000, 10_000}) {
            for (BvhOptions opts : new BvhOptions[] {BvhOptions.defaults(), new BvhOptions(1, 12)}) {
                double[] bounds = BoxScene.randomBoxes(rnd, n);
                Bvh bvh = Bvh.build(bounds, n, opts);
                checkQueries(bvh, new BoxScene(bounds, n), rnd, "n=" + n + " " + opts);
            }
        }
    }

    @Test
    void identicalBoxesAreAnsweredLikeBruteForce() {
        Random rnd = new Random(8);
        double[] bounds = BoxScene.identicalBoxes(500);
        checkQueries(Bvh.build(bounds, 500), new BoxScene(bounds, 500), rnd, "identical");
    }

    @Test
    void aDeepListLikeTreeIsAnsweredWithinItsStackSize() {
        // Boxes along a line at exponentially growing positions give a deep, unbalanced tree
        int n = 400;
        double[] bounds = new double[6 * n];
        for (int p = 0; p < n; p++) {
            double x = Math.pow(1.5, p % 200) * (p / 200 + 1);
            double[] box = {x, -1, -1, x + 0.5, 1, 1};
            System.arraycopy(box, 0, bounds, 6 * p, 6);
        }
        Bvh bvh = Bvh.build(bounds, n, new BvhOptions(1, 16));
        assertTrue(bvh.depth() > 2 * 9, "expected an unbalanced tree, depth " + bvh.depth());
        Accelerator acc = bvh;
        checkQueries(acc, new BoxScene(bounds, n), new Random(13), "deep, depth " + bvh.depth());
    }

    @Test
    void anEmptyTreeMissesEveryRay() {
        Bvh bvh = Bvh.build(new double[0], 0);
        LeafIntersector<Object> never = (q, p, t) -> { throw new AssertionError("called for " + p); };
        assertEquals(7.0, bvh.closestHit(0, 0, 0, 1, 1, 1, 0, 7.0, never, null, bvh.newStack()), 0);
        assertFalse(bvh.occluded(0, 0, 0, 1, 1, 1, 0, 7.0, (q, p, t) -> true, null, bvh.newStack()));
    }

    @Test
    void nearChildrenAreVisitedFirstSoFarBoxesAreCulled() {
        // 1000 unit boxes on a line along x; a ray down the line hits box 0 first
        int n = 1000;
        double[] bounds = new double[6 * n];
        for (int p = 0; p < n; p++) {
            double[] box = {2 * p, 0, 0, 2 * p + 1, 1, 1};
            System.arraycopy(box, 0, bounds, 6 * p, 6);
        }
        BoxScene scene = new BoxScene(bounds, n);
        scene.setRay(-1, 0.5, 0.5, 1, 0, 0, 0);
        Bvh bvh = Bvh.build(bounds, n);
        double t = bvh.closestHit(scene.ox, scene.oy, scene.oz, scene.invDx, scene.invDy,
                scene.invDz, 0, Double.POSITIVE_INFINITY, scene, scene, bvh.newStack());
        assertEquals(1.0, t, 0);
        assertTrue(scene.calledCount <= 2 * BvhOptions.defaults().maxLeafSize(),
                "callbacks: " + scene.calledCount);
    }

    @Test
    void refitAfterMovingBoxesMatchesBruteForceAndLeavesTheOldTreeAlone() {
        Random rnd = new Random(9);
        for (int n : new int[] {1, 7, 1000, 10_000}) {
            double[] bounds = BoxScene.randomBoxes(rnd, n);
            Bvh old = Bvh.build(bounds, n);
            Aabb[] oldBoxes = new Aabb[old.nodeCount()];
            for (int i = 0; i < oldBoxes.length; i++) {
                oldBoxes[i] = old.nodeBounds(i);
            }
            double[] moved = bounds.clone();
            for (int p = 0; p < n; p++) {
                if (p == 0 || rnd.nextInt(10) == 0) {
                    for (int a = 0; a < 3; a++) {
                        double d = 4 * rnd.nextGaussian(), grow = rnd.nextDouble();
                        moved[6 * p + a] += d - grow;
                        moved[6 * p + 3 + a] += d + grow;
                    }
                }
            }
            Bvh refit = old.refit(moved);
            String in = "n=" + n;
            assertNotSame(old, refit);
            assertEquals(old.nodeCount(), refit.nodeCount(), in);
            assertEquals(old.depth(), refit.depth(), in);
            BinnedSahBuilderTest.checkStructure(refit, moved, n, 4, in + " refit");
            checkQueries(refit, new BoxScene(moved, n), rnd, in + " refit");
            for (int i = 0; i < oldBoxes.length; i++) {
                assertEquals(oldBoxes[i], old.nodeBounds(i), in + ": old node " + i + " changed");
            }
            checkQueries(old, new BoxScene(bounds, n), rnd, in + " old after refit");
        }
    }

    @Test
    void aRefitOfSomePrimitivesEqualsAFullRefitAndAnswersLikeARebuild() {
        Random rnd = new Random(19);
        for (int n : new int[] {1, 50, 5000, 20_000}) {
            for (BvhOptions opts : new BvhOptions[] {new BvhOptions(1, 16), new BvhOptions(4, 16, 1),
                    new BvhOptions(8, 4)}) {
                double[] bounds = BoxScene.randomBoxes(rnd, n);
                Bvh old = Bvh.build(bounds, n, opts);
                int first = rnd.nextInt(n), count = 1 + rnd.nextInt(Math.min(64, n - first));
                double[] moved = bounds.clone();
                for (int p = first; p < first + count; p++) {
                    for (int a = 0; a < 3; a++) {
                        double d = 6 * rnd.nextGaussian();
                        moved[6 * p + a] += d;
                        moved[6 * p + 3 + a] += d + rnd.nextDouble();
                    }
                }
                String in = "n=" + n + " " + opts + " moved " + first + "+" + count;
                double[] range = java.util.Arrays.copyOfRange(moved, 6 * first, 6 * (first + count));
                Bvh part = old.refit(range, first, count), full = old.refit(moved);
                if (opts.maxLeafSize() == 1 || (opts.mortonPrims() == 1 && !hasEqualCentres(bounds))) {
                    // single-primitive leaves: exactly the full refit
                    assertArrayEquals(full.nodeBoundsCopy(), part.nodeBoundsCopy(), in);
                }
                BinnedSahBuilderTest.checkContainment(part, moved, n, in);
                checkQueries(part, new BoxScene(moved, n), rnd, in + " refit");
                checkQueries(Bvh.build(moved, n, opts), new BoxScene(moved, n), rnd, in + " rebuild");
            }
        }
    }

    /** True when two boxes have the same centre (a Morton leaf may then hold both). */
    static boolean hasEqualCentres(double[] b) {
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (int p = 0; p < b.length / 6; p++) {
            if (!seen.add((b[6 * p] + b[6 * p + 3]) + "," + (b[6 * p + 1] + b[6 * p + 4]) + "," + (b[6 * p + 2] + b[6 * p + 5]))) {
                return true;
            }
        }
        return false;
    }

    @Test
    void aRefitRangeOutsideThePrimitivesIsRefused() {
        Bvh bvh = Bvh.build(BoxScene.randomBoxes(new Random(20), 10), 10);
        double[] bounds = BoxScene.randomBoxes(new Random(21), 10);
        UserMessages.of(IllegalArgumentException.class, () -> bvh.refit(bounds, 8, 3));
        UserMessages.of(IllegalArgumentException.class, () -> bvh.refit(bounds, -1, 1));
        UserMessages.of(IllegalArgumentException.class, () -> bvh.refit(new double[6], 2, 2));
    }

    @Test
    void bytesCountTheNodesAndTheLeafOrder() {
        int n = 1000;
        Bvh bvh = Bvh.build(BoxScene.randomBoxes(new Random(22), n), n);
        long expected = (16 + 4L * 6 * bvh.nodeCount()) + (16 + 4L * 2 * bvh.nodeCount()) + (16 + 4L * n);
        assertEquals(expected, bvh.bytes(), 8 * 3);
        assertTrue(bvh.bytes() <= Bvh.estimateBytes(n), "retained within the build estimate");
    }

    @Test
    void primIndicesIsACopyInLeafOrder() {
        double[] bounds = BoxScene.randomBoxes(new Random(10), 50);
        Bvh bvh = Bvh.build(bounds, 50);
        int[] copy = bvh.primIndices();
        copy[0] = -1;
        assertTrue(bvh.primIndex(0) >= 0, "primIndices() must not expose the internal array");
        int[] sorted = bvh.primIndices();
        java.util.Arrays.sort(sorted);
        for (int p = 0; p < 50; p++) {
            assertEquals(p, sorted[p], "primIndices is a permutation");
        }
    }

    @Test
    void theStackHoldsTwoIntsPerLevel() {
        Bvh bvh = Bvh.build(BoxScene.randomBoxes(new Random(12), 300), 300);
        assertEquals(2 * bvh.depth(), bvh.stackSize());
        assertEquals(bvh.stackSize(), bvh.newStack().length);
    }
}
