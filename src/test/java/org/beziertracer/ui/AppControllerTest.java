package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.beziertracer.UserMessages;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Controller logic without a window: mouse in device pixels, fake engine and dialogs. */
class AppControllerTest {

    @TempDir
    Path dir;
    private FakeEngine engine;
    private FakeDialogs dialogs;
    private AppController c;

    @BeforeEach
    void setUp() {
        engine = new FakeEngine();
        dialogs = new FakeDialogs();
        c = new AppController(engine, dialogs);
        c.viewport(800, 600, 1);
    }

    private void dragPoint(int i, int j, double dx, double dy) {
        ProjectedScene ps = c.projected();
        double x = ps.x(0, i, j), y = ps.y(0, i, j);
        c.mousePressed(x, y);
        for (int k = 1; k <= 10; k++) {
            c.mouseDragged(x + dx * k / 10, y + dy * k / 10);
        }
        c.mouseReleased(x + dx, y + dy);
    }

    @Test
    void opensOnTheDefaultBicubicPatchLitFromTheEye() {
        assertEquals(1, c.scene().patchCount());
        assertEquals(3, c.scene().patches().get(0).degreeU());
        assertTrue(c.scene().lights().isEmpty(), "no lights: the renderer puts one at the eye");
        assertFalse(c.history().isDirty());
        assertEquals(1, engine.requests.size(), "first layout starts a render");
    }

    @Test
    void draggingAPointMovesItUnderTheCursorAsOneUndoableEdit() {
        Scene before = c.scene();
        int renders = engine.requests.size();
        dragPoint(1, 1, 30, -40);
        assertEquals(renders + 10, engine.requests.size(), "every drag event restarts a render");
        ProjectedScene ps = c.projected();
        assertEquals(before.patches().get(0).get(1, 1, 0) != c.scene().patches().get(0).get(1, 1, 0), true);
        ProjectedScene old = new ProjectedScene(before, c.projector());
        assertEquals(old.x(0, 1, 1) + 30, ps.x(0, 1, 1), 1e-6);
        assertEquals(old.y(0, 1, 1) - 40, ps.y(0, 1, 1), 1e-6);
        assertTrue(c.history().isDirty());
        c.undo();
        assertSame(before, c.scene());
        assertArrayEquals(before.patches().get(0).copyNet(), c.scene().patches().get(0).copyNet());
        assertFalse(c.history().canUndo(), "one drag, one edit");
        c.redo();
        assertNotEquals(before, c.scene());
    }

    @Test
    void draggingEmptySpaceRotatesTheViewNotTheModel() {
        Scene before = c.scene();
        OrbitView view = c.view();
        c.mousePressed(5, 5);
        c.mouseDragged(60, 25);
        c.mouseReleased(60, 25);
        assertSame(before, c.scene());
        assertNotEquals(view, c.view());
        assertFalse(c.history().canUndo());
    }

    @Test
    void hoverHighlightsThePointUnderTheCursor() {
        ProjectedScene ps = c.projected();
        c.mouseMoved(ps.x(0, 2, 3) + 3, ps.y(0, 2, 3));
        assertEquals(new PointRef(0, 2, 3), c.hover());
        c.mouseMoved(1, 1);
        assertEquals(null, c.hover());
    }

    @Test
    void aMalformedFileShowsOneLineAndKeepsTheModel() throws IOException {
        Path bad = dir.resolve("bad.bpt");
        Files.writeString(bad, "1\n3 3\n0 0 zero\n");
        Scene before = c.scene();
        assertFalse(c.open(bad));
        assertEquals(1, dialogs.errors.size());
        assertTrue(dialogs.errors.get(0).startsWith(bad.toString()), dialogs.errors.get(0));
        assertFalse(dialogs.errors.get(0).contains("\n"));
        assertSame(before, c.scene());
    }

    @Test
    void unsavedEditsPromptBeforeOpeningAndCancelKeepsThem() {
        dragPoint(2, 2, 0, -50);
        Scene edited = c.scene();
        dialogs.discard = UserDialogs.Choice.CANCEL;
        assertFalse(c.openBuiltIn("teapot"));
        assertEquals(1, dialogs.prompts);
        assertSame(edited, c.scene());
        dialogs.discard = UserDialogs.Choice.DISCARD;
        assertTrue(c.openBuiltIn("teapot"));
        assertEquals(32, c.scene().patchCount());
        assertFalse(c.history().isDirty());
    }

    @Test
    void saveWritesBptAtomicallyAndClearsDirty() throws IOException {
        dragPoint(0, 0, 20, 20);
        Path out = dir.resolve("edited.bpt");
        assertTrue(c.saveTo(out));
        assertFalse(c.history().isDirty());
        assertEquals(c.scene().patches(), Models.load(out.toString()).patches());
        assertTrue(c.quit(), "nothing unsaved: closing does not ask");
        assertTrue(engine.closed);
    }

    @Test
    void toolboxSettingsReachTheRenderRequest() {
        c.setting(() -> c.tools().normals = true);
        c.setting(() -> c.tools().superSampling = true);
        c.setMethod(org.beziertracer.intersect.Method.NEWTON);
        c.setting(() -> c.tools().bvh = false);
        c.setting(() -> c.tools().perspective = 0);
        RenderRequest r = engine.requests.get(engine.requests.size() - 1);
        assertEquals("normals", r.settings().shading());
        assertEquals(4, r.settings().spp());
        assertEquals("newton", r.settings().method());
        assertFalse(r.settings().bvh());
        assertEquals(0, r.camera().fovDegrees(), "perspective 0 is orthographic");
        int n = engine.requests.size();
        c.toggleRayTrace();
        assertEquals(n, engine.requests.size(), "the wireframe view does not ray trace");
    }

    @Test
    void tessellatedModeReachesTheRenderRequestAndTheStatusLabel() {
        RenderRequest exact = engine.requests.get(engine.requests.size() - 1);
        assertEquals(0, exact.tessellate(), "exact by default");
        assertEquals("clipping", c.tools().intersectionLabel());
        c.setTessellated(true);
        RenderRequest r = engine.requests.get(engine.requests.size() - 1);
        assertEquals(ToolSettings.DEFAULT_TESSELLATION, r.tessellate());
        assertEquals("tessellated " + ToolSettings.DEFAULT_TESSELLATION, c.tools().intersectionLabel());
        c.setTessellation(8);
        r = engine.requests.get(engine.requests.size() - 1);
        assertEquals(8, r.tessellate());
        assertEquals("tessellated 8", c.tools().intersectionLabel());
        assertEquals(exact.settings(), r.settings(), "same method, BVH and shading: only the surface changes");
        c.setTessellated(false);
        assertEquals(0, engine.requests.get(engine.requests.size() - 1).tessellate());
        assertEquals(8, c.tools().tessellation, "K is kept for the next time the mode is on");
        UserMessages.of(IllegalArgumentException.class, () -> c.setTessellation(0));
    }

    @Test
    void randomizeShowsItsSeedAndResetFlattens() {
        c.randomizeControlPoints(1234);
        assertTrue(c.message().contains("1234"), c.message());
        assertEquals(NetEdits.randomize(Models.patch(), 1234).patches(), c.scene().patches());
        c.tools().gridPointsU = 6;
        c.resetControlPoints();
        assertEquals(5, c.scene().patches().get(0).degreeU());
        c.undo();
        c.undo();
        assertEquals(Models.patch().patches(), c.scene().patches());
    }
}
