package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Arrays;

import javax.swing.JTextField;

import org.beziertracer.app.Toggle;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

/**
 * GUI tests of selecting and moving points with the real mouse and keyboard (Robot): clicks with
 * Shift and Ctrl, a rubber band, Escape, a drag along an axis, nudges by arrow key and by menu, the
 * inspector. Checks are on the screen's pixels (selected points are drawn red) and the status bar.
 */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class EditingGuiTest extends GuiSession {

    @TempDir
    Path dir;

    /** True when the screen shows a selected (red) handle at {@code p} (screen coordinates). */
    static boolean redAt(BufferedImage panel, Point inPanel) {
        double[] m = GuiDriver.mean(panel, new Rectangle(inPanel.x - 1, inPanel.y - 1, 3, 3));
        return m[0] > 190 && m[1] < 140 && m[2] < 140;
    }

    private static Point at(int i, int j) { return d.screenOfPoint(0, i, j); }

    @Test
    @Order(1)
    void clickShiftClickCtrlClickAndEscapeSelectAndTheSelectedPointsTurnRed() {
        d.clickAt(at(1, 1));
        d.clickAt(at(2, 1), KeyEvent.VK_SHIFT);
        d.clickAt(at(2, 2), KeyEvent.VK_SHIFT);
        BufferedImage three = shot();
        assertEquals("3 points selected", d.status("selection"));
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {2, 2}}) {
            assertTrue(redAt(three, d.inPanel(at(ij[0], ij[1]))), "selected point " + Arrays.toString(ij) + " is red: "
                    + GuiDriver.save(three, "three-selected"));
        }
        assertTrue(!redAt(three, d.inPanel(at(1, 2))), "an unselected point is not");
        d.clickAt(at(2, 1), KeyEvent.VK_CONTROL);
        BufferedImage two = shot();
        assertEquals("2 points selected", d.status("selection"));
        assertTrue(!redAt(two, d.inPanel(at(2, 1))), "Ctrl-click took it out");
        d.focusPicture();
        d.key(KeyEvent.VK_ESCAPE);
        BufferedImage none = shot();
        assertEquals("nothing selected", d.status("selection"));
        assertTrue(!redAt(none, d.inPanel(at(1, 1))) && !redAt(none, d.inPanel(at(2, 2))), "Escape cleared it");
        d.clickAt(at(1, 2));
        d.menu("Edit", "clearSelection");
        assertEquals("nothing selected", d.status("selection"), "Edit → Clear Selection");
        d.menu("Edit", "selectAll");
        d.settle();
        assertEquals("16 points selected", d.status("selection"), "Edit → Select All");
        assertTrue(redAt(shot(), d.inPanel(at(3, 3))));
    }

    @Test
    @Order(2)
    void aShiftDragOnEmptySpaceSelectsThePointsInTheBand() {
        int x0 = Integer.MAX_VALUE, y0 = Integer.MAX_VALUE, x1 = Integer.MIN_VALUE, y1 = Integer.MIN_VALUE;
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {1, 2}, {2, 2}}) {
            Point p = at(ij[0], ij[1]);
            x0 = Math.min(x0, p.x - 6);
            y0 = Math.min(y0, p.y - 6);
            x1 = Math.max(x1, p.x + 6);
            y1 = Math.max(y1, p.y + 6);
        }
        d.dragHolding(new Point(x0, y0), new Point(x1, y1), 8, KeyEvent.VK_SHIFT);
        BufferedImage img = shot();
        assertEquals("4 points selected", d.status("selection"));
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {1, 2}, {2, 2}}) {
            assertTrue(redAt(img, d.inPanel(at(ij[0], ij[1]))), "in the band: " + Arrays.toString(ij) + " "
                    + GuiDriver.save(img, "band"));
        }
        assertTrue(!redAt(img, d.inPanel(at(0, 0))), "outside the band");
    }

    @Test
    @Order(3)
    void draggingWithXHeldMovesAlongTheWorldXAxisOnly() {
        BezierPatch before = GuiDriver.onEdt(() -> d.app.document().scene()).patches().get(0);
        BufferedImage img0 = shot();
        Point a = at(1, 2);
        d.focusPicture();
        d.dragHolding(a, new Point(a.x + 70, a.y - 50), 10, KeyEvent.VK_X);
        BufferedImage img1 = shot();
        BezierPatch after = GuiDriver.onEdt(() -> d.app.document().scene()).patches().get(0);
        assertTrue(Math.abs(after.get(1, 2, 0) - before.get(1, 2, 0)) > 0.1, "moved along x");
        assertEquals(before.get(1, 2, 1), after.get(1, 2, 1), 1e-9, "y held");
        assertEquals(before.get(1, 2, 2), after.get(1, 2, 2), 1e-9, "z held");
        assertTrue(GuiDriver.differing(img0, img1, 24) > 200, "the surface moved on screen");
    }

    @Test
    @Order(4)
    void arrowKeysAndTheNudgeMenuMoveTheSelectionOnePixelOrTen() {
        d.clickAt(at(2, 1));
        d.settle();
        Point p0 = d.inPanel(at(2, 1));
        d.focusPicture();
        d.key(KeyEvent.VK_RIGHT, KeyEvent.VK_SHIFT);
        d.settle();
        Point p1 = d.inPanel(at(2, 1));
        assertEquals(p0.x + 10, p1.x, 1, "Shift+Right: ten pixels right");
        assertEquals(p0.y, p1.y, 1);
        d.key(KeyEvent.VK_LEFT);
        d.settle();
        assertEquals(p0.x + 9, d.inPanel(at(2, 1)).x, 1, "Left: one pixel back");
        d.menuPath("Edit", "nudge", "nudgeUp10");
        BufferedImage img = shot();
        Point p2 = d.inPanel(at(2, 1));
        assertEquals(p1.y - 10, p2.y, 1, "Edit → Nudge Selection → Nudge Up ×10");
        assertTrue(redAt(img, p2), "the red handle is drawn where the point went: " + GuiDriver.save(img, "nudged"));
        assertTrue(!redAt(img, p0), "and no longer where it was");
        d.menu("Edit", "undo");
        d.settle();
        assertEquals(p1.x - 1, d.inPanel(at(2, 1)).x, 1, "each nudge was one edit");
    }

    @Test
    @Order(5)
    void typingACoordinateInTheInspectorMovesThePointAsOneEdit() {
        d.clickAt(at(1, 2));
        BufferedImage img0 = shot();
        javax.swing.JLabel title = d.find("inspector.title");
        assertEquals("Patch 0, point (1, 2)", GuiDriver.onEdt(() -> title.getText()));
        JTextField z = d.find("inspector.z");
        assertEquals("0", GuiDriver.onEdt(() -> z.getText()));
        d.typeInto(z, "1.25");
        BufferedImage img1 = shot();
        assertEquals(1.25, GuiDriver.onEdt(() -> d.app.document().scene()).patches().get(0).get(1, 2, 2), 1e-12);
        assertTrue(GuiDriver.differing(img0, img1, 24) > 300, "the surface rose: " + GuiDriver.save(img1, "inspector-z"));
        assertEquals("1.25", GuiDriver.onEdt(() -> z.getText()));
        Scene typed = GuiDriver.onEdt(() -> d.app.document().scene());
        d.key(KeyEvent.VK_UP);
        d.settle();
        assertTrue(typed == GuiDriver.onEdt(() -> d.app.document().scene()), "Up in the field does not nudge the point");
        d.typeInto(z, "abc");
        d.settle();
        WrappingText message = d.find("inspector.message");
        assertEquals("z: expected a number, found \"abc\"", GuiDriver.onEdt(() -> message.getText()));
        d.focusPicture();
        d.ctrl(KeyEvent.VK_Z);
        BufferedImage back = shot();
        assertTrue(GuiDriver.differing(img0, back, 24) < 50, "Ctrl+Z: one edit, undone");
        d.menu("View", "inspector");
        d.settle();
        assertTrue(!GuiDriver.onEdt(() -> d.frame.inspector().isShowing()), "View → Inspector hides it");
        d.menu("View", "inspector");
        d.settle();
        assertTrue(GuiDriver.onEdt(() -> d.frame.inspector().isShowing()));
    }

    @Test
    @Order(6)
    void keepTangentContinuityTurnsTheMirroredPointAcrossTheBorder() throws Exception {
        d.menu("Models", "model:teapot");
        d.settle();
        d.tool("smoothJoins");
        assertTrue(GuiDriver.onEdt(() -> d.app.settings().current().on(Toggle.SMOOTH_JOINS)));
        Scene teapot = GuiDriver.onEdt(() -> d.app.document().scene());
        int[] row = Borders.visibleRow(d, teapot);
        BufferedImage img0 = shot();
        Point a = d.screenOfPoint(row[0], row[1], row[2]);
        d.drag(a, new Point(a.x - 25, a.y - 35), 8);
        BufferedImage img1 = shot();
        assertTrue(GuiDriver.differing(img0, img1, 24) > 100, "the surface changed");
        Path file = dir.resolve("smooth.bpt");
        d.menu("File", "saveAs");
        d.chooseFile(file);
        d.settle();
        Scene saved = org.beziertracer.model.io.Models.load(file.toString());
        double sine = Borders.bend(saved, row);
        assertTrue(sine < 1e-9, "the cross-border row stays straight in the saved file: sine " + sine);
        assertTrue(Borders.moved(teapot, saved, row), "the mirrored point followed");
        d.tool("smoothJoins");
    }

    /** A border point of the teapot's body drawn as a handle of its own, shared with another patch: {patch, i, j}. */
    private static int[] pickableSharedBorderPoint() {
        return GuiDriver.onEdt(() -> {
            var g = d.app.overlay().geometry();
            Scene s = d.app.document().scene();
            for (int k = 0; k < g.handleCount(); k++) {
                var r = g.handle(k).ref();
                boolean border = r.i() == 0 || r.i() == 3 || r.j() == 0 || r.j() == 3;
                if (border && r.patch() < 12 && g.handleX(k) > 40 && g.handleY(k) > 40
                        && g.handleX(k) < d.app.view().width() - 60 && g.handleY(k) < d.app.view().height() - 60
                        && g.pick(g.handleX(k), g.handleY(k), 1).ref().equals(r) && copies(s, r.patch(), r.i(), r.j()) >= 2) {
                    return new int[] {r.patch(), r.i(), r.j()};
                }
            }
            throw new AssertionError("no shared border point drawn");
        });
    }

    /** Points of {@code s} within 1e-9 of the scene size of point (i, j) of patch p, itself included. */
    private static int copies(Scene s, int p, int i, int j) {
        return copiesAt(s, s, p, 4 * j + i);
    }

    /** Points of {@code s} within 1e-9 of its size of point k of patch p of {@code at}. */
    private static int copiesAt(Scene s, Scene at, int p, int k) {
        double tol = 1e-9 * s.controlBounds().diagonal();
        int n = 0;
        for (int q = 0; q < s.patchCount(); q++) {
            for (int l = 0; l < 16; l++) {
                n += dist(s, q, l, at, p, k) <= tol ? 1 : 0;
            }
        }
        return n;
    }

    private static double dist(Scene s, int p, int k, Scene t, int q, int l) {
        double d2 = 0;
        for (int c = 0; c < 3; c++) {
            double v = s.patches().get(p).get(k % 4, k / 4, c) - t.patches().get(q).get(l % 4, l / 4, c);
            d2 += v * v;
        }
        return Math.sqrt(d2);
    }

    /** The teapot opened, one of its shared border points {r = patch, i, j} with its copies, the picture and where the point is. */
    private record Grab(Scene original, int[] r, int copies, BufferedImage before, Point at) {}

    private static Grab teapotBorderPoint() {
        d.menu("Models", "model:teapot");
        d.settle();
        Scene original = GuiDriver.onEdt(() -> d.app.document().scene());
        int[] r = pickableSharedBorderPoint();
        return new Grab(original, r, copies(original, r[0], r[1], r[2]), shot(), d.screenOfPoint(r[0], r[1], r[2]));
    }

    @Test
    @Order(7)
    void aDraggedTeapotBorderPointMovesEveryCopyAndTheSavedFileKeepsEveryCoincidence() throws Exception {
        Grab g = teapotBorderPoint();
        Scene original = g.original();
        int[] r = g.r();
        int copies = g.copies();
        BufferedImage img0 = g.before();
        Point a = g.at();
        d.drag(a, new Point(a.x + 30, a.y - 45), 10);
        BufferedImage img1 = shot();
        assertTrue(GuiDriver.differing(img0, img1, 24) > 100, "the surface moved");
        assertEquals("1 point selected", d.status("selection"), "one handle");
        Path file = dir.resolve("welded.bpt");
        d.menu("File", "saveAs");
        d.chooseFile(file);
        d.settle();
        Scene saved = org.beziertracer.model.io.Models.load(file.toString());
        assertEquals(copies, copies(saved, r[0], r[1], r[2]), "every copy moved with it");
        double tol = 1e-9 * original.controlBounds().diagonal();
        int pairs = 0;
        for (int p = 0; p < original.patchCount(); p++) {
            for (int k = 0; k < 16; k++) {
                for (int q = p; q < original.patchCount(); q++) {
                    for (int l = q == p ? k + 1 : 0; l < 16; l++) {
                        if (dist(original, p, k, original, q, l) <= tol) {
                            pairs++;
                            assertTrue(dist(saved, p, k, saved, q, l) <= tol, "P" + k + " of patch " + p + " and P" + l
                                    + " of patch " + q + " coincided, and still must");
                        }
                    }
                }
            }
        }
        assertTrue(pairs > 300, "pairs checked: " + pairs);
        org.beziertracer.intersect.BorderRays.assertNoneFallThrough(saved, org.beziertracer.intersect.Method.CLIPPING);
    }

    @Test
    @Order(8)
    void altDragTearsOneCopyAway() {
        Grab g = teapotBorderPoint();
        int[] r = g.r();
        d.dragHolding(g.at(), new Point(g.at().x + 40, g.at().y + 40), 10, KeyEvent.VK_ALT);
        BufferedImage img1 = shot();
        Scene now = GuiDriver.onEdt(() -> d.app.document().scene());
        assertEquals(1, copies(now, r[0], r[1], r[2]), "the grabbed copy alone");
        assertEquals(g.copies() - 1, copiesAt(now, g.original(), r[0], 4 * r[2] + r[1]), "the other copies stayed where they were");
        assertTrue(GuiDriver.differing(g.before(), img1, 24) > 50, "the torn patch shows");
    }

    @Test
    @Order(9)
    void keepCurvatureContinuityKeepsACutBicubicC2AcrossWhileASecondRowIsDragged() throws Exception {
        Path file = dir.resolve("cut.bpt");
        org.beziertracer.model.io.BptWriter.write(file, org.beziertracer.app.C2Models.cut(
                org.beziertracer.app.C2Models.randomPatch(3, 3, 7), new double[] {0.5}, new double[] {0.5}).patches());
        d.menu("File", "open");
        d.chooseFile(file);
        d.settle();
        Scene before = GuiDriver.onEdt(() -> d.app.document().scene());
        assertEquals(4, before.patchCount());
        d.menu("Edit", "curvatureJoins");
        d.settle();
        assertTrue(GuiDriver.onEdt(() -> d.app.settings().current().on(Toggle.CURVATURE_JOINS)), "Edit → Keep Curvature Continuity");
        // Point (1, 1) of patch 0: the second row inward of both its borders (u = 3 and v = 3)
        BufferedImage img0 = shot();
        Point a2 = d.screenOfPoint(0, 1, 1);
        d.drag(a2, new Point(a2.x + 20, a2.y - 30), 8);
        BufferedImage img1 = shot();
        assertTrue(GuiDriver.differing(img0, img1, 24) > 100, "the surface changed: " + GuiDriver.save(img1, "curvature-drag"));
        Path saved = dir.resolve("cut-dragged.bpt");
        d.menu("File", "saveAs");
        d.chooseFile(saved);
        d.settle();
        Scene after = org.beziertracer.model.io.Models.load(saved.toString());
        assertTrue(after.patches().get(0).get(1, 1, 0) != before.patches().get(0).get(1, 1, 0), "the grabbed point moved");
        assertTrue(after.patches().get(1).get(2, 1, 0) != before.patches().get(1).get(2, 1, 0),
                "its mirror two rows across the u border followed");
        assertTrue(after.patches().get(2).get(1, 2, 0) != before.patches().get(2).get(1, 2, 0),
                "its mirror two rows across the v border followed");
        double residual = org.beziertracer.app.CurvatureJoins.worstResidual(after);
        assertTrue(residual <= 1e-9, "every cross-border row stays C2 in the saved file: residual " + residual);

        // A model cut into two biquadratic halves: its one border is too short, and the status bar says so
        Path quadratic = dir.resolve("quadratic.bpt");
        org.beziertracer.model.io.BptWriter.write(quadratic, org.beziertracer.app.C2Models.cut(
                org.beziertracer.app.C2Models.randomPatch(2, 2, 4), new double[] {0.5}, new double[] {}).patches());
        d.menu("File", "open");
        d.chooseFile(quadratic);
        d.waitFor("the short-border message", () -> "curvature continuity not kept across 1 border: degree below 3 across"
                .equals(d.app.status().message()));
        d.menu("Edit", "curvatureJoins");
        d.settle();
    }
}
