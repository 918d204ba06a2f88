package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * Both builders ({@link BinnedSahBuilder}, {@link MortonBuilder}) built in parallel: the same arrays
 * as on one thread, well-formed trees, and closest hits equal to brute force on random boxes.
 */
class ParallelBuildTest {

    static final BvhOptions SAH = BvhOptions.defaults().withMortonPrims(Integer.MAX_VALUE);
    static final BvhOptions MORTON = BvhOptions.defaults().withMortonPrims(1);

    @Test
    void aParallelBuildGivesTheArraysOfASequentialOne() {
        Random rnd = new Random(31);
        int n = 6 * BvhBuild.PARALLEL_PRIMS + 17;
        double[] bounds = BoxScene.randomBoxes(rnd, n);
        for (boolean morton : new boolean[] {false, true}) {
            BvhOptions opts = morton ? MORTON : SAH;
            Bvh one = morton ? MortonBuilder.build(bounds, n, opts, false) : BinnedSahBuilder.build(bounds, n, opts, false);
            for (int run = 0; run < 3; run++) {
                Bvh many = Bvh.build(bounds, n, opts);
                String in = (morton ? "Morton" : "SAH") + " run " + run;
                assertArrayEquals(one.nodesCopy(), many.nodesCopy(), in + ": nodes");
                assertArrayEquals(one.nodeBoundsCopy(), many.nodeBoundsCopy(), in + ": node boxes");
                assertArrayEquals(one.primIndices(), many.primIndices(), in + ": leaf order");
                assertEquals(one.depth(), many.depth(), in);
            }
        }
    }

    @Test
    void parallelBuildsAreWellFormedAndAnswerLikeBruteForce() {
        Random rnd = new Random(32);
        for (int n : new int[] {1, 2, 7, 1000, 3 * BvhBuild.PARALLEL_PRIMS, 100_000}) {
            double[] bounds = BoxScene.randomBoxes(rnd, n);
            for (BvhOptions opts : new BvhOptions[] {SAH, MORTON, new BvhOptions(3, 8, 1)}) {
                Bvh bvh = Bvh.build(bounds, n, opts);
                String in = "n=" + n + " " + opts;
                BinnedSahBuilderTest.checkStructure(bvh, bounds, n, opts.maxLeafSize(), in);
                BvhTest.checkQueries(bvh, new BoxScene(bounds, n), rnd, in);
            }
        }
    }

    @Test
    void mortonBuildsOfDegenerateInputsAreWellFormed() {
        int n = 5000;
        double[] nested = new double[6 * n], spread = new double[6 * n];
        for (int p = 0; p < n; p++) {
            double h = p % 2 == 0 ? p : 0;
            double x = Math.pow(1.1, p % 3000) * (p / 3000 + 1);
            for (int a = 0; a < 3; a++) {
                nested[6 * p + a] = -h;
                nested[6 * p + 3 + a] = h;
            }
            spread[6 * p] = spread[6 * p + 3] = x;
        }
        for (int maxLeaf : new int[] {1, 4}) {
            BvhOptions opts = new BvhOptions(maxLeaf, 16, 1);
            BinnedSahBuilderTest.checkStructure(Bvh.build(BoxScene.identicalBoxes(n), n, opts),
                    BoxScene.identicalBoxes(n), n, maxLeaf, "identical, leaf " + maxLeaf);
            BinnedSahBuilderTest.checkStructure(Bvh.build(nested, n, opts), nested, n, maxLeaf, "nested");
            Bvh bvh = Bvh.build(spread, n, opts);
            BinnedSahBuilderTest.checkStructure(bvh, spread, n, maxLeaf, "exponential");
            assertTrue(bvh.depth() <= 64 + 13, "depth " + bvh.depth());
        }
    }

    @Test
    void theRadixSortSortsLikeArraysSortAndCarriesTheValues() {
        Random rnd = new Random(33);
        for (int n : new int[] {1, 2, 100, 50_000}) {
            long[] keys = new long[n];
            int[] values = new int[n];
            for (int i = 0; i < n; i++) {
                keys[i] = rnd.nextInt(4) == 0 ? keys[rnd.nextInt(i + 1)] : rnd.nextLong() >>> 1;
                values[i] = i;
            }
            long[] original = keys.clone();
            long[] expected = keys.clone();
            java.util.Arrays.sort(expected);
            MortonBuilder.sort(keys, values);
            assertArrayEquals(expected, keys, "n=" + n);
            for (int i = 0; i < n; i++) {
                assertEquals(original[values[i]], keys[i], "value carried at " + i);
                if (i > 0 && keys[i] == keys[i - 1]) {
                    assertTrue(values[i] > values[i - 1], "stable at " + i);
                }
            }
        }
    }

    @Test
    void spreadPutsBitIAtBit3I() {
        Random rnd = new Random(34);
        for (int t = 0; t < 1000; t++) {
            long x = rnd.nextInt(1 << MortonBuilder.BITS);
            long s = MortonBuilder.spread(x);
            for (int i = 0; i < 63; i++) {
                long expected = i % 3 == 0 ? (x >>> (i / 3)) & 1 : 0;
                assertEquals(expected, (s >>> i) & 1, "x=" + x + " bit " + i);
            }
        }
    }
}
