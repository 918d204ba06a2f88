package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.beziertracer.geometry.Patches;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class OverlayBuilderTest {

    private static Scene randomPatch() {
        return NetEdits.randomize(Models.patch(), 11);
    }

    private static ScreenProjector fit(Scene s, double fov, int w, int h) {
        return new ScreenProjector(OrbitView.fit(s.controlBounds(), fov).camera((double) w / h), w, h);
    }

    private static OverlayGeometry build(Scene s, ScreenProjector p, int iso) {
        return OverlayBuilder.build(new OverlayRequest(s, p, true, true, iso, 1));
    }

    @Test
    void pickFindsTheNearestControlPointWithinTheRadius() {
        Scene s = randomPatch();
        ScreenProjector p = fit(s, 40, 800, 600);
        OverlayGeometry g = build(s, p, 0);
        double[] at = new double[3];
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                var q = s.patches().get(0);
                p.project(q.get(i, j, 0), q.get(i, j, 1), q.get(i, j, 2), at);
                Handle got = g.pick(at[0] + 2, at[1] - 1, 6);
                assertNotNull(got, "pick near P" + i + j);
                assertEquals(new PointRef(0, i, j), got.ref(), "pick near P" + i + j);
                assertEquals(at[0], got.x(), 1e-3);
            }
        }
        assertNull(g.pick(-100, -100, 6));
    }

    @Test
    void orthographicWireframeIsTheProjectionOfTheSurface() {
        // A parallel projection is affine, and Bézier surfaces are affine invariant: the cheap 2-D
        // evaluation on projected control points is then exact.
        Scene s = randomPatch();
        CameraSpec ortho = OrbitView.fit(s.controlBounds(), 0).camera(1);
        ScreenProjector p = new ScreenProjector(ortho, 500, 500);
        int k = 6;
        List<float[]> curves = build(s, p, k).isoCurves();
        assertEquals(2 * (k + 1), curves.size());
        double[] out = new double[3];
        for (int b = 0; b <= k; b++) {
            float[] line = curves.get(b);
            for (int a = 0; a <= k; a++) {
                Vec3 q = Patches.evaluate(s.patches().get(0), (double) a / k, (double) b / k);
                p.project(q.x(), q.y(), q.z(), out);
                assertEquals(out[0], line[2 * a], 1e-3);
                assertEquals(out[1], line[2 * a + 1], 1e-3);
            }
        }
    }

    @Test
    void thePolygonJoinsNeighboursAlongRowsAndColumns() {
        Scene s = randomPatch();
        OverlayGeometry g = build(s, fit(s, 40, 640, 480), 0);
        assertEquals(3 * 4 + 4 * 3, g.segmentCount(), "a bicubic net: 12 row and 12 column segments");
        assertEquals(0, g.isoCurves().size(), "no iso-curves asked for");
        OverlayGeometry none = OverlayBuilder.build(new OverlayRequest(s, fit(s, 40, 640, 480), false, false, 0, 1));
        assertEquals(0, none.handleCount());
        assertEquals(0, none.segmentCount());
        assertEquals(16, none.pointCount(), "the count is of the model, drawn or not");
    }

    @Test
    void theWireframeViewDrawsControlPolygonAndPointsOnlyWhenTheirTogglesAreOn() {
        Scene s = randomPatch();
        ScreenProjector p = fit(s, 40, 640, 480);
        Settings wireframe = Settings.defaults().with(Toggle.RAY_TRACE, false);
        Settings neither = wireframe.with(Toggle.CONTROL_POLYGON, false).with(Toggle.CONTROL_POINTS, false);
        OverlayGeometry none = OverlayBuilder.build(OverlayRequest.of(s, p, neither, 1));
        assertEquals(0, none.handleCount(), "Control Points unchecked: no handles in the wireframe view");
        assertEquals(0, none.segmentCount(), "Control Polygon unchecked: no polygon in the wireframe view");
        assertFalse(none.isoCurves().isEmpty(), "the wireframe view still draws its iso-curves");
        assertFalse(neither.pointsShown(), "unchecked points cannot be picked either");
        OverlayGeometry pointsOnly = OverlayBuilder.build(OverlayRequest.of(s, p, wireframe.with(Toggle.CONTROL_POLYGON, false), 1));
        assertEquals(16, pointsOnly.handleCount());
        assertEquals(0, pointsOnly.segmentCount());
        OverlayGeometry polygonOnly = OverlayBuilder.build(OverlayRequest.of(s, p, wireframe.with(Toggle.CONTROL_POINTS, false), 1));
        assertEquals(0, polygonOnly.handleCount());
        assertEquals(24, polygonOnly.segmentCount());
    }

    /** A grid of side × side flat bicubic patches, one unit each, in z = 0. */
    static Scene grid(int side) {
        return Scene.builder().patches(BigModels.grid(side * side)).build();
    }

    @Test
    void aDenseModelGetsABoundedOverlayThatThinsByScreenDensity() {
        Scene s = grid(100); // 10 000 patches, 160 000 points, on a big picture: more cells than the budget
        ScreenProjector far = fit(s, 40, 1600, 1200);
        // Every patch selected: all their handles stay drawn, thinned (with none, only the focus would be)
        int[] all = java.util.stream.IntStream.range(0, s.patchCount()).toArray();
        OverlayGeometry g = OverlayBuilder.build(new OverlayRequest(s, far, true, true, 12, 1, Double.NaN, Double.NaN, all));
        assertTrue(g.focused());
        assertTrue(g.handleCount() <= OverlayBuilder.HANDLE_BUDGET, "handles " + g.handleCount());
        assertTrue(g.handleCount() > OverlayBuilder.HANDLE_BUDGET / 4, "the screen still fills with handles: "
                + g.handleCount());
        assertTrue(g.thinned());
        assertTrue(g.segmentCount() <= OverlayBuilder.SEGMENT_BUDGET, "segments " + g.segmentCount());
        long curvePoints = g.isoCurves().stream().mapToLong(c -> c.length / 2).sum();
        assertTrue(curvePoints <= OverlayBuilder.CURVE_POINT_BUDGET, "curve points " + curvePoints);
        assertEquals(160_000, g.pointCount());
        // No two handles in one cell (merged cells are whole multiples of the first)
        double cell = Math.ceil(2 * OverlayBuilder.HANDLE_RADIUS);
        Set<Long> cells = new HashSet<>();
        for (int k = 0; k < g.handleCount(); k++) {
            long key = (long) Math.floor(g.handleX(k) / cell) * 100_000 + (long) Math.floor(g.handleY(k) / cell);
            assertTrue(cells.add(key), "one handle per cell at most");
        }
    }

    /** The pixel of the centroid of patch {@code p}'s control points. */
    private static double[] centreOf(Scene s, int p, ScreenProjector projector) {
        var patch = s.patches().get(p);
        double x = 0, y = 0, z = 0;
        for (int j = 0; j <= patch.degreeV(); j++) {
            for (int i = 0; i <= patch.degreeU(); i++) {
                x += patch.get(i, j, 0) / patch.pointCount();
                y += patch.get(i, j, 1) / patch.pointCount();
                z += patch.get(i, j, 2) / patch.pointCount();
            }
        }
        double[] at = new double[3];
        projector.project(x, y, z, at);
        return at;
    }

    @Test
    void denseHandlesShowOnlyThePatchUnderTheMouseAndTheSelectedPatches() {
        Scene s = grid(100); // 10 000 patches on 1600×1200: about 16 pixels a patch, handles far denser than points
        ScreenProjector far = fit(s, 40, 1600, 1200);
        OverlayGeometry none = OverlayBuilder.build(new OverlayRequest(s, far, true, true, 0, 1));
        assertTrue(none.focused(), "dense: focus mode");
        assertEquals(0, none.handleCount(), "no mouse, nothing selected: no handles cover the surface");
        assertEquals(-1, none.underMouse());
        double[] at = centreOf(s, 4242, far);
        OverlayGeometry hovered = OverlayBuilder.build(new OverlayRequest(s, far, true, true, 0, 1, at[0], at[1], new int[0]));
        assertEquals(4242, hovered.underMouse(), "the patch under the mouse");
        assertTrue(hovered.handleCount() > 0 && hovered.handleCount() <= 16, "its handles: " + hovered.handleCount());
        for (int k = 0; k < hovered.handleCount(); k++) {
            assertEquals(4242, hovered.handle(k).ref().patch(), "only the hovered patch's handles");
        }
        assertNotNull(hovered.pick(at[0], at[1], 16), "and they can be picked");
        int[] selected = {17, 9001};
        OverlayGeometry both = OverlayBuilder.build(new OverlayRequest(s, far, true, true, 0, 1, at[0], at[1], selected));
        Set<Integer> patches = new HashSet<>();
        for (int k = 0; k < both.handleCount(); k++) {
            patches.add(both.handle(k).ref().patch());
        }
        assertEquals(Set.of(17, 4242, 9001), patches, "the hovered and the selected patches");
        // Not dense: the teapot, and the same grid zoomed in, show every handle whatever the mouse
        Scene teapot = Models.teapot();
        OverlayGeometry t = OverlayBuilder.build(new OverlayRequest(teapot, fit(teapot, 40, 1600, 1200), true, true, 0, 1));
        assertFalse(t.focused());
        assertTrue(t.handleCount() > 250, "the teapot's handles: " + t.handleCount());
        CameraSpec close = new CameraSpec(new Vec3(1.5, 1.5, 10), new Vec3(1.5, 1.5, 0), new Vec3(0, 1, 0), 0, 20);
        OverlayGeometry zoomed = build(s, new ScreenProjector(close, 800, 800), 0);
        assertFalse(zoomed.focused(), "zoomed in, a handle per point: " + zoomed.handleCount());
    }

    @Test
    void refocusingReusesTheLastBuildAndGivesWhatAFullBuildGives() {
        Scene s = grid(100);
        ScreenProjector far = fit(s, 40, 1600, 1200);
        OverlayGeometry first = OverlayBuilder.build(new OverlayRequest(s, far, true, true, 0, 1));
        java.util.Random rnd = new java.util.Random(8);
        OverlayGeometry last = first;
        for (int trial = 0; trial < 20; trial++) {
            double x = rnd.nextDouble() * 1600, y = rnd.nextDouble() * 1200;
            int[] focus = trial % 3 == 0 ? new int[] {rnd.nextInt(s.patchCount())} : new int[0];
            OverlayRequest r = new OverlayRequest(s, fit(s, 40, 1600, 1200), true, true, 0, 1, x, y, focus);
            OverlayGeometry full = OverlayBuilder.build(r), again = OverlayBuilder.build(last, r);
            String at = "mouse at " + x + ", " + y + ", focus " + java.util.Arrays.toString(focus);
            assertEquals(full.underMouse(), again.underMouse(), at);
            assertEquals(full.handleCount(), again.handleCount(), at);
            for (int k = 0; k < full.handleCount(); k++) {
                assertEquals(full.handle(k), again.handle(k), at);
            }
            assertSame(first.focusIndex(), again.focusIndex(), "the boxes are reused, not projected again: " + at);
            last = again;
        }
        // Another view: built afresh
        ScreenProjector turned = new ScreenProjector(OrbitView.fit(s.controlBounds(), 40)
                .turned(new Arcball(1600, 1200).drag(800, 600, 900, 600)).camera(1600.0 / 1200), 1600, 1200);
        OverlayGeometry moved = OverlayBuilder.build(last, new OverlayRequest(s, turned, true, true, 0, 1));
        assertTrue(moved.focusIndex() != null && moved.focusIndex() != first.focusIndex(), "a new view is built again");
    }

    @Test
    void theAppRebuildsDenseHandlesForTheMouseAndTheSelection() {
        AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());
        try {
            app.view().resize(1600, 1200, 1);
            Scene s = grid(100);
            app.files().open("grid", () -> new org.beziertracer.model.io.SceneDocument(s,
                    org.beziertracer.model.RenderSettings.defaults()));
            OverlayGeometry g = app.overlay().geometry();
            assertTrue(g.focused(), "10 000 patches on screen: dense");
            assertEquals(0, g.handleCount());
            double[] at = centreOf(app.document().scene(), 4242, app.view().projector());
            app.pointer().moved(at[0], at[1]);
            assertEquals(4242, app.overlay().geometry().underMouse(), "the mouse brings up the patch under it");
            assertTrue(app.overlay().geometry().handleCount() > 0);
            // Over one of its handles the focus stays, though the neighbours' boxes hold a border point too
            Handle h = app.overlay().geometry().handle(0);
            app.pointer().moved(h.x(), h.y());
            assertEquals(4242, app.overlay().geometry().underMouse(), "the handle under the mouse stays grabbable");
            assertEquals(h.ref(), app.overlay().hover().ref());
            app.pointer().moved(at[0], at[1]);
            app.select(Selection.of(new PointRef(17, 1, 1)));
            Set<Integer> patches = new HashSet<>();
            for (int k = 0; k < app.overlay().geometry().handleCount(); k++) {
                patches.add(app.overlay().geometry().handle(k).ref().patch());
            }
            assertEquals(Set.of(17, 4242), patches, "and a selection keeps its patch's handles");
            app.pointer().left();
            assertEquals(-1, app.overlay().geometry().underMouse(), "the mouse left the picture");
        } finally {
            app.close();
        }
    }

    @Test
    void zoomedInEveryPointOnScreenIsDrawn() {
        Scene s = grid(100);
        // Look straight down at one corner patch from close by, orthographic, 40 pixels per unit
        CameraSpec close = new CameraSpec(new Vec3(1.5, 1.5, 10), new Vec3(1.5, 1.5, 0), new Vec3(0, 1, 0), 0, 20);
        ScreenProjector p = new ScreenProjector(close, 800, 800);
        OverlayGeometry g = build(s, p, 0);
        // Points at multiples of 1/3; shared borders coincide and show one handle. The picture spans
        // x, y in [−8.5, 11.5] at 40 pixels per unit, plus a margin of two 7-pixel cells.
        int across = 0;
        for (int x = 0; x <= 300; x++) {
            double sx = (x / 3.0 - 1.5 + 10) * 40;
            if (sx >= -14 && sx < 814) {
                across++;
                for (int y = 0; y <= 300; y++) {
                    double sy = (1.5 - y / 3.0 + 10) * 40;
                    if (sy > -14 && sy <= 814) {
                        assertNotNull(g.pick(sx, sy, 1), "point (" + x + "/3, " + y + "/3) has a handle");
                    }
                }
            }
        }
        int onScreen = across * across;
        assertEquals(onScreen, g.handleCount(), "one handle per distinct point on screen");
        assertFalse(g.segmentCount() == 0);
    }

    @Test
    void pointsBehindTheEyeHideTheirPatch() {
        Scene s = Models.teapot();
        var box = s.controlBounds();
        CameraSpec inside = new CameraSpec(box.center(), box.center().add(new Vec3(1, 0, 0)), Vec3.Z, 60, 1);
        OverlayGeometry g = build(s, new ScreenProjector(inside, 400, 300), 4);
        for (int k = 0; k < g.handleCount(); k++) {
            var ref = g.handle(k).ref();
            var patch = s.patches().get(ref.patch());
            double[] out = new double[3];
            for (int j = 0; j <= patch.degreeV(); j++) {
                for (int i = 0; i <= patch.degreeU(); i++) {
                    assertTrue(new ScreenProjector(inside, 400, 300).project(patch.get(i, j, 0), patch.get(i, j, 1),
                            patch.get(i, j, 2), out), "a drawn patch lies wholly in front of the eye");
                }
            }
        }
    }

    @Test
    void theBudgetKeepsTheBiggestPatchesFirst() {
        float[] extent = {100, 1, 50, -1, 2};
        assertEquals(0, ExtentBudget.threshold(extent, p -> 10, 40), "all four visible patches fit");
        double t = ExtentBudget.threshold(extent, p -> 10, 25);
        assertTrue(t > 2 && t <= 50, "the two biggest fit, the small ones not: " + t);
        assertEquals(Double.POSITIVE_INFINITY, ExtentBudget.threshold(extent, p -> 10, 5));
    }
}
