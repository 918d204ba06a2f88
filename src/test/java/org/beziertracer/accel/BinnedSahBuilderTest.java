package org.beziertracer.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.math.Aabb;
import org.junit.jupiter.api.Test;

/** Structure of trees built by {@link BinnedSahBuilder} (through {@link Bvh#build}). */
class BinnedSahBuilderTest {

    /**
     * Walks the tree and checks: every node reached once, children adjacent and inside their parent,
     * leaves non-empty and at most {@code maxLeafSize}, each leaf box the union of its primitives'
     * boxes rounded outward to floats (so it contains their double boxes),
     * every primitive in exactly one leaf, node count {@code 2 * leaves - 1}, depth as reported.
     */
    static void checkStructure(Bvh bvh, double[] bounds, int n, int maxLeafSize, String in) {
        assertEquals(n, bvh.primCount(), in);
        int[] seen = new int[n];
        int[] nodes = new int[bvh.nodeCount()], levels = new int[bvh.nodeCount()];
        int sp = 0, visited = 0, leaves = 0, depth = 0;
        nodes[sp] = 0;
        levels[sp++] = 1;
        while (sp > 0) {
            int node = nodes[--sp], level = levels[sp];
            visited++;
            depth = Math.max(depth, level);
            Aabb box = bvh.nodeBounds(node);
            if (bvh.isLeaf(node)) {
                leaves++;
                int k = bvh.leafPrimCount(node), first = bvh.nodeLeftFirst(node);
                assertTrue(k >= 1 && k <= maxLeafSize, in + ": leaf " + node + " holds " + k);
                Aabb union = Aabb.EMPTY;
                for (int s = first; s < first + k; s++) {
                    int p = bvh.primIndex(s);
                    seen[p]++;
                    union = union.union(rounded(prim(bounds, p)));
                    assertTrue(contains(box, prim(bounds, p)), in + ": leaf " + node + " does not contain prim " + p);
                }
                assertEquals(union, box, in + ": leaf " + node + " box is not the union of its prims");
            } else {
                int left = bvh.nodeLeftFirst(node);
                assertTrue(left > node && left + 1 < bvh.nodeCount(), in + ": node " + node + " child " + left);
                Aabb union = bvh.nodeBounds(left).union(bvh.nodeBounds(left + 1));
                assertEquals(union, box, in + ": node " + node + " box is not the union of its children");
                nodes[sp] = left;
                levels[sp++] = level + 1;
                nodes[sp] = left + 1;
                levels[sp++] = level + 1;
            }
        }
        for (int p = 0; p < n; p++) {
            assertEquals(1, seen[p], in + ": prim " + p + " occurrences in leaves");
        }
        assertEquals(bvh.nodeCount(), visited, in + ": nodes reached");
        assertEquals(2 * leaves - 1, bvh.nodeCount(), in + ": binary tree node count");
        assertEquals(depth, bvh.depth(), in + ": depth");
    }

    /**
     * The conservative property alone (after a partial refit, which may leave boxes larger than
     * needed): every primitive's box inside its leaf's, every child's inside its parent's.
     */
    static void checkContainment(Bvh bvh, double[] bounds, int n, String in) {
        int[] seen = new int[n];
        for (int node = 0; node < bvh.nodeCount(); node++) {
            Aabb box = bvh.nodeBounds(node);
            int first = bvh.nodeLeftFirst(node);
            if (bvh.isLeaf(node)) {
                for (int s = first; s < first + bvh.leafPrimCount(node); s++) {
                    int p = bvh.primIndex(s);
                    seen[p]++;
                    assertTrue(contains(box, prim(bounds, p)), in + ": leaf " + node + " does not contain prim " + p);
                }
            } else {
                assertTrue(contains(box, bvh.nodeBounds(first)) && contains(box, bvh.nodeBounds(first + 1)),
                        in + ": node " + node + " does not contain its children");
            }
        }
        for (int p = 0; p < n; p++) {
            assertEquals(1, seen[p], in + ": prim " + p + " occurrences in leaves");
        }
    }

    /** The box rounded outward to floats, as the hierarchy stores it. */
    static Aabb rounded(Aabb b) {
        return new Aabb(RayBox.down(b.minX()), RayBox.down(b.minY()), RayBox.down(b.minZ()), RayBox.up(b.maxX()),
                RayBox.up(b.maxY()), RayBox.up(b.maxZ()));
    }

    static boolean contains(Aabb outer, Aabb inner) {
        return outer.minX() <= inner.minX() && outer.minY() <= inner.minY() && outer.minZ() <= inner.minZ()
                && outer.maxX() >= inner.maxX() && outer.maxY() >= inner.maxY() && outer.maxZ() >= inner.maxZ();
    }

    static Aabb prim(double[] b, int p) {
        int o = 6 * p;
        return new Aabb(b[o], b[o + 1], b[o + 2], b[o + 3], b[o + 4], b[o + 5]);
    }

    @Test
    void randomBoxesGiveAWellFormedShallowTree() {
        Random rnd = new Random(2024);
        for (int n : new int[] {1, 2, 7, 100, 1000, 10_000}) {
            for (BvhOptions opts : new BvhOptions[] {BvhOptions.defaults(), new BvhOptions(1, 12),
                    new BvhOptions(8, 2)}) {
                double[] bounds = BoxScene.randomBoxes(rnd, n);
                Bvh bvh = Bvh.build(bounds, n, opts);
                String in = "n=" + n + " " + opts;
                checkStructure(bvh, bounds, n, opts.maxLeafSize(), in);
                int log2 = 32 - Integer.numberOfLeadingZeros(n);
                assertTrue(bvh.depth() <= 3 * log2 + 2, in + ": depth " + bvh.depth());
                assertTrue(contains(bvh.bounds(), prim(bounds, 0)), in);
            }
        }
    }

    /**
     * Two thin layers of small boxes, 10 apart in y, each spread 100 wide in x: the widest centroid
     * axis is x, but the cheap root split separates the layers along y. A build of up to
     * {@link BinnedSahBuilder#ALL_AXES_PRIMS} primitives bins every axis and finds it (the root's
     * children do not overlap in y); a bigger build bins the widest axis only and splits in x.
     */
    @Test
    void smallBuildsBinEveryAxisAndBigOnesTheWidest() {
        for (int n : new int[] {64, 1000, BinnedSahBuilder.ALL_AXES_PRIMS, BinnedSahBuilder.ALL_AXES_PRIMS + 2}) {
            Random rnd = new Random(n);
            double[] bounds = new double[6 * n];
            for (int p = 0; p < n; p++) {
                double x = 100 * rnd.nextDouble(), y = (p % 2) * 10 + 0.1 * rnd.nextDouble(), z = rnd.nextDouble();
                double[] box = {x, y, z, x + 0.01, y + 0.01, z + 0.01};
                System.arraycopy(box, 0, bounds, 6 * p, 6);
            }
            Bvh bvh = Bvh.build(bounds, n, BvhOptions.defaults());
            int left = bvh.nodeLeftFirst(0);
            Aabb a = bvh.nodeBounds(left), b = bvh.nodeBounds(left + 1);
            boolean apartInY = a.max().y() < b.min().y() || b.max().y() < a.min().y();
            assertEquals(n <= BinnedSahBuilder.ALL_AXES_PRIMS, apartInY, n + " boxes: root children " + a + " and " + b);
        }
    }

    @Test
    void onePrimitiveIsASingleLeaf() {
        double[] bounds = {1, 2, 3, 4, 5, 6};
        Bvh bvh = Bvh.build(bounds, 1, BvhOptions.defaults());
        checkStructure(bvh, bounds, 1, 1, "one prim");
        assertEquals(1, bvh.nodeCount());
        assertEquals(1, bvh.depth());
        assertEquals(new Aabb(1, 2, 3, 4, 5, 6), bvh.bounds());
    }

    @Test
    void zeroPrimitivesGiveAnEmptyTree() {
        Bvh bvh = Bvh.build(new double[0], 0, BvhOptions.defaults());
        assertEquals(0, bvh.primCount());
        assertEquals(Aabb.EMPTY, bvh.bounds());
        assertTrue(bvh.isLeaf(0));
    }

    @Test
    void identicalBoxesFallBackToMedianSplitsAndStayBalanced() {
        for (int n : new int[] {2, 5, 4096, 100_000}) {
            for (int maxLeaf : new int[] {1, 4}) {
                double[] bounds = BoxScene.identicalBoxes(n);
                Bvh bvh = Bvh.build(bounds, n, new BvhOptions(maxLeaf, 16));
                String in = "n=" + n + " maxLeaf=" + maxLeaf;
                checkStructure(bvh, bounds, n, maxLeaf, in);
                int balanced = 1 + (int) Math.ceil(Math.log((double) n / maxLeaf) / Math.log(2));
                assertTrue(bvh.depth() <= Math.max(1, balanced), in + ": depth " + bvh.depth());
            }
        }
    }

    @Test
    void nestedBoxesWithOneCentreAndPointBoxesBuild() {
        int n = 1000;
        double[] bounds = new double[6 * n];
        for (int p = 0; p < n; p++) {
            double h = p % 2 == 0 ? p : 0; // every other box is the point (0, 0, 0)
            for (int a = 0; a < 3; a++) {
                bounds[6 * p + a] = -h;
                bounds[6 * p + 3 + a] = h;
            }
        }
        Bvh bvh = Bvh.build(bounds, n, BvhOptions.defaults());
        checkStructure(bvh, bounds, n, 4, "nested");
    }

    @Test
    void exponentiallySpreadBoxesDoNotOverflowTheJavaStack() {
        int n = 20_000;
        double[] bounds = new double[6 * n];
        for (int p = 0; p < n; p++) {
            double x = Math.pow(1.1, p % 7000) * (p / 7000 + 1);
            bounds[6 * p] = bounds[6 * p + 3] = x;
        }
        Bvh bvh = Bvh.build(bounds, n, BvhOptions.defaults());
        checkStructure(bvh, bounds, n, 4, "exponential");
    }

    @Test
    void badBoxesAreRejectedWithThePrimitiveNamed() {
        double[] bounds = {0, 0, 0, 1, 1, 1, 0, 2, 0, 1, 1, 1};
        String e = UserMessages.of(IllegalArgumentException.class,
                () -> Bvh.build(bounds, 2, BvhOptions.defaults()));
        assertTrue(e.contains("primitive 1"), e);
        UserMessages.of(IllegalArgumentException.class, () -> Bvh.build(new double[] {Double.NaN, 0, 0, 1, 1, 1}, 1));
        UserMessages.of(IllegalArgumentException.class, () -> Bvh.build(new double[6], 2));
    }

    /** Prints build times (best of several runs, after warm-up); a report, not a timed assertion. */
    @Test
    void buildTimesAreReportedFor512And51200Boxes() {
        Random rnd = new Random(5);
        for (int n : new int[] {512, 51_200}) {
            double[] bounds = BoxScene.randomBoxes(rnd, n);
            double best = Double.POSITIVE_INFINITY, refit = Double.POSITIVE_INFINITY;
            Bvh bvh = null;
            for (int run = 0; run < 8; run++) {
                bvh = Bvh.build(bounds, n, BvhOptions.defaults());
                best = Math.min(best, bvh.buildMillis());
                refit = Math.min(refit, bvh.refit(bounds).buildMillis());
            }
            System.out.printf(java.util.Locale.ROOT,
                    "BVH build %,d boxes: %.2f ms (refit %.2f ms), %d nodes, depth %d, SAH cost %.1f%n",
                    n, best, refit, bvh.nodeCount(), bvh.depth(), bvh.sahCost());
            checkStructure(bvh, bounds, n, 4, "timed n=" + n);
        }
    }
}
