package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.Test;

/** Click, Shift-click, Ctrl-click, rubber band, Escape, dragging a selection, axis keys and nudges, on the default patch. */
class SelectionGesturesTest {

    private final AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());

    SelectionGesturesTest() {
        app.view().resize(800, 600, 1);
    }

    private double[] screen(int i, int j) {
        BezierPatch p = app.document().scene().patches().get(0);
        double[] out = new double[3];
        app.view().projector().project(p.get(i, j, 0), p.get(i, j, 1), p.get(i, j, 2), out);
        return out;
    }

    private void click(int i, int j, Modifiers mods) {
        double[] at = screen(i, j);
        app.pointer().pressed(at[0], at[1], mods);
        app.pointer().released(at[0], at[1]);
    }

    private static PointRef p(int i, int j) { return new PointRef(0, i, j); }

    private double[] xyz(Scene s, PointRef r) {
        BezierPatch p = s.patches().get(r.patch());
        return new double[] {p.get(r.i(), r.j(), 0), p.get(r.i(), r.j(), 1), p.get(r.i(), r.j(), 2)};
    }

    @Test
    void clickSelectsShiftAddsCtrlTogglesAndAClickOnEmptySpaceOrEscapeClears() {
        click(1, 1, Modifiers.NONE);
        assertEquals(Selection.of(p(1, 1)), app.selection());
        click(2, 1, Modifiers.SHIFT);
        click(2, 2, Modifiers.SHIFT);
        assertEquals(Selection.of(p(1, 1), p(2, 1), p(2, 2)), app.selection());
        click(2, 1, Modifiers.CTRL);
        assertEquals(Selection.of(p(1, 1), p(2, 2)), app.selection(), "Ctrl-click takes a selected point out");
        click(0, 3, Modifiers.CTRL);
        assertEquals(Selection.of(p(1, 1), p(2, 2), p(0, 3)), app.selection(), "and puts another in");
        click(2, 2, Modifiers.NONE);
        assertEquals(Selection.of(p(2, 2)), app.selection(), "a plain click on a selected point selects it alone");
        click(0, 3, Modifiers.SHIFT);
        click(3, 3, Modifiers.NONE);
        assertEquals(Selection.of(p(3, 3)), app.selection(), "a plain click starts over");
        app.pointer().pressed(3, 3, Modifiers.NONE);
        app.pointer().released(4, 4);
        assertEquals(Selection.EMPTY, app.selection(), "a click on empty space clears");
        click(1, 2, Modifiers.NONE);
        app.selections().clear();
        assertEquals(Selection.EMPTY, app.selection(), "Edit → Clear Selection (Escape)");
    }

    @Test
    void aRubberBandAddsThePointsInsideAndWithCtrlTogglesThem() {
        double x0 = Double.MAX_VALUE, y0 = Double.MAX_VALUE, x1 = -Double.MAX_VALUE, y1 = -Double.MAX_VALUE;
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {1, 2}, {2, 2}}) {
            double[] a = screen(ij[0], ij[1]);
            x0 = Math.min(x0, a[0] - 3);
            x1 = Math.max(x1, a[0] + 3);
            y0 = Math.min(y0, a[1] - 3);
            y1 = Math.max(y1, a[1] + 3);
        }
        app.pointer().pressed(x0, y0, Modifiers.SHIFT);
        app.pointer().dragged((x0 + x1) / 2, (y0 + y1) / 2);
        assertTrue(app.overlay().snapshot().band() != null, "the band is drawn while dragging");
        app.pointer().dragged(x1, y1);
        app.pointer().released(x1, y1);
        assertEquals(null, app.overlay().snapshot().band(), "and gone after");
        assertEquals(java.util.Set.of(p(1, 1), p(2, 1), p(1, 2), p(2, 2)), java.util.Set.copyOf(app.selection().points()),
                "the four middle points lie in the band");
        click(1, 1, Modifiers.CTRL);
        app.pointer().pressed(x0, y0, Modifiers.CTRL);
        app.pointer().released(x1, y1);
        assertEquals(Selection.of(p(1, 1)), app.selection(), "Ctrl-band toggles: three out, (1,1) back in");
    }

    @Test
    void draggingASelectedPointMovesTheWholeSelectionAsOneEdit() {
        Scene before = app.document().scene();
        click(1, 1, Modifiers.NONE);
        click(2, 2, Modifiers.SHIFT);
        double[] at = screen(1, 1);
        app.pointer().pressed(at[0], at[1], Modifiers.NONE);
        app.pointer().dragged(at[0] + 20, at[1] - 30);
        app.pointer().released(at[0] + 20, at[1] - 30);
        Scene after = app.document().scene();
        double[] d11 = diff(after, before, p(1, 1)), d22 = diff(after, before, p(2, 2));
        for (int c = 0; c < 3; c++) {
            assertEquals(d11[c], d22[c], 1e-12, "the same offset for every selected point");
        }
        assertTrue(Math.abs(d11[0]) + Math.abs(d11[1]) + Math.abs(d11[2]) > 0.1);
        assertEquals(before.patches().get(0).get(0, 0, 0), after.patches().get(0).get(0, 0, 0), "unselected points stay");
        assertEquals("Move 2 points", app.document().history().undoName());
        app.edits().undo();
        assertSame(before, app.document().scene());
    }

    private double[] diff(Scene a, Scene b, PointRef r) {
        double[] x = xyz(a, r), y = xyz(b, r);
        return new double[] {x[0] - y[0], x[1] - y[1], x[2] - y[2]};
    }

    @Test
    void holdingAnAxisKeyConstrainsTheDragToThatWorldAxis() {
        Scene before = app.document().scene();
        double[] at = screen(1, 2);
        app.pointer().pressed(at[0], at[1], Modifiers.NONE);
        app.pointer().axis(Axis.Z, true);
        app.pointer().dragged(at[0] + 25, at[1] - 40);
        app.pointer().released(at[0] + 25, at[1] - 40);
        app.pointer().axis(Axis.Z, false);
        double[] d = diff(app.document().scene(), before, p(1, 2));
        assertEquals(0, d[0], 1e-12, "x held");
        assertEquals(0, d[1], 1e-12, "y held");
        assertTrue(d[2] > 0.1, "moved up along z: " + d[2]);
        double[] now = screen(1, 2);
        assertTrue(now[1] < at[1] - 10, "towards the mouse on the screen");
        app.pointer().pressed(now[0], now[1], Modifiers.NONE);
        app.pointer().axis(Axis.X, true);
        app.pointer().dragged(now[0] + 60, now[1]);
        app.pointer().axis(Axis.X, false); // let go mid-drag: the move is free again
        app.pointer().dragged(now[0] + 60, now[1] + 5);
        app.pointer().released(now[0] + 60, now[1] + 5);
        double[] last = screen(1, 2);
        assertEquals(now[0] + 60, last[0], 1e-6, "free again: under the mouse");
    }

    @Test
    void arrowKeysNudgeByOnePixelOnTheScreenAndShiftByTen() {
        click(2, 1, Modifiers.NONE);
        double[] at = screen(2, 1);
        app.selections().nudge(1, 0);
        assertEquals(at[0] + 1, screen(2, 1)[0], 1e-6);
        assertEquals(at[1], screen(2, 1)[1], 1e-6);
        app.selections().nudge(0, -SelectionCommands.NUDGE_SHIFT_FACTOR);
        assertEquals(at[1] - 10, screen(2, 1)[1], 1e-6, "Shift: ten pixels up");
        assertEquals("Nudge", app.document().history().undoName());
        app.edits().undo();
        assertEquals(at[1], screen(2, 1)[1], 1e-6, "each nudge is one edit");
        app.selections().clear();
        Scene s = app.document().scene();
        app.selections().nudge(1, 0);
        assertSame(s, app.document().scene(), "nothing selected, nothing moves");
        assertTrue(app.status().message().contains("select"), app.status().message());
    }

    @Test
    void selectAllTakesEveryPointAndTheSelectionOutlivesADragAndAnUndo() {
        app.selections().selectAll();
        assertEquals(16, app.selection().size());
        assertEquals(16, app.overlay().snapshot().selected().size(), "every selected point is highlighted");
        app.edits().randomize(3);
        app.edits().undo();
        assertEquals(16, app.selection().size());
        app.settings().toggle(Toggle.CONTROL_POINTS);
        app.selections().clear();
        app.selections().selectAll();
        assertFalse(app.selection().size() > 0, "hidden points cannot be selected");
    }

    @Test
    void selectionsCombineHandleByHandle() {
        List<PointRef> weld = List.of(new PointRef(0, 3, 0), new PointRef(1, 0, 0));
        Selection s = Selection.EMPTY.with(weld);
        assertEquals(1, s.handleCount());
        assertEquals(2, s.size());
        assertEquals(Selection.EMPTY, s.toggled(weld));
        Selection t = s.combined(List.of(weld, List.of(new PointRef(2, 1, 1))), true);
        assertEquals(Selection.of(new PointRef(2, 1, 1)), t);
    }
}
