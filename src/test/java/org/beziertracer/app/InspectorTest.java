package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/** The inspector shows the selection and moves it by typed coordinates, one undoable edit each. */
class InspectorTest {

    private final AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    private double coord(PointRef r, int c) {
        return app.document().scene().patches().get(r.patch()).get(r.i(), r.j(), c);
    }

    @Test
    void oneHandleShowsItsPatchIndicesAndCoordinatesAndTakesATypedValue() {
        assertNull(app.inspector().state(), "nothing selected");
        assertEquals("select a control point first", app.inspector().set(Inspector.Field.X, "1"));
        PointRef r = new PointRef(0, 2, 1);
        app.select(Selection.of(r));
        Inspector.State st = app.inspector().state();
        assertEquals(r, st.primary());
        assertEquals(1, st.handles());
        assertEquals(Inspector.format(coord(r, 0)), st.text(Inspector.Field.X));
        assertFalse(st.hasWeight(), "a polynomial patch has no weight row");
        Scene before = app.document().scene();
        assertNull(app.inspector().set(Inspector.Field.Z, " 1.25 "));
        assertEquals(1.25, coord(r, 2), 1e-12);
        assertEquals(before.patches().get(0).get(2, 1, 0), coord(r, 0), "x stays");
        assertEquals("Set z", app.document().history().undoName());
        app.edits().undo();
        assertSame(before, app.document().scene(), "one undoable edit");
    }

    @Test
    void severalPointsShowAndShiftTheirCentroid() {
        List<PointRef> refs = List.of(new PointRef(0, 0, 0), new PointRef(0, 3, 0), new PointRef(0, 3, 3));
        app.select(Selection.of(refs));
        Inspector.State st = app.inspector().state();
        assertEquals(3, st.handles());
        double cx = (coord(refs.get(0), 0) + coord(refs.get(1), 0) + coord(refs.get(2), 0)) / 3;
        assertEquals(cx, st.xyz()[0], 1e-12);
        double[] x0 = refs.stream().mapToDouble(r -> coord(r, 0)).toArray();
        assertNull(app.inspector().set(Inspector.Field.X, String.valueOf(cx + 2)));
        for (int k = 0; k < 3; k++) {
            assertEquals(x0[k] + 2, coord(refs.get(k), 0), 1e-12, "each point shifts with the centroid");
        }
        assertEquals(cx + 2, app.inspector().state().xyz()[0], 1e-12);
    }

    @Test
    void aWeldedHandleMovesEveryCopy() {
        app.files().openBuiltIn("teapot");
        Scene teapot = app.document().scene();
        List<PointRef> copies = Topology.of(teapot, false).handle(new PointRef(0, 0, 0), teapot);
        app.select(Selection.ofHandles(List.of(copies)));
        assertEquals(copies.size(), app.inspector().state().copies());
        assertNull(app.inspector().set(Inspector.Field.Y, "-12"));
        for (PointRef c : copies) {
            assertEquals(-12, coord(c, 1), 1e-12, "copy " + c);
        }
    }

    @Test
    void badValuesAreOneLineAndChangeNothing() {
        app.select(Selection.of(new PointRef(0, 1, 1)));
        Scene before = app.document().scene();
        String m = app.inspector().set(Inspector.Field.X, "abc");
        assertEquals("x: expected a number, found \"abc\"", UserMessages.check(m));
        assertTrue(UserMessages.check(app.inspector().set(Inspector.Field.Y, "NaN")).startsWith("y must be a finite number"));
        assertTrue(UserMessages.check(app.inspector().set(Inspector.Field.Z, "9".repeat(500))).length() < 120,
                "a long echo is cut");
        assertEquals("this patch has no weights (it is not rational)",
                UserMessages.check(app.inspector().set(Inspector.Field.WEIGHT, "2")));
        assertSame(before, app.document().scene());
    }

    @Test
    void aRefusalStaysUntilTheSelectionChangesOrAModelIsOpened() {
        app.select(Selection.of(new PointRef(0, 1, 1)));
        app.inspector().set(Inspector.Field.X, "abc");
        assertEquals("x: expected a number, found \"abc\"", app.inspector().message());
        app.select(Selection.of(new PointRef(0, 1, 1)));
        assertEquals("x: expected a number, found \"abc\"", app.inspector().message(), "the same selection keeps it");
        app.select(Selection.of(new PointRef(0, 2, 1)));
        assertNull(app.inspector().message(), "another selection clears it");
        app.inspector().set(Inspector.Field.Y, "NaN");
        assertTrue(app.inspector().message().startsWith("y must be a finite number"));
        assertNull(app.inspector().set(Inspector.Field.Y, "0.5"));
        assertNull(app.inspector().message(), "an accepted value clears it");
        app.document().history().markSaved(); // opening another model asks nothing
        for (String model : new String[] {"teapot", "sphere", "patch"}) {
            app.select(Selection.of(new PointRef(0, 1, 1)));
            app.inspector().set(Inspector.Field.Z, "z?");
            assertTrue(app.inspector().message() != null);
            app.files().openBuiltIn(model);
            assertNull(app.inspector().message(), "opening " + model + " clears it");
        }
        app.inspector().set(Inspector.Field.Z, "1");
        assertEquals("select a control point first", app.inspector().message());
        app.files().openBuiltIn("torus");
        assertNull(app.inspector().message(), "a load with nothing selected clears it too");
    }

    @Test
    void numbersAreShownShortAndExact() {
        assertEquals("1.5", Inspector.format(1.5));
        assertEquals("-0.333333333", Inspector.format(-1.0 / 3));
        assertEquals("0", Inspector.format(0));
        assertEquals("1E-7", Inspector.format(1e-7));
        BezierPatch p = app.document().scene().patches().get(0);
        assertEquals(p.get(0, 0, 0), Double.parseDouble(Inspector.format(p.get(0, 0, 0))), 1e-9);
    }

    @Test
    void aRationalPatchShowsItsWeightAndTakesATypedOneOnEveryCopy() {
        app.files().openBuiltIn("sphere");
        Scene sphere = app.document().scene();
        assertTrue(sphere.patches().get(0).isRational(), "the built-in sphere is rational");
        // A point on a border between patches: its copies are re-weighted together
        PointRef r = new PointRef(0, 0, 1);
        List<PointRef> copies = Topology.of(sphere, false).handle(r, sphere);
        app.select(Selection.ofHandles(List.of(copies)));
        Inspector.State st = app.inspector().state();
        assertTrue(st.hasWeight(), "a rational patch has a weight row");
        assertEquals(Inspector.format(sphere.patches().get(0).weight(0, 1)), st.text(Inspector.Field.WEIGHT));
        assertNull(app.inspector().set(Inspector.Field.WEIGHT, "2.5"));
        for (PointRef c : copies) {
            assertEquals(2.5, app.document().scene().patches().get(c.patch()).weight(c.i(), c.j()), 0, "copy " + c);
        }
        assertEquals(sphere.patches().get(0).get(0, 1, 0), coord(r, 0), "the point itself stays");
        assertEquals("2.5", app.inspector().state().text(Inspector.Field.WEIGHT));
        assertEquals("Set weight", app.document().history().undoName());
        assertTrue(UserMessages.check(app.inspector().set(Inspector.Field.WEIGHT, "0")).startsWith("weight must be a positive number"));
        app.edits().undo();
        assertSame(sphere, app.document().scene(), "one undoable edit");
    }
}
