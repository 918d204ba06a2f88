package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.beziertracer.UserMessages;
import org.junit.jupiter.api.Test;

/** The two-level build of {@link Bvh#build(double[], int, int[], BvhOptions)} ({@link GroupedBuilder}). */
class GroupedBuilderTest {

    /** Group starts of random sizes 0..{@code maxSize} (some empty) covering {@code n} primitives. */
    static int[] randomGroups(Random rnd, int n, int maxSize) {
        java.util.List<Integer> starts = new java.util.ArrayList<>();
        int p = 0;
        while (p < n) {
            starts.add(p);
            p = Math.min(n, p + (rnd.nextInt(8) == 0 ? 0 : 1 + rnd.nextInt(maxSize)));
        }
        starts.add(n);
        return starts.stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * Boxes whose groups are clusters, as a patch's sub-patches are: each group's boxes lie around
     * its own random centre (the first groups' clusters overlap others'), mixed with {@link
     * BoxScene#randomBoxes}' flat, point and duplicate boxes.
     */
    static double[] clusteredBoxes(Random rnd, int[] groupFirst) {
        int n = groupFirst[groupFirst.length - 1];
        double[] b = BoxScene.randomBoxes(rnd, n);
        for (int j = 0; j + 1 < groupFirst.length; j++) {
            double[] centre = {-8 + 16 * rnd.nextDouble(), -8 + 16 * rnd.nextDouble(), -8 + 16 * rnd.nextDouble()};
            double spread = 0.05 + 2 * rnd.nextDouble();
            for (int p = groupFirst[j]; p < groupFirst[j + 1]; p++) {
                for (int a = 0; a < 3; a++) {
                    double c = 0.5 * (b[6 * p + a] + b[6 * p + 3 + a]), half = 0.5 * (b[6 * p + 3 + a] - b[6 * p + a]);
                    double moved = centre[a] + spread * c / 10;
                    b[6 * p + a] = moved - 0.2 * half;
                    b[6 * p + 3 + a] = moved + 0.2 * half;
                }
            }
        }
        return b;
    }

    @Test
    void groupedTreesAreWellFormedAndAnswerLikeBruteForce() {
        Random rnd = new Random(31);
        for (int n : new int[] {1, 2, 9, 500, 20_000}) {
            for (int maxSize : new int[] {1, 6, 60}) {
                int[] groups = randomGroups(rnd, n, maxSize);
                double[] bounds = rnd.nextBoolean() ? clusteredBoxes(rnd, groups) : BoxScene.randomBoxes(rnd, n);
                for (BvhOptions opts : new BvhOptions[] {BvhOptions.defaults(), BvhOptions.defaults().withMortonPrims(1)}) {
                    String in = "n=" + n + " groups=" + (groups.length - 1) + " " + opts;
                    Bvh bvh = Bvh.build(bounds, n, groups, opts);
                    BinnedSahBuilderTest.checkStructure(bvh, bounds, n, 1, in);
                    BvhTest.checkQueries(bvh, new BoxScene(bounds, n), rnd, in);
                }
            }
        }
    }

    @Test
    void eachGroupKeepsItsPlaceInTheLeafOrderAndItsOwnSubtree() {
        Random rnd = new Random(5);
        int n = 5000;
        int[] groups = randomGroups(rnd, n, 40);
        double[] bounds = clusteredBoxes(rnd, groups);
        Bvh bvh = Bvh.build(bounds, n, groups, BvhOptions.defaults());
        for (int j = 0; j + 1 < groups.length; j++) {
            for (int s = groups[j]; s < groups[j + 1]; s++) {
                int p = bvh.primIndex(s);
                assertTrue(p >= groups[j] && p < groups[j + 1], "slot " + s + " of group " + j + " holds " + p);
            }
        }
        // Every group of two or more is one subtree: some node holds exactly its primitives
        // (children follow their parent, so a backward sweep sees the children first)
        int[] lo = new int[bvh.nodeCount()], hi = new int[bvh.nodeCount()], count = new int[bvh.nodeCount()];
        for (int node = bvh.nodeCount() - 1; node >= 0; node--) {
            int first = bvh.nodeLeftFirst(node);
            if (bvh.isLeaf(node)) {
                lo[node] = first;
                hi[node] = first + bvh.leafPrimCount(node);
                count[node] = bvh.leafPrimCount(node);
            } else {
                lo[node] = Math.min(lo[first], lo[first + 1]);
                hi[node] = Math.max(hi[first], hi[first + 1]);
                count[node] = count[first] + count[first + 1];
            }
        }
        for (int j = 0; j + 1 < groups.length; j++) {
            int a = groups[j], b = groups[j + 1];
            boolean found = b - a < 2;
            for (int node = 0; node < bvh.nodeCount() && !found; node++) {
                found = lo[node] == a && hi[node] == b && count[node] == b - a;
            }
            assertTrue(found, "no node holds exactly group " + j + " (" + a + ".." + (b - 1) + ")");
        }
    }

    @Test
    void theBuildIsTheSameEveryTimeAndARefitAnswersLikeARebuild() {
        Random rnd = new Random(12);
        int n = 30_000;
        int[] groups = randomGroups(rnd, n, 50);
        double[] bounds = clusteredBoxes(rnd, groups);
        Bvh a = Bvh.build(bounds, n, groups, BvhOptions.defaults());
        Bvh b = Bvh.build(bounds, n, groups, BvhOptions.defaults());
        assertArrayEquals(a.nodeBoundsCopy(), b.nodeBoundsCopy());
        assertArrayEquals(a.nodesCopy(), b.nodesCopy());
        assertArrayEquals(a.primIndices(), b.primIndices());
        int g = 1 + rnd.nextInt(groups.length - 2);
        int first = groups[g], count = Math.max(1, groups[g + 1] - first);
        double[] moved = bounds.clone();
        for (int p = first; p < first + count; p++) {
            for (int k = 0; k < 6; k++) {
                moved[6 * p + k] += 3 + (k >= 3 ? 0.5 : 0);
            }
        }
        Bvh refit = a.refit(Arrays.copyOfRange(moved, 6 * first, 6 * (first + count)), first, count);
        BinnedSahBuilderTest.checkContainment(refit, moved, n, "refit");
        BvhTest.checkQueries(refit, new BoxScene(moved, n), rnd, "refit of group " + g);
    }

    @Test
    void groupsThatDoNotCoverThePrimitivesInOrderAreRefused() {
        double[] bounds = BoxScene.randomBoxes(new Random(1), 10);
        BvhOptions opts = BvhOptions.defaults();
        UserMessages.of(IllegalArgumentException.class, () -> Bvh.build(bounds, 10, new int[] {0, 5, 9}, opts));
        UserMessages.of(IllegalArgumentException.class, () -> Bvh.build(bounds, 10, new int[] {1, 5, 10}, opts));
        UserMessages.of(IllegalArgumentException.class, () -> Bvh.build(bounds, 10, new int[] {0, 6, 5, 10}, opts));
        UserMessages.of(IllegalArgumentException.class, () -> Bvh.build(bounds, 10, new int[] {10}, opts));
        assertEquals(0, Bvh.build(new double[0], 0, new int[] {0, 0}, opts).primCount());
    }

    @Test
    void onlyBigScenesOfSeveralPrimitivesAPatchAreBuiltInTwoLevels() {
        assertTrue(BvhOptions.groupsPay(BvhOptions.GROUPED_PRIMS, BvhOptions.GROUPED_PRIMS / 4));
        assertFalse(BvhOptions.groupsPay(BvhOptions.GROUPED_PRIMS - 1, 100));
        assertFalse(BvhOptions.groupsPay(BvhOptions.GROUPED_PRIMS, BvhOptions.GROUPED_PRIMS / 4 + 1));
        assertFalse(BvhOptions.groupsPay(1 << 20, 1 << 20));
        assertFalse(BvhOptions.groupsPay(1 << 20, 0), "no patches: nothing to group by");
    }
}
