package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.accel.Bvh;
import org.beziertracer.geometry.PatchPieces;
import org.beziertracer.geometry.PatchSplitter;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * The memory estimates beside the data (sub-patch table, BVH, triangle mesh) cover every array
 * the build makes, without over-counting much; the budget's message says what, how much and the fix.
 */
class HeapBudgetTest {

    private static List<BezierPatch> wavy(int count, int degree, long seed) {
        Random rnd = new Random(seed);
        List<BezierPatch> out = new ArrayList<>();
        for (int k = 0; k < count; k++) {
            double[] net = new double[(degree + 1) * (degree + 1) * 3];
            for (int i = 0; i < net.length; i++) {
                net[i] = rnd.nextDouble() * 10 + (i % 3 == 0 ? 3 * k : 0);
            }
            out.add(new BezierPatch(degree, degree, net));
        }
        return out;
    }

    /** Bytes of the pieces a build splits the split patches into first (dropped once copied into the table). */
    private static long pieces(List<BezierPatch> patches, SubPatchTable t) {
        long bytes = 0;
        for (BezierPatch p : patches) {
            PatchPieces pieces = PatchSplitter.split(p, t.options(), t.minSize());
            bytes += pieces.count() > 1 ? 8L * (pieces.nets().length + pieces.boxes().length) : 0;
        }
        return bytes;
    }

    @Test
    void theSubPatchCountEstimateIsExactForSmallModelsAndCloseForLargeOnes() {
        List<BezierPatch> teapot = Models.teapot().patches();
        assertEquals(SubPatchTable.build(teapot, SplitOptions.defaults()).count,
                SubPatchTable.estimate(teapot, SplitOptions.defaults()).leaves());
        assertEquals(teapot.size(), SubPatchTable.estimate(teapot, SplitOptions.wholePatches()).leaves());
        List<BezierPatch> mixed = new ArrayList<>(wavy(300, 3, 1));
        for (int k = 0; k < 300; k++) {
            mixed.add(teapot.get(k % teapot.size()));
        }
        long actual = SubPatchTable.build(mixed, SplitOptions.defaults()).count;
        long estimate = SubPatchTable.estimate(mixed, SplitOptions.defaults()).leaves();
        assertTrue(Math.abs(estimate - actual) < 0.15 * actual, "estimate " + estimate + ", actual " + actual);
    }

    @Test
    void theTableEstimateCoversItsArraysAndThePiecesItIsBuiltFrom() {
        for (List<BezierPatch> patches : List.of(Models.teapot().patches(), wavy(20, 15, 2), wavy(50, 1, 3))) {
            SubPatchTable t = SubPatchTable.build(patches, SplitOptions.defaults());
            long arrays = t.bytes() + pieces(patches, t);
            long estimate = SubPatchTable.estimate(patches, SplitOptions.defaults()).bytes();
            assertTrue(estimate >= arrays && estimate <= 1.5 * arrays, "estimate " + estimate + ", arrays " + arrays);
        }
    }

    @Test
    void theBvhEstimateCoversTheBuilderAndTheFinalNodes() {
        SubPatchTable t = SubPatchTable.build(Models.teapot().patches(), SplitOptions.defaults());
        Bvh bvh = Bvh.build(t.bounds(0, t.count), t.count);
        // Nodes (32 bytes) and the leaf order are kept; float boxes and centroids (SAH) or Morton
        // codes and the made-node lists are the builder's
        long finalArrays = 32L * bvh.nodeCount() + 4L * t.count;
        long builder = Math.max(36L, 40L) * t.count;
        long estimate = Bvh.estimateBytes(t.count);
        assertTrue(estimate >= finalArrays + builder, "estimate " + estimate);
        assertTrue(estimate <= 1.2 * (finalArrays + builder), "estimate " + estimate);
        assertTrue(bvh.bytes() >= finalArrays && bvh.bytes() <= finalArrays + 64, "retained " + bvh.bytes());
    }

    @Test
    void theMeshEstimateCoversTheMeshItsCopyAndTheTriangleArrays() {
        List<BezierPatch> teapot = Models.teapot().patches();
        for (int k : new int[] {1, 4, 20}) {
            TriangleMesh tm = TriangleMesh.build(teapot, k);
            Mesh m = tm.mesh;
            long mesh = 8L * (3 + 3 + 2) * m.vertexCount() + 4L * 4 * m.triangleCount();
            long own = 8L * (tm.corners.length + tm.bounds.length) + 4L * tm.patchOf.length;
            long estimate = TriangleMesh.estimateBytes(teapot.size(), k);
            assertEquals(2 * mesh + own, estimate, "K = " + k);
        }
    }

    @Test
    void aBuildThatWouldNotFitIsRefusedInOneLineNamingTheSourceTheNeedAndTheFix() {
        String message = UserMessages.of(IllegalArgumentException.class,
                () -> HeapBudget.require("big.obj", "600000 patches", Long.MAX_VALUE / 4));
        assertTrue(message.matches("big\\.obj: 600000 patches need about \\d+ GB of heap; this JVM allows [0-9.]+ [MG]B"
                + "(, [0-9.]+ [MG]B of it in use)? \\(run java -Xmx\\d+g …\\)"), message);
        HeapBudget.require("small.bpt", "1 patch", 1024); // fits: no exception
        Scene teapot = Models.teapot();
        long estimate = HeapBudget.estimateBytes(teapot, IntersectOptions.defaults().withTessellate(400));
        assertTrue(estimate > 2.5e9, "10 M triangles need gigabytes: " + estimate);
        assertTrue(HeapBudget.estimateBytes(teapot, IntersectOptions.defaults()) < 8e6, "the exact teapot is small");
    }

    @Test
    void sizesAndSuggestionsReadLikeAPersonWouldWriteThem() {
        assertEquals("640 MB", HeapBudget.size(640L << 20));
        assertEquals("1 GB", HeapBudget.size(1L << 30));
        assertEquals("3.2 GB", HeapBudget.size((long) (3.2 * (1L << 30))));
        assertEquals("12 GB", HeapBudget.size(12L << 30));
        assertEquals("16g", HeapBudget.suggestion(12L << 30));
        assertEquals("256m", HeapBudget.suggestion(150L << 20));
        assertEquals("64m", HeapBudget.suggestion(1 << 20));
        assertEquals("this JVM allows 1 GB, 400 MB of it in use (run java -Xmx4g …)",
                HeapBudget.limit(1L << 30, 400L << 20, 2L << 30));
    }
    /** The build's estimate is the sum of its parts: the leaves' data, the boxes handed to the BVH build, the build, Newton's records. */
    @Test
    void theBuildEstimateAddsUpItsParts() {
        Scene teapot = Models.teapot();
        for (int k : new int[] {1, 7}) {
            long triangles = 2L * k * k * teapot.patchCount();
            assertEquals(TriangleMesh.estimateBytes(teapot.patchCount(), k) + 6 * 8 * triangles + Bvh.estimateBytes(triangles),
                    HeapBudget.estimateBytes(teapot, IntersectOptions.defaults().withTessellate(k)), "K = " + k);
        }
        IntersectOptions clipping = IntersectOptions.defaults();
        SubPatchTable.Estimate table = SubPatchTable.estimate(teapot.patches(), clipping.split());
        // Clipping below ClippingLeaves.RECORD_LEAVES and Newton add their per-leaf records (STRIDE
        // floats each), clipping its leaves' slabs too
        long records = 4L * NewtonLeafRecords.STRIDE * table.leaves(), slabs = 4L * LeafSlabs.STRIDE * table.leaves();
        assertTrue(ClippingLeaves.hasRecords(table.leaves()));
        assertEquals(table.bytes() + 6 * 8 * table.leaves() + Bvh.estimateBytes(table.leaves()) + records + slabs,
                HeapBudget.estimateBytes(teapot, clipping));
        IntersectOptions newton = clipping.withMethod(Method.NEWTON).withSplit(clipping.split());
        assertEquals(HeapBudget.estimateBytes(teapot, clipping) - slabs, HeapBudget.estimateBytes(teapot, newton));
        // Subdivision keeps no records
        IntersectOptions subdivision = clipping.withMethod(Method.SUBDIVISION).withSplit(clipping.split());
        assertEquals(records + slabs, HeapBudget.estimateBytes(teapot, clipping) - HeapBudget.estimateBytes(teapot, subdivision));
        // Above bicubic, clipping also keeps a quadratic start a leaf (LeafQuadratics), Newton does not
        Scene wavy = new Scene(List.of(new BezierPatch(5, 5, wavyNet(5))));
        SubPatchTable.Estimate wavyTable = SubPatchTable.estimate(wavy.patches(), clipping.split());
        assertEquals(table(wavyTable) + 4L * (NewtonLeafRecords.STRIDE + LeafSlabs.STRIDE + LeafQuadratics.STRIDE)
                * wavyTable.leaves(),
                HeapBudget.estimateBytes(wavy, clipping));
        assertEquals(table(wavyTable) + 4L * NewtonLeafRecords.STRIDE * wavyTable.leaves(),
                HeapBudget.estimateBytes(wavy, newton));
    }

    private static long table(SubPatchTable.Estimate t) {
        return t.bytes() + 6 * 8 * t.leaves() + Bvh.estimateBytes(t.leaves());
    }

    /** A degree-n×n height field with some waves, on the unit square. */
    static double[] wavyNet(int n) {
        double[] net = new double[3 * (n + 1) * (n + 1)];
        for (int j = 0, p = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++, p += 3) {
                net[p] = (double) i / n;
                net[p + 1] = (double) j / n;
                net[p + 2] = 0.2 * Math.sin(7.0 * i / n) * Math.cos(5.0 * j / n);
            }
        }
        return net;
    }

    /**
     * Above {@link ClippingLeaves#RECORD_LEAVES} leaves the clipping leaves keep no records (issue
     * [6]'s memory budget): 40,000 random bicubic patches estimate to more leaves than that, and
     * their clipping estimate equals subdivision's, which keeps none; the built leaves hold none.
     */
    @Test
    void aBigModelsClippingLeavesKeepNoRecords() {
        List<BezierPatch> patches = wavy(40_000, 3, 5);
        Scene scene = new Scene(patches);
        IntersectOptions clipping = IntersectOptions.defaults();
        SubPatchTable.Estimate table = SubPatchTable.estimate(patches, clipping.split());
        assertTrue(!ClippingLeaves.hasRecords(table.leaves()), table.leaves() + " leaves");
        assertEquals(HeapBudget.estimateBytes(scene, clipping.withMethod(Method.SUBDIVISION).withSplit(clipping.split())),
                HeapBudget.estimateBytes(scene, clipping));
        PatchLeaves leaves = PatchLeaves.build(scene, clipping, 1);
        assertTrue(!ClippingLeaves.hasRecords(leaves.count()), leaves.count() + " leaves built");
        assertEquals(leaves.table.bytes(), leaves.bytes());
        PatchLeaves small = PatchLeaves.build(Models.teapot(), clipping, 1);
        assertEquals(small.table.bytes() + HeapBytes.array((long) NewtonLeafRecords.STRIDE * small.count(), 4)
                + HeapBytes.array((long) LeafSlabs.STRIDE * small.count(), 4), small.bytes());
    }

    /** The refusal names the scene's patches (and the tessellation with its triangle count). */
    @Test
    void theRefusalOfAModelSaysWhatNeedsTheMemory() {
        Scene teapot = Models.teapot();
        String tessellated = UserMessages.of(IllegalArgumentException.class,
                () -> HeapBudget.require("teapot", teapot, IntersectOptions.defaults().withTessellate(1024)));
        assertTrue(tessellated.startsWith("teapot: 32 patches tessellated 1024x1024 (67108864 triangles) need about "),
                tessellated);
        BezierPatch big = wavy(1, 15, 4).get(0);
        Scene many = new Scene(java.util.Collections.nCopies(2_000_000, big));
        String exact = UserMessages.of(IllegalArgumentException.class,
                () -> HeapBudget.require(null, many, IntersectOptions.defaults().withBvh(false)));
        assertTrue(exact.startsWith("2000000 patches need about "), exact);
    }

    /**
     * The headroom counts: a request that fits only without the collector's 10 % is refused, and
     * the message names the request with its headroom; one that fits with it is accepted.
     */
    @Test
    void theCollectorsHeadroomIsPartOfTheRequest() {
        Runtime rt = Runtime.getRuntime();
        System.gc();
        long available = rt.maxMemory() - (rt.totalMemory() - rt.freeMemory());
        long tight = (long) (available / 1.05);
        String message = UserMessages.of(IllegalArgumentException.class, () -> HeapBudget.require("x", "a scene", tight));
        assertTrue(message.startsWith("x: a scene need about " + HeapBudget.size((long) (tight * HeapBudget.GC_HEADROOM))
                + " of heap; this JVM allows " + HeapBudget.size(rt.maxMemory())), message);
        HeapBudget.require("x", "a scene", (long) (available / 1.2)); // fits, headroom included
        // the whole heap with its headroom: never fits beside what is in use
        long all = (long) (rt.maxMemory() / HeapBudget.GC_HEADROOM);
        assertTrue(UserMessages.of(IllegalArgumentException.class, () -> HeapBudget.require(null, "it", all))
                .startsWith("it need about "));
    }

    @Test
    void outOfMemoryNamesTheLimitAndTheFix() {
        long max = Runtime.getRuntime().maxMemory();
        assertEquals("out of memory: this JVM allows " + HeapBudget.size(max) + " (run java -Xmx" + HeapBudget.suggestion(max)
                + " …)", HeapBudget.outOfMemory());
        assertEquals("1g", HeapBudget.suggestion(500L << 20), "exactly 1024 MB reads as 1g");
        assertEquals("512m", HeapBudget.suggestion(300L << 20));
    }
}
