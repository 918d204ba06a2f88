package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class EditHistoryTest {

    private static Scene moved(Scene s, double z) {
        return s.withPatch(0, s.patches().get(0).withPoint(1, 2, 0.1, 0.2, z));
    }

    @Test
    void aDragOfManyPreviewsIsOneUndoableEdit() {
        Scene start = Models.patch();
        EditHistory h = new EditHistory(start);
        for (int k = 1; k <= 20; k++) {
            h.preview(moved(h.current(), k * 0.1));
        }
        h.commit("Move control point", start);
        assertTrue(h.canUndo());
        assertNotNull(h.undo());
        assertSame(start, h.current(), "undo restores the exact scene before the drag");
        assertArrayEquals(start.patches().get(0).copyNet(), h.current().patches().get(0).copyNet());
        assertFalse(h.canUndo(), "the whole drag was one edit");
    }

    @Test
    void undoAndRedoWalkTheEdits() {
        Scene a = Models.patch();
        EditHistory h = new EditHistory(a);
        h.apply("one", moved(a, 1));
        Scene b = h.current();
        h.apply("two", moved(b, 2));
        Scene c = h.current();
        h.undo();
        assertSame(b, h.current());
        h.redo();
        assertSame(c, h.current());
        h.undo();
        h.apply("three", moved(b, 3));
        assertFalse(h.canRedo(), "a new edit clears the redo stack");
    }

    @Test
    void dirtyFollowsTheSavedSceneThroughUndo() {
        Scene a = Models.patch();
        EditHistory h = new EditHistory(a);
        assertFalse(h.isDirty());
        h.apply("one", moved(a, 1));
        assertTrue(h.isDirty());
        h.undo();
        assertFalse(h.isDirty(), "undoing back to the loaded scene is clean");
        h.redo();
        h.markSaved();
        assertFalse(h.isDirty());
        h.undo();
        assertTrue(h.isDirty());
    }

    @Test
    void commitWithoutChangeRecordsNothing() {
        Scene a = Models.patch();
        EditHistory h = new EditHistory(a);
        h.commit("click", a);
        assertFalse(h.canUndo());
        assertFalse(h.isDirty());
    }

    @Test
    void anEditThatReframedHandsItsFramingsBackOnUndoAndRedo() {
        Scene a = Models.teapot();
        EditHistory h = new EditHistory(a);
        Framing before = Framing.of(a.controlBounds());
        Scene grid = NetEdits.resetGrid(a, 4, 4);
        Framing after = Framing.of(grid.controlBounds());
        h.apply("Reset control points", grid, before, after);
        h.apply("move", moved(grid, 1));
        assertNull(h.undo().framingBefore(), "a point move keeps the framing");
        EditHistory.Edit reset = h.undo();
        assertSame(a, h.current());
        assertEquals(before, reset.framingBefore(), "undoing the reset gives the teapot's framing back");
        assertEquals(after, h.redo().framingAfter(), "redo gives the grid's framing");
        h.undo();
        assertNull(h.undo(), "nothing left to undo");
    }
}
