package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.beziertracer.render.ShadingMode;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The app without a window: mouse in device pixels, every worker inline, fake engine and dialogs. */
class AppModelTest {

    @TempDir
    Path dir;
    private FakeEngine engine;
    private FakeDialogs dialogs;
    private AppModel app;

    @BeforeEach
    void setUp() {
        engine = new FakeEngine();
        dialogs = new FakeDialogs();
        app = new AppModel(engine, dialogs, AppThreads.direct(), MemoryPreferences.fresh());
        app.view().resize(800, 600, 1);
    }

    /** Where control point (i, j) of patch 0 is on the picture now. */
    private double[] screen(int i, int j) {
        BezierPatch p = app.document().scene().patches().get(0);
        double[] out = new double[3];
        assertTrue(app.view().projector().project(p.get(i, j, 0), p.get(i, j, 1), p.get(i, j, 2), out));
        return out;
    }

    private void dragPoint(int i, int j, double dx, double dy) {
        double[] at = screen(i, j);
        PointerTool mouse = app.pointer();
        mouse.pressed(at[0], at[1]);
        for (int k = 1; k <= 10; k++) {
            mouse.dragged(at[0] + dx * k / 10, at[1] + dy * k / 10);
        }
        mouse.released(at[0] + dx, at[1] + dy);
    }

    private RenderRequest lastRequest() {
        return engine.requests.get(engine.requests.size() - 1);
    }

    @Test
    void opensOnTheDefaultBicubicPatchLitFromAboveLeftOfTheEye() {
        Scene s = app.document().scene();
        assertEquals(1, s.patchCount());
        assertEquals(3, s.patches().get(0).degreeU());
        assertTrue(s.lights().isEmpty(), "the model has no lights of its own");
        RenderRequest r = lastRequest();
        assertEquals(1, r.lights().size(), "the app's default light");
        org.beziertracer.math.Vec3 light = r.lights().get(0).position();
        double[] at = new double[3];
        assertTrue(app.view().projector().project(light.x(), light.y(), light.z(), at), "in front of the eye");
        assertTrue(at[0] < 400 && at[1] < 300, "above and to the left of the picture's centre: " + at[0] + "," + at[1]);
        assertTrue(light.sub(r.camera().eye()).length() > 0.2 * r.camera().target().sub(r.camera().eye()).length(),
                "not at the eye");
        assertFalse(app.document().isDirty());
        assertEquals(1, engine.requests.size(), "the first layout starts a render");
        assertEquals(16, app.overlay().geometry().handleCount(), "every control point gets a handle");
        assertEquals(16, app.overlay().geometry().pointCount());
    }

    @Test
    void draggingAPointMovesItUnderTheCursorAsOneUndoableEdit() {
        Scene before = app.document().scene();
        double[] start = screen(1, 1);
        int renders = engine.requests.size();
        dragPoint(1, 1, 30, -40);
        assertEquals(renders + 10, engine.requests.size(), "every drag step restarts a render, the release none");
        double[] now = screen(1, 1);
        assertEquals(start[0] + 30, now[0], 1e-6);
        assertEquals(start[1] - 40, now[1], 1e-6);
        assertTrue(app.document().isDirty());
        assertEquals(Selection.of(new PointRef(0, 1, 1)), app.selection(), "the dragged point stays selected");
        app.edits().undo();
        assertSame(before, app.document().scene());
        assertArrayEquals(before.patches().get(0).copyNet(), app.document().scene().patches().get(0).copyNet());
        assertFalse(app.document().history().canUndo(), "one drag, one edit");
        app.edits().redo();
        assertNotEquals(before, app.document().scene());
    }

    @Test
    void draggingASelectionMovesEveryPointByTheSameOffset() {
        Scene base = Models.teapot();
        Selection sel = Selection.of(new PointRef(0, 1, 1), new PointRef(3, 0, 2), new PointRef(3, 2, 2));
        Scene moved = SelectionMove.apply(base, sel, new double[] {0.5, -1, 2}, Topology.NONE, false);
        for (PointRef r : sel.points()) {
            BezierPatch a = base.patches().get(r.patch()), b = moved.patches().get(r.patch());
            assertEquals(a.get(r.i(), r.j(), 0) + 0.5, b.get(r.i(), r.j(), 0), 1e-12);
            assertEquals(a.get(r.i(), r.j(), 1) - 1, b.get(r.i(), r.j(), 1), 1e-12);
            assertEquals(a.get(r.i(), r.j(), 2) + 2, b.get(r.i(), r.j(), 2), 1e-12);
        }
        assertSame(base.patches().get(1), moved.patches().get(1), "untouched patches are shared");
        assertEquals(base.patches().get(3).get(1, 1, 0), moved.patches().get(3).get(1, 1, 0), "other points stay");
    }

    @Test
    void draggingEmptySpaceRotatesTheViewNotTheModel() {
        Scene before = app.document().scene();
        OrbitView view = app.view().view();
        app.pointer().pressed(5, 5);
        app.pointer().dragged(60, 25);
        app.pointer().released(60, 25);
        assertSame(before, app.document().scene());
        assertNotEquals(view, app.view().view());
        assertFalse(app.document().history().canUndo());
    }

    @Test
    void hoverHighlightsThePointUnderTheCursorAndMovesWithTheView() {
        double[] at = screen(2, 3);
        app.pointer().moved(at[0] + 3, at[1]);
        assertEquals(new PointRef(0, 2, 3), app.overlay().hover().ref());
        app.view().zoom(1);
        double[] moved = screen(2, 3);
        assertEquals(moved[0], app.overlay().hover().x(), 1e-3, "the highlight follows the point");
        app.pointer().moved(1, 1);
        assertNull(app.overlay().hover());
        app.settings().toggle(Toggle.CONTROL_POINTS);
        app.pointer().moved(moved[0], moved[1]);
        assertNull(app.overlay().hover(), "hidden points cannot be picked");
    }

    @Test
    void aMalformedFileShowsOneLineAndKeepsTheModel() throws IOException {
        Path bad = dir.resolve("bad.bpt");
        Files.writeString(bad, "1\n3 3\n0 0 zero\n");
        Scene before = app.document().scene();
        app.files().open(bad);
        assertEquals(1, dialogs.errors.size());
        assertTrue(dialogs.errors.get(0).startsWith(bad.toString()), dialogs.errors.get(0));
        assertFalse(dialogs.errors.get(0).contains("\n"));
        assertSame(before, app.document().scene());
        assertNull(app.status().task(), "no task left in the status bar");
    }

    @Test
    void aFileWithReaderNotesShowsThemOnceInTheStatusLine() throws IOException {
        Path cad = dir.resolve("cad-export.obj");
        try (var in = getClass().getResourceAsStream("/org/beziertracer/model/io/cad-export.obj")) {
            Files.write(cad, in.readAllBytes());
        }
        app.files().open(cad);
        assertEquals(2, app.document().scene().patchCount());
        assertEquals("opened cad-export.obj — " + cad + ": skipped 2 curv, 1 scrv, 1 sp, 1 con (3-D curves, special "
                + "curves, special points and connectivity hints are not drawn)", app.status().message());
        assertTrue(dialogs.errors.isEmpty(), "a note is not an error: " + dialogs.errors);
        app.files().openBuiltIn("teapot");
        assertEquals("opened teapot", app.status().message(), "the next file's status has no note of the last");
    }

    @Test
    void unsavedEditsPromptBeforeOpeningAndCancelKeepsThem() {
        dragPoint(2, 2, 0, -50);
        Scene edited = app.document().scene();
        dialogs.discard = UserDialogs.Choice.CANCEL;
        app.files().openBuiltIn("teapot");
        assertEquals(1, dialogs.prompts);
        assertSame(edited, app.document().scene());
        dialogs.discard = UserDialogs.Choice.DISCARD;
        app.files().openBuiltIn("teapot");
        assertEquals(32, app.document().scene().patchCount());
        assertFalse(app.document().isDirty());
        assertEquals("teapot — Bézier Tracer", app.document().title());
        assertEquals("opened teapot", app.status().message());
    }

    @Test
    void saveWritesBptAtomicallyClearsDirtyAndQuitClosesTheEngine() throws IOException {
        dragPoint(0, 0, 20, 20);
        Path out = dir.resolve("edited.bpt");
        boolean[] then = {false};
        app.files().saveTo(out, () -> then[0] = true);
        assertTrue(then[0]);
        assertFalse(app.document().isDirty());
        assertEquals("edited.bpt", app.document().name());
        assertEquals(app.document().scene().patches(), Models.load(out.toString()).patches());
        boolean[] closed = {false};
        app.files().quit(() -> closed[0] = true);
        assertEquals(0, dialogs.prompts, "nothing unsaved: closing does not ask");
        assertTrue(closed[0]);
        assertTrue(engine.closed);
    }

    @Test
    void quittingWithUnsavedEditsSavesFirstWhenAsked() throws IOException {
        dragPoint(1, 2, 10, 10);
        Path out = dir.resolve("kept.obj");
        dialogs.discard = UserDialogs.Choice.SAVE;
        dialogs.save = out;
        boolean[] closed = {false};
        app.files().quit(() -> closed[0] = true);
        assertTrue(closed[0]);
        assertEquals(app.document().scene().patches(), Models.load(out.toString()).patches());
    }

    @Test
    void settingsReachTheRenderRequestTyped() {
        SettingsModel s = app.settings();
        s.toggle(Toggle.NORMALS);
        s.toggle(Toggle.SUPER_SAMPLING);
        s.set(Method.NEWTON);
        s.toggle(Toggle.BVH);
        s.set(Level.PERSPECTIVE, 0);
        RenderRequest r = lastRequest();
        assertEquals(ShadingMode.NORMALS.label(), r.settings().shading());
        assertEquals(4, r.settings().spp());
        assertEquals(Method.NEWTON, r.intersect().method());
        assertFalse(r.intersect().bvh());
        assertEquals(0, r.camera().fovDegrees(), "perspective 0 is orthographic");
        int n = engine.requests.size();
        s.toggle(Toggle.RAY_TRACE);
        assertEquals(n, engine.requests.size(), "the wireframe view does not ray trace");
        assertTrue(app.overlay().geometry().isoCurves().size() > 0, "the wireframe view draws iso-curves");
    }

    @Test
    void tessellatedModeReachesTheRenderRequestAndTheStatusLabel() {
        RenderRequest exact = lastRequest();
        assertEquals(0, exact.intersect().tessellate(), "exact by default");
        assertEquals("clipping", app.settings().current().intersectionLabel());
        app.settings().toggle(Toggle.TESSELLATED);
        assertEquals(Level.TESSELLATION.initial(), lastRequest().intersect().tessellate());
        app.settings().set(Level.TESSELLATION, 8);
        RenderRequest r = lastRequest();
        assertEquals(8, r.intersect().tessellate());
        assertEquals(8, r.options().tessellate());
        assertEquals("tessellated 8", app.settings().current().intersectionLabel());
        assertEquals(exact.settings(), r.settings(), "same method, BVH and shading: only the surface changes");
        app.settings().toggle(Toggle.TESSELLATED);
        assertEquals(0, lastRequest().intersect().tessellate());
        assertEquals(8, app.settings().current().level(Level.TESSELLATION), "K is kept for the next time");
        UserMessages.of(IllegalArgumentException.class, () -> app.settings().set(Level.TESSELLATION, 0));
    }

    @Test
    void randomizeShowsItsSeedAndResetFlattens() {
        app.edits().randomize(1234);
        assertTrue(app.status().message().contains("1234"), app.status().message());
        assertEquals(NetEdits.randomize(Models.patch(), 1234).patches(), app.document().scene().patches());
        app.settings().set(Level.GRID_U, 6);
        app.edits().replaceWithFlatGrid();
        assertEquals(5, app.document().scene().patches().get(0).degreeU());
        app.edits().undo();
        app.edits().undo();
        assertEquals(Models.patch().patches(), app.document().scene().patches());
    }

    @Test
    void resetControlPointsThenUndoRestoresThePointsAndTheFraming() {
        app.files().openBuiltIn("teapot");
        app.view().rotate(40, -10);
        app.view().zoom(2);
        OrbitView teapotView = app.view().view();
        app.edits().replaceWithFlatGrid();
        assertEquals(1, app.document().scene().patchCount());
        assertNotEquals(teapotView.framing(), app.view().view().framing(), "the reset re-frames on the grid");
        assertEquals(teapotView.zoom(), app.view().view().zoom(), "and keeps the zoom");
        app.edits().undo();
        assertEquals(32, app.document().scene().patchCount());
        assertEquals(teapotView, app.view().view(), "undo puts the teapot's framing back");
        app.edits().redo();
        assertEquals(1, app.document().scene().patchCount());
        assertEquals(Framing.of(app.document().scene().controlBounds()), app.view().view().framing());
    }

    @Test
    void revertToOriginalBringsBackTheOpenedModelAsOneUndoableEditBesideTheFlatGrid() {
        app.files().openBuiltIn("teapot");
        Scene teapot = app.document().scene();
        assertSame(teapot, app.document().original());
        app.edits().revertToOriginal();
        assertFalse(app.document().history().canUndo(), "the original already: no edit");
        assertTrue(app.status().message().contains("as it was opened"), app.status().message());
        app.edits().randomize(99);
        app.edits().replaceWithFlatGrid();
        assertEquals(1, app.document().scene().patchCount(), "the flat grid is one patch");
        assertEquals(EditCommands.FLAT_GRID, app.document().history().undoName());
        app.edits().revertToOriginal();
        assertSame(teapot, app.document().scene(), "every point of the teapot back, all 32 patches");
        assertEquals(EditCommands.REVERT, app.document().history().undoName());
        assertEquals(Framing.of(teapot.controlBounds()), app.view().view().framing(), "framed on the teapot again");
        app.edits().undo();
        assertEquals(1, app.document().scene().patchCount(), "undo: the flat grid again");
        app.edits().redo();
        assertSame(teapot, app.document().scene());
        assertFalse(app.document().isDirty(), "the original is what was opened: nothing to save");
        // A model opened afterwards is the new original
        app.files().openBuiltIn("sphere");
        assertSame(app.document().scene(), app.document().original());
    }

    @Test
    void anEditThatArrivesAfterTheModelChangedIsDropped() {
        java.util.List<Runnable> later = new java.util.ArrayList<>();
        AppThreads queued = new AppThreads(Runnable::run, later::add, Runnable::run, Runnable::run, Runnable::run, Runnable::run);
        AppModel m = new AppModel(new FakeEngine(), dialogs, queued, MemoryPreferences.fresh());
        m.view().resize(400, 300, 1);
        m.edits().randomize(99);
        m.files().openBuiltIn("teapot");
        later.forEach(Runnable::run);
        assertEquals(32, m.document().scene().patchCount(), "the randomized patch did not land on the teapot");
        assertFalse(m.document().history().canUndo());
    }
}
