package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;

import org.beziertracer.UserMessages;
import org.beziertracer.accel.Bvh;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * A method is its leaves class plus one {@link Method} constant: every name, message and estimate
 * of a method elsewhere derives from the constants — the labels and the parse that checks them,
 * the list an unknown name gets, and {@link HeapBudget}'s share of each method's leaves.
 */
class MethodTest {

    @Test
    void everyLabelParsesBackToItsConstantInAnyCase() {
        assertEquals(Arrays.stream(Method.values()).map(Method::label).toList(), Method.labels());
        assertEquals(Method.values().length, new HashSet<>(Method.labels()).size(), "labels are distinct");
        for (Method m : Method.values()) {
            assertEquals(m.name().toLowerCase(Locale.ROOT), m.label());
            assertSame(m, Method.parse(m.label()));
            assertSame(m, Method.parse("  " + m.label().toUpperCase(Locale.ROOT) + "\t"));
            assertFalse(m.description().isBlank(), m + " describes itself");
            assertTrue(m.description().lines().count() == 1, m + ": one line");
        }
    }

    @Test
    void anUnknownNameGetsOneLineListingEveryLabel() {
        String message = UserMessages.of(IllegalArgumentException.class, () -> Method.parse("bogus"));
        assertEquals("unknown method 'bogus': expected " + Method.choices(), message);
        for (String label : Method.labels()) {
            assertTrue(message.contains(label), label + " in: " + message);
        }
        // the sentence lists each label once, in the enum's order
        String list = message.substring(message.indexOf("expected ") + "expected ".length());
        assertEquals(Method.labels(), List.of(list.split(", | or ")));
        assertEquals("unknown method '': expected " + Method.choices(),
                UserMessages.of(IllegalArgumentException.class, () -> Method.parse(null)));
        assertEquals("unknown method ' ': expected " + Method.choices(),
                UserMessages.of(IllegalArgumentException.class, () -> Method.parse(" ")));
    }

    @Test
    void theModelLayersDefaultMethodIsTheIntersectionDefault() {
        assertSame(IntersectOptions.defaults().method(), Method.parse(RenderSettings.defaults().method()));
    }

    /**
     * For every method, HeapBudget's estimate is the table's part (the same for all at one split)
     * plus exactly what the constant says its leaves keep; positive for every method, and the
     * methods with per-leaf records (clipping, Newton) keep some on the teapot and a degree-5 patch.
     */
    @Test
    void theBudgetTakesEachMethodsLeafBytesFromItsConstant() {
        SplitOptions split = SplitOptions.defaults();
        Scene wavy = new Scene(List.of(new BezierPatch(5, 5, HeapBudgetTest.wavyNet(5))));
        for (Scene scene : List.of(Models.teapot(), wavy)) {
            List<BezierPatch> patches = scene.patches();
            SubPatchTable.Estimate table = SubPatchTable.estimate(patches, split);
            long tablePart = table.bytes() + 6 * 8 * table.leaves() + Bvh.estimateBytes(table.leaves());
            for (Method m : Method.values()) {
                IntersectOptions o = IntersectOptions.defaults().withMethod(m).withSplit(split);
                long estimate = HeapBudget.estimateBytes(scene, o);
                assertTrue(estimate > 0, m + ": " + estimate);
                assertEquals(tablePart + m.solverBytes(patches, table.leaves()), estimate, m.label());
                assertTrue(m.solverBytes(patches, table.leaves()) >= 0, m.label());
            }
            assertTrue(Method.CLIPPING.solverBytes(patches, table.leaves()) > 0);
            assertTrue(Method.NEWTON.solverBytes(patches, table.leaves()) > 0);
        }
    }

    /** Each constant's estimate is its own leaves class's: clipping's grows past bicubic (quadratic starts), Newton's does not. */
    @Test
    void eachConstantsEstimateIsItsLeavesClasss() {
        List<BezierPatch> bicubic = Models.teapot().patches();
        List<BezierPatch> quintic = List.of(new BezierPatch(5, 5, HeapBudgetTest.wavyNet(5)));
        long leaves = 1000;
        for (List<BezierPatch> patches : List.of(bicubic, quintic)) {
            assertEquals(ClippingLeaves.estimateBytes(patches, leaves), Method.CLIPPING.solverBytes(patches, leaves));
            assertEquals(NewtonLeaves.estimateBytes(patches, leaves), Method.NEWTON.solverBytes(patches, leaves));
            assertEquals(SubdivisionLeaves.estimateBytes(patches, leaves), Method.SUBDIVISION.solverBytes(patches, leaves));
        }
        assertEquals(4L * (NewtonLeafRecords.STRIDE + LeafSlabs.STRIDE) * leaves, Method.CLIPPING.solverBytes(bicubic, leaves));
        assertEquals(4L * (NewtonLeafRecords.STRIDE + LeafSlabs.STRIDE + LeafQuadratics.STRIDE) * leaves,
                Method.CLIPPING.solverBytes(quintic, leaves));
        assertEquals(4L * NewtonLeafRecords.STRIDE * leaves, Method.NEWTON.solverBytes(quintic, leaves));
        assertEquals(0, Method.SUBDIVISION.solverBytes(quintic, leaves));
        assertEquals(0, Method.CLIPPING.solverBytes(bicubic, ClippingLeaves.RECORD_LEAVES + 1L), "no records above the cap");
    }

}
