package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.beziertracer.intersect.BorderRays;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The welding test, without a window: drag a teapot border point with the mouse, save, and
 * every pair of points that coincided in the original still coincides in the saved file; the crack
 * test passes on the edited model. Alt-drag moves one copy only.
 */
class WeldedDragTest {

    @TempDir
    Path dir;

    private final FakeDialogs dialogs = new FakeDialogs();
    private final AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());

    WeldedDragTest() {
        app.view().resize(800, 600, 1);
        app.files().openBuiltIn("teapot");
    }

    /** Where {@code r} is drawn now. */
    private double[] screen(PointRef r) {
        var p = app.document().scene().patches().get(r.patch());
        double[] out = new double[3];
        assertTrue(app.view().projector().project(p.get(r.i(), r.j(), 0), p.get(r.i(), r.j(), 1), p.get(r.i(), r.j(), 2), out));
        return out;
    }

    /** A border point of the body that the overlay draws as a handle (so the mouse can pick it). */
    private PointRef pickableBorderPoint(int copiesAtLeast) {
        Topology t = Topology.of(app.document().scene(), false);
        OverlayGeometry g = app.overlay().geometry();
        for (int k = 0; k < g.handleCount(); k++) {
            PointRef r = g.handle(k).ref();
            boolean border = r.i() == 0 || r.i() == 3 || r.j() == 0 || r.j() == 3;
            if (border && r.patch() < 12 && t.handle(r, app.document().scene()).size() >= copiesAtLeast
                    && app.overlay().geometry().pick(g.handleX(k), g.handleY(k), 1).ref().equals(r)) {
                return r;
            }
        }
        throw new AssertionError("no pickable border point");
    }

    private void drag(PointRef r, Modifiers mods, double dx, double dy) {
        double[] at = screen(r);
        app.pointer().pressed(at[0], at[1], mods);
        for (int k = 1; k <= 8; k++) {
            app.pointer().dragged(at[0] + dx * k / 8, at[1] + dy * k / 8);
        }
        app.pointer().released(at[0] + dx, at[1] + dy);
    }

    @Test
    void aDraggedTeapotBorderPointKeepsEveryCoincidenceInTheSavedFileAndLeavesNoCrack() throws Exception {
        Scene original = app.document().scene();
        List<PointRef> all = WeldIndexTest.allPoints(original);
        double tol = WeldIndex.tolerance(original);
        PointRef grabbed = pickableBorderPoint(2);
        int copies = Topology.of(original, false).handle(grabbed, original).size();
        drag(grabbed, Modifiers.NONE, 40, -60);
        assertEquals(copies, app.selection().size(), "the handle selected every copy");
        Scene edited = app.document().scene();
        assertNotEquals(original.patches().get(grabbed.patch()), edited.patches().get(grabbed.patch()), "the point moved");
        Path file = dir.resolve("edited.bpt");
        app.files().saveTo(file, () -> {});
        assertEquals(List.of(), dialogs.errors);
        Scene saved = Models.load(file.toString());
        int pairs = 0;
        for (int a = 0; a < all.size(); a++) {
            for (int b = a + 1; b < all.size(); b++) {
                if (WeldIndexTest.distance(original, all.get(a), all.get(b)) <= tol) {
                    pairs++;
                    assertTrue(WeldIndexTest.distance(saved, all.get(a), all.get(b)) <= tol,
                            all.get(a) + " and " + all.get(b) + " coincided and still must");
                }
            }
        }
        assertTrue(pairs > 300, "coinciding pairs checked: " + pairs);
        BorderRays.assertNoneFallThrough(saved, Method.CLIPPING);
        app.edits().undo();
        assertEquals(original.patches(), app.document().scene().patches(), "the drag of every copy was one edit");
        assertFalse(app.document().history().canUndo());
    }

    @Test
    void altDragMovesOneCopyOnly() {
        Scene original = app.document().scene();
        PointRef grabbed = pickableBorderPoint(2);
        List<PointRef> copies = Topology.of(original, false).handle(grabbed, original);
        drag(grabbed, Modifiers.ALT, 30, 30);
        assertEquals(Selection.of(grabbed), app.selection(), "Alt takes the copy under the mouse only");
        Scene edited = app.document().scene();
        for (PointRef c : copies.subList(1, copies.size())) {
            assertEquals(original.patches().get(c.patch()), edited.patches().get(c.patch()), "the other copies stay: " + c);
        }
        assertTrue(WeldIndexTest.distance(edited, grabbed, copies.get(1)) > 1, "the copy left the others");
    }
}
