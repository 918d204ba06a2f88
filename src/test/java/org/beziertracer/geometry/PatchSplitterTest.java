package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/**
 * {@link PatchSplitter}: the pieces tile the parameter square with halvings, each piece is the
 * parent restricted to its box, and splitting stops exactly when a piece is flat enough or the
 * depth cap is reached.
 */
class PatchSplitterTest {

    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];

    static BezierPatch randomPatch(Random rnd) {
        int n = 1 + rnd.nextInt(7), m = 1 + rnd.nextInt(7);
        return new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, Math.pow(10, rnd.nextInt(5) - 2)));
    }

    @Test
    void piecesTileTheSquareAndReproduceTheParent() {
        Random rnd = new Random(2015);
        for (int trial = 0; trial < 200; trial++) {
            BezierPatch patch = randomPatch(rnd);
            int n = patch.degreeU(), m = patch.degreeV();
            SplitOptions options = new SplitOptions(true, 0.02 + 0.3 * rnd.nextDouble(), rnd.nextInt(9));
            PatchPieces pieces = PatchSplitter.split(patch, options);
            String where = "trial " + trial + " " + TestNets.degrees(n, m, 3) + " " + options;
            assertEquals(n, pieces.degreeU(), where);
            assertEquals(m, pieces.degreeV(), where);
            assertTrue(pieces.count() >= 1 && pieces.count() <= 1 << options.maxDepthFor(n, m),
                    pieces.count() + " pieces: " + where);
            double area = 0;
            double[] parentNet = patch.copyNet();
            double tol = ROUNDING * TestNets.size(parentNet, 0, parentNet.length);
            for (int p = 0; p < pieces.count(); p++) {
                double u0 = pieces.boxes()[4 * p], u1 = pieces.boxes()[4 * p + 1];
                double v0 = pieces.boxes()[4 * p + 2], v1 = pieces.boxes()[4 * p + 3];
                assertTrue(isHalving(u1 - u0) && isHalving(v1 - v0), "box widths are halvings: " + where);
                area += (u1 - u0) * (v1 - v0);
                for (int q = 0; q < p; q++) {
                    assertTrue(disjoint(pieces.boxes(), p, q), "pieces " + q + " and " + p + " overlap: " + where);
                }
                // The piece at its own (s,t) is the parent at the mapped (u,v)
                for (int k = 0; k < 4; k++) {
                    double s = rnd.nextDouble(), t = rnd.nextDouble();
                    double[] a = TestNets.eval(pieces.nets(), p * pieces.netLength(), n, m, 3, s, t);
                    double[] b = TestNets.eval(parentNet, 0, n, m, 3, u0 + s * (u1 - u0), v0 + t * (v1 - v0));
                    assertTrue(TestNets.maxDiff(a, b) <= tol, "piece " + p + " at (" + s + "," + t + ") off by "
                            + TestNets.maxDiff(a, b) + ": " + where);
                }
            }
            assertEquals(1, area, ROUNDING, "the boxes cover the square: " + where);
        }
    }

    private static boolean isHalving(double width) {
        double k = -Math.log(width) / Math.log(2);
        return width > 0 && k == Math.rint(k);
    }

    private static boolean disjoint(double[] boxes, int p, int q) {
        return boxes[4 * p + 1] <= boxes[4 * q] || boxes[4 * q + 1] <= boxes[4 * p]
                || boxes[4 * p + 3] <= boxes[4 * q + 2] || boxes[4 * q + 3] <= boxes[4 * p + 2];
    }

    @Test
    void aPieceIsSplitExactlyWhenItIsNotFlatAndAboveTheDepthCap() {
        Random rnd = new Random(2016);
        double[] box = new double[6];
        for (int trial = 0; trial < 200; trial++) {
            BezierPatch patch = randomPatch(rnd);
            int n = patch.degreeU(), m = patch.degreeV();
            SplitOptions options = new SplitOptions(true, 0.02 + 0.3 * rnd.nextDouble(), 1 + rnd.nextInt(8));
            PatchPieces pieces = PatchSplitter.split(patch, options);
            for (int p = 0; p < pieces.count(); p++) {
                int off = p * pieces.netLength();
                int depth = depth(pieces, p);
                double diagonal = diagonal(pieces, p, n, m);
                boolean flat = PatchSplitter.flatness(pieces.nets(), off, n, m) <= options.flatnessFor(n, m) * diagonal;
                String where = "trial " + trial + " piece " + p + " depth " + depth + " " + options;
                // past the base cap, only pieces near flat by the base tolerance are split on
                boolean baseLeaf = depth >= options.maxDepth() && !flatByBase(pieces, p, n, m, options);
                assertTrue(flat || baseLeaf || depth == options.maxDepthFor(n, m),
                        "a piece neither flat nor at the cap: " + where);
                assertTrue(depth <= options.maxDepthFor(n, m), where);
            }
            // The parent of each piece (its box doubled in the direction it was last halved) was not
            // flat: a flat patch is never split
            if (pieces.count() == 1) {
                continue;
            }
            double[] net = patch.copyNet();
            NetMeasures.controlBounds(net, 0, n, m, box);
            double diagonal = Math.sqrt(sq(box[3] - box[0]) + sq(box[4] - box[1]) + sq(box[5] - box[2]));
            assertTrue(PatchSplitter.flatness(net, 0, n, m) > options.flatnessFor(n, m) * diagonal,
                    "a flat patch was split: trial " + trial);
        }
    }

    /**
     * A bilinear patch is its own bilinear interpolation (flatness 0), so below bicubic the split
     * also counts the corner twist: a twisted unit square (a hyperbolic paraboloid) is split, a
     * plane parallelogram stays whole; the twist bounds the distance from
     * the corners' parallelogram. From degree 3 on, the measure is the plain flatness.
     */
    @Test
    void belowBicubicTheCornerTwistCountsAsNonFlat() {
        SplitOptions options = SplitOptions.defaults();
        double[] saddle = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5};
        assertTrue(PatchSplitter.split(new BezierPatch(1, 1, saddle), options).count() > 1, "twisted bilinear kept whole");
        double[] parallelogram = {0, 0, 0, 1, 0, 0.2, 0.3, 1, 0.1, 1.3, 1, 0.3};
        assertEquals(1, PatchSplitter.split(new BezierPatch(1, 1, parallelogram), options).count());
        assertEquals(0.125, PatchSplitter.flatness(saddle, 0, 1, 1), 1e-15);
        // Every point (u, v, uv/2) of the saddle lies within that bound of the corners' plane
        // through their centroid (0.5, 0.5, 0.125), normal (-0.25, -0.25, 1)
        double nl = Math.sqrt(0.0625 + 0.0625 + 1);
        for (int i = 0; i <= 10; i++) {
            for (int j = 0; j <= 10; j++) {
                double u = i / 10.0, v = j / 10.0;
                double d = Math.abs(-0.25 * (u - 0.5) - 0.25 * (v - 0.5) + (0.5 * u * v - 0.125)) / nl;
                assertTrue(d <= PatchSplitter.flatness(saddle, 0, 1, 1) + 1e-15, "(" + u + ", " + v + ") " + d);
            }
        }
        Random rnd = new Random(2019);
        for (int trial = 0; trial < 50; trial++) {
            int n = 3 + rnd.nextInt(5), m = 1 + rnd.nextInt(7);
            double[] net = TestNets.randomNet(rnd, n, m, 3, 1);
            assertEquals(NetMeasures.flatness(net, 0, n, m), PatchSplitter.flatness(net, 0, n, m), 0.0);
            assertEquals(NetMeasures.flatness(net, 0, m, n), PatchSplitter.flatness(net, 0, m, n), 0.0);
        }
    }

    private static double sq(double x) { return x * x; }

    /** The number of halvings that made piece {@code p} (its parameter box's area is 2^-depth). */
    private static int depth(PatchPieces pieces, int p) {
        double width = pieces.boxes()[4 * p + 1] - pieces.boxes()[4 * p];
        double height = pieces.boxes()[4 * p + 3] - pieces.boxes()[4 * p + 2];
        return (int) Math.round(-Math.log(width * height) / Math.log(2));
    }

    /** The diagonal of piece {@code p}'s control box. */
    private static double diagonal(PatchPieces pieces, int p, int n, int m) {
        double[] box = new double[6];
        NetMeasures.controlBounds(pieces.nets(), p * pieces.netLength(), n, m, box);
        return Math.sqrt(sq(box[3] - box[0]) + sq(box[4] - box[1]) + sq(box[5] - box[2]));
    }

    /**
     * True when piece {@code p} is within {@link PatchSplitter#PAST_CAP_FLATNESS} times the base
     * tolerance {@link SplitOptions#flatnessTolerance} of flat.
     */
    private static boolean flatByBase(PatchPieces pieces, int p, int n, int m, SplitOptions options) {
        return PatchSplitter.flatness(pieces.nets(), p * pieces.netLength(), n, m)
                <= PatchSplitter.PAST_CAP_FLATNESS * options.flatnessTolerance() * diagonal(pieces, p, n, m);
    }

    @Test
    void aNetFarFromFlatStaysNearTheBaseCapsPieceCountAtHighDegree() {
        Random rnd = new Random(2017);
        for (int trial = 0; trial < 20; trial++) {
            int n = 9 + rnd.nextInt(7), m = 9 + rnd.nextInt(7);
            BezierPatch patch = new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 10));
            PatchPieces pieces = PatchSplitter.split(patch, SplitOptions.defaults());
            // at most 8 times the base cap's 64, not 2^maxDepthFor = 1,024..4,096 (every piece split on)
            assertTrue(pieces.count() <= 8 << SplitOptions.defaults().maxDepth(),
                    pieces.count() + " pieces, trial " + trial + " degree " + n + "x" + m);
        }
    }

    @Test
    void theLongerControlPolygonIsHalvedFirst() {
        // 4 units long in u, 1 in v, bent in z so it is not flat: the first halving is in u
        double[] net = new double[3 * 3 * 3];
        for (int j = 0; j < 3; j++) {
            for (int i = 0; i < 3; i++) {
                int k = 3 * (j * 3 + i);
                net[k] = 2 * i;
                net[k + 1] = 0.5 * j;
                net[k + 2] = i == 1 ? 3 : 0;
            }
        }
        PatchPieces pieces = PatchSplitter.split(new BezierPatch(2, 2, net), new SplitOptions(true, 0.01, 1).forPatches(Integer.MAX_VALUE));
        assertEquals(2, pieces.count());
        assertArrayEquals(new double[] {0, 0.5, 0, 1, 0.5, 1, 0, 1}, Arrays.copyOf(pieces.boxes(), 8), 0);
    }

    @Test
    void disabledOrDepthZeroKeepsTheWholePatch() {
        BezierPatch patch = randomPatch(new Random(3));
        for (SplitOptions options : new SplitOptions[] {SplitOptions.wholePatches(), new SplitOptions(true, 1e-9, 0)}) {
            PatchPieces pieces = PatchSplitter.split(patch, options);
            assertEquals(1, pieces.count(), options.toString());
            assertArrayEquals(new double[] {0, 1, 0, 1}, pieces.boxes(), 0, options.toString());
            assertArrayEquals(patch.copyNet(), pieces.nets(), 0, options.toString());
        }
    }

    @Test
    void oneWorkspaceSplitsPatchAfterPatchAsFreshMemoryWould() {
        Random rnd = new Random(2018);
        TrimRegion region = new TrimRegion(List.of(TrimShapes.circle(0.5, 0.5, 0.35, true)), List.of());
        PatchSplitter.Workspace w = new PatchSplitter.Workspace();
        for (int trial = 0; trial < 60; trial++) {
            // degrees up and down, so the kept nets are sometimes longer than the patch needs
            int n = 1 + rnd.nextInt(trial % 3 == 0 ? 9 : 4), m = 1 + rnd.nextInt(4);
            double[] weights = null;
            if (rnd.nextInt(3) == 0) {
                weights = new double[(n + 1) * (m + 1)];
                for (int k = 0; k < weights.length; k++) {
                    weights[k] = 0.3 + 3 * rnd.nextDouble();
                }
            }
            PatchDomain domain = rnd.nextInt(4) == 0 ? new PatchDomain(0, 1, 0, 1, region) : null;
            BezierPatch p = new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 5), weights, domain, null);
            TrimCurves trim = p.trim() == null ? null : TrimCurves.of(p.trim());
            double minSize = rnd.nextInt(4) == 0 ? 2 : 0;
            PatchPieces fresh = PatchSplitter.split(p, SplitOptions.defaults(), trim, minSize);
            PatchPieces reused = PatchSplitter.split(p, SplitOptions.defaults(), trim, minSize, w);
            String in = "trial " + trial + ": " + p + (domain != null ? " trimmed" : "");
            assertEquals(fresh.count(), reused.count(), in);
            assertArrayEquals(fresh.nets(), reused.nets(), 0, in);
            assertArrayEquals(fresh.boxes(), reused.boxes(), 0, in);
            assertArrayEquals(fresh.weights(), reused.weights(), 0, in);
            assertArrayEquals(fresh.trimTest(), reused.trimTest(), in);
        }
    }

    /**
     * Up to bicubic the fine split ({@link SplitOptions#fine}) goes on to its own tolerance and
     * cap, with no past-the-cap rule of the higher degrees; without it (a big scene,
     * {@link SplitOptions#forPatches}) a piece stops at the base tolerance and cap.
     */
    @Test
    void upToBicubicTheFineSplitGoesOnToItsToleranceAndCap() {
        Random rnd = new Random(2020);
        SplitOptions fine = SplitOptions.defaults();
        SplitOptions coarse = fine.forPatches(SplitOptions.FINE_PATCHES + 1);
        assertTrue(fine.fine() && !coarse.fine() && fine.forPatches(SplitOptions.FINE_PATCHES) == fine);
        int fineCount = 0, coarseCount = 0;
        for (int trial = 0; trial < 200; trial++) {
            int n = 1 + rnd.nextInt(3), m = 1 + rnd.nextInt(3);
            BezierPatch patch = new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 1));
            for (SplitOptions options : new SplitOptions[] {fine, coarse}) {
                double tolerance = options.fine() ? SplitOptions.FINE_FLATNESS * options.flatnessTolerance()
                        : options.flatnessTolerance();
                int cap = options.maxDepth() + (options.fine() ? SplitOptions.FINE_DEPTH : 0);
                PatchPieces pieces = PatchSplitter.split(patch, options);
                for (int p = 0; p < pieces.count(); p++) {
                    int off = p * pieces.netLength();
                    int depth = depth(pieces, p);
                    double size = diagonal(pieces, p, n, m);
                    String where = "trial " + trial + " " + n + "x" + m + " piece " + p + " depth " + depth
                            + " fine " + options.fine();
                    assertTrue(depth <= cap, where);
                    assertTrue(PatchSplitter.flatness(pieces.nets(), off, n, m) <= tolerance * size || depth == cap,
                            "a piece neither flat nor at the cap: " + where);
                }
                if (options.fine()) {
                    fineCount += pieces.count();
                } else {
                    coarseCount += pieces.count();
                }
            }
        }
        assertTrue(fineCount > 2 * coarseCount, fineCount + " fine pieces, " + coarseCount + " coarse");
    }

    /**
     * The strongly curved arch: alone in a scene it gets the fine split, with several times the
     * base split's leaves; in a scene of more than {@link SplitOptions#FINE_PATCHES} copies of it
     * (whose scene-relative stop stays below its pieces) the base split's leaves exactly.
     */
    @Test
    void aStronglyCurvedBicubicIsSplitFinelyAloneAndAsBeforeInABigScene() {
        BezierPatch arch = org.beziertracer.model.io.GeneratedModels.curvedPatch();
        SplitOptions options = SplitOptions.defaults();
        PatchPieces coarse = PatchSplitter.split(arch, options.forPatches(SplitOptions.FINE_PATCHES + 1));
        PatchPieces fine = PatchSplitter.split(arch, options);
        assertTrue(fine.count() >= 3 * coarse.count(), fine.count() + " leaves fine, " + coarse.count() + " coarse");
        assertEquals(fine.count(), SubPatchTable.build(List.of(arch), options).countOf(0));
        List<BezierPatch> many = new java.util.ArrayList<>();
        for (int k = 0; k <= SplitOptions.FINE_PATCHES; k++) {
            many.add(arch);
        }
        SubPatchTable big = SubPatchTable.build(many, options);
        assertEquals(coarse.count(), big.countOf(0));
        assertEquals(coarse.count(), big.countOf(SplitOptions.FINE_PATCHES));
        assertEquals(false, big.options().fine());
    }
}
