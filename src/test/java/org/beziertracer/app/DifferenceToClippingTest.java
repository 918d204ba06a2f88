package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** View → Difference to clipping without a display: the mask, the criterion, and the model's staleness rules. */
class DifferenceToClippingTest {

    private static final int W = 80, H = 60;
    private static Scene teapot;
    private static OrbitView home;

    @BeforeAll
    static void load() {
        teapot = ModelLoader.builtIn("teapot").scene();
        home = ViewModel.home(teapot, teapot.controlBounds(), OrbitView.DEFAULT_FOV_DEGREES);
    }

    private static CameraSpec camera(OrbitView v) { return v.camera((double) W / H); }

    /** The teapot as 4×4 triangle pairs per patch: far from the exact surface. */
    private static final IntersectOptions TESSELLATED = IntersectOptions.defaults().withTessellate(4);

    private static SceneIntersector build(Method m) {
        return SceneIntersector.build(teapot, IntersectOptions.defaults().withMethod(m));
    }

    private static DifferenceMask compare(IntersectOptions o, String label, OrbitView v) {
        return DifferenceMask.compare(SceneIntersector.build(teapot, o), build(Method.CLIPPING), camera(v), W, H, label,
                () -> false);
    }

    private static int marked(DifferenceMask mask) {
        int n = 0;
        for (int y = 0; y < mask.height(); y++) {
            for (int x = 0; x < mask.width(); x++) {
                n += mask.marked(x, y) ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void clippingAgainstItselfDiffersNowhere() {
        DifferenceMask mask = compare(IntersectOptions.defaults(), "clipping", home);
        assertEquals(0, mask.count());
        assertEquals(0, marked(mask));
        assertEquals("clipping: 0 pixels differ from clipping", mask.describe());
        for (int c : mask.argb()) {
            assertEquals(DifferenceMask.VEIL, c);
        }
    }

    @Test
    void aCoarseTessellationOfTheTeapotDiffersAndTheMaskShowsExactlyTheCountedPixels() {
        DifferenceMask mask = compare(TESSELLATED, "tessellated 4", home);
        assertTrue(mask.count() > W * H / 20, "flat triangles lie off the curved surface: " + mask.count());
        assertTrue(mask.count() < W * H, "the background agrees (both miss): " + mask.count());
        assertEquals(mask.count(), marked(mask));
        int red = 0;
        for (int c : mask.argb()) {
            red += c == DifferenceMask.MARK ? 1 : 0;
        }
        assertEquals(mask.count(), red, "one red mark per differing pixel");
        assertEquals("tessellated 4: " + mask.count() + " pixels differ from clipping", mask.describe());
        assertFalse(mask.marked(0, 0), "a corner of the picture is background: both miss");
    }

    @Test
    void theCriterionIsPatchHitOrMissAndTBeyondTheTolerance() {
        Hit a = new Hit(), b = new Hit();
        a.kind = b.kind = Hit.PATCH;
        a.index = b.index = 3;
        a.t = 2;
        b.t = 2 + 0.9e-3;
        assertFalse(DifferenceMask.differ(false, a, false, b, 1e-3), "both miss");
        assertTrue(DifferenceMask.differ(true, a, false, b, 1e-3), "hit against miss");
        assertTrue(DifferenceMask.differ(false, a, true, b, 1e-3), "miss against hit");
        assertFalse(DifferenceMask.differ(true, a, true, b, 1e-3), "same patch, t within the tolerance");
        b.t = 2 + 1.1e-3;
        assertTrue(DifferenceMask.differ(true, a, true, b, 1e-3), "same patch, t beyond the tolerance");
        b.t = 2;
        b.index = 4;
        assertTrue(DifferenceMask.differ(true, a, true, b, 1e-3), "another patch at the same t");
        b.index = 3;
        b.kind = Hit.PLANE;
        assertTrue(DifferenceMask.differ(true, a, true, b, 1e-3), "a plane with the patch's index");
        b.kind = Hit.PATCH;
        a.t = Double.NaN;
        assertTrue(DifferenceMask.differ(true, a, true, b, 1e-3), "a NaN distance is no agreement");
    }

    @Test
    void newtonAndSubdivisionAgreeWithClippingOnTheTeapotAtASmallSize() {
        assertEquals(0, compare(IntersectOptions.defaults().withMethod(Method.NEWTON), "newton", home).count());
        assertEquals(0, compare(IntersectOptions.defaults().withMethod(Method.SUBDIVISION), "subdivision", home).count());
    }

    @Test
    void aComparisonStopsWhenItIsCancelled() {
        int[] rows = {0};
        DifferenceMask mask = DifferenceMask.compare(build(Method.NEWTON), build(Method.CLIPPING), camera(home), W, H,
                "newton", () -> ++rows[0] > 3);
        assertNull(mask);
        assertEquals(4, rows[0], "checked once per row, stopped at the first check that said so");
    }

    // ------------------------------------------------------------------ the model

    private final List<Runnable> worker = new ArrayList<>();
    private final List<Runnable> ui = new ArrayList<>();
    private int changes;
    private final DifferenceModel model = new DifferenceModel(worker::add, ui::add, () -> changes++,
            e -> fail("comparison failed: " + e));

    private static void runAll(List<Runnable> queue) {
        while (!queue.isEmpty()) {
            queue.remove(0).run();
        }
    }

    private void request(OrbitView v, IntersectOptions o) {
        model.request(teapot, camera(v), W, H, o, o.tessellated() ? "tessellated" : o.method().label());
    }

    @Test
    void aResultThatArrivesAfterTheViewMovedIsDropped() {
        OrbitView turned = home.turned(new Arcball(800, 600).drag(400, 300, 440, 300));
        request(home, TESSELLATED);
        assertTrue(model.computing());
        runAll(worker); // the first comparison finished, its result is on its way to the UI thread
        request(turned, TESSELLATED);
        runAll(ui);
        assertNull(model.current(), "the mask of the old view is not shown");
        assertTrue(model.computing() && model.busy());
        runAll(worker);
        runAll(ui);
        assertNotNull(model.current());
        assertEquals(compare(TESSELLATED, "tessellated", turned).count(), model.current().count(), "the mask of the new view");
        assertTrue(compare(TESSELLATED, "tessellated", home).count() != model.current().count(), "not the old view's");
        assertFalse(model.computing() || model.busy());
    }

    @Test
    void switchedOffBeforeTheResultArrivesShowsNothing() {
        request(home, TESSELLATED);
        model.clear();
        runAll(worker);
        runAll(ui);
        assertNull(model.current());
        assertFalse(model.computing());
    }

    @Test
    void theSameRequestAgainComputesNothing() {
        request(home, IntersectOptions.defaults());
        runAll(worker);
        runAll(ui);
        int seen = changes;
        request(home, IntersectOptions.defaults());
        assertTrue(worker.isEmpty(), "nothing to compute");
        assertEquals(seen, changes);
        assertEquals(0, model.current().count());
        request(home, TESSELLATED);
        assertNull(model.current(), "another method: the mask is stale at once");
        assertEquals(1, worker.size());
    }

    @Test
    void switchedOffItLetsGoOfTheComparedModelEvenAfterMoreClears() throws InterruptedException {
        // The worker's two snapshots held the last compared model for ever (the app soak saw the
        // heap grow from 10 to 87 MB): a clear must release them, even when more clears follow
        // before the worker runs (each one makes the previous request stale)
        java.lang.ref.WeakReference<org.beziertracer.model.Scene> compared = compareACopyAndSwitchOff();
        for (int k = 0; k < 20 && compared.get() != null; k++) {
            System.gc();
            Thread.sleep(20);
        }
        assertNull(compared.get(), "the compared model was let go");
    }

    private java.lang.ref.WeakReference<org.beziertracer.model.Scene> compareACopyAndSwitchOff() {
        org.beziertracer.model.Scene copy = teapot.toBuilder().build();
        model.request(copy, camera(home), W, H, IntersectOptions.defaults(), "clipping");
        runAll(worker);
        runAll(ui);
        assertEquals(0, model.current().count());
        model.clear();
        model.clear();
        runAll(worker);
        runAll(ui);
        return new java.lang.ref.WeakReference<>(copy);
    }

    // ------------------------------------------------------------------ in the app

    @Test
    void theAppComparesTheSelectedMethodAndForgetsTheMaskWhenSwitchedOff() {
        AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());
        app.view().resize(W, H, 1);
        app.files().openBuiltIn("teapot");
        assertNull(app.difference().current(), "off: nothing computed");
        app.settings().toggle(Toggle.DIFFERENCE_TO_CLIPPING);
        assertEquals(0, app.difference().current().count(), "clipping against clipping");
        app.settings().set(Method.NEWTON);
        assertEquals("newton", app.difference().current().method());
        app.settings().toggle(Toggle.TESSELLATED);
        DifferenceMask sub = app.difference().current();
        assertTrue(sub.count() > 0, "the tessellated teapot differs");
        assertEquals(app.settings().current().intersectionLabel(), sub.method());
        app.view().rotate(40, 0);
        assertTrue(app.difference().current() != sub, "a moved view gets a new mask");
        app.settings().toggle(Toggle.DIFFERENCE_TO_CLIPPING);
        assertNull(app.difference().current(), "off: the mask is gone");
        assertFalse(app.busy());
        app.close();
    }
}
