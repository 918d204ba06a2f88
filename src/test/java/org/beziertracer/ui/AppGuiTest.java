package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Frame;
import java.awt.GraphicsEnvironment;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.swing.JDialog;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;

import org.beziertracer.UserMessages;
import org.beziertracer.model.Scene;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

/**
 * GUI tests: the real app in this JVM, driven with {@link java.awt.Robot} on a real (or Xvfb)
 * display: {@code xvfb-run -a mvn -B -q test -Dtest='*GuiTest'}. Skipped, with a message, only
 * when the JVM is headless. Every test starts from the default patch, fully rendered.
 */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class AppGuiTest {

    private static GuiDriver d;

    @TempDir
    Path dir;

    /** Shown for every skipped GUI test. */
    static final String NO_DISPLAY = "GUI test skipped: no display (java.awt is headless); "
            + "run under xvfb-run to include it";

    @BeforeAll
    static void launch() throws Exception {
        if (!GraphicsEnvironment.isHeadless()) {
            d = GuiDriver.launch();
        }
    }

    @AfterAll
    static void close() {
        if (d != null) {
            d.close();
        }
    }

    @BeforeEach
    void defaultPatch() {
        Assumptions.assumeFalse(GraphicsEnvironment.isHeadless(), NO_DISPLAY);
        GuiDriver.onEdt(() -> {
            d.c.history().markSaved();
            d.c.openBuiltIn("patch");
        });
        d.settle();
    }

    /** Centre of the surface on screen, relative to the panel (screen pixels). */
    private Rectangle centreBox() {
        ProjectedScene ps = GuiDriver.onEdt(() -> d.c.projected());
        double x = 0, y = 0;
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {1, 2}, {2, 2}}) {
            x += ps.x(0, ij[0], ij[1]) / 4;
            y += ps.y(0, ij[0], ij[1]) / 4;
        }
        double s = d.frame.renderPanel().deviceScale();
        return new Rectangle((int) (x / s) - 20, (int) (y / s) + 10, 16, 12);
    }

    @Test
    @Order(1)
    void theWindowOpensOnTheDefaultPatchWithARenderedSurface() {
        Frame main = null;
        for (Frame f : Frame.getFrames()) {
            if ("beziertracer.main".equals(f.getName()) && f.isShowing()) {
                main = f;
            }
        }
        assertNotNull(main, "main window found among Frame.getFrames()");
        Scene s = GuiDriver.onEdt(() -> d.c.scene());
        assertEquals(16, s.patches().get(0).pointCount());
        BufferedImage img = d.capturePanel();
        double[] surface = GuiDriver.mean(img, centreBox());
        double[] corner = GuiDriver.mean(img, new Rectangle(2, 2, 10, 10));
        assertTrue(surface[0] > corner[0] + 40, "the surface (warm) is lit against the background: "
                + java.util.Arrays.toString(surface) + " vs " + java.util.Arrays.toString(corner));
        String pass = GuiDriver.onEdt(() -> d.frame.statusBar().text("pass"));
        assertTrue(pass.startsWith("pass "), pass);
    }

    @Test
    @Order(2)
    void draggingAControlPointChangesThePictureWhereTheSurfaceMovedAndUndoRestoresIt() {
        Scene before = GuiDriver.onEdt(() -> d.c.scene());
        ProjectedScene ps = GuiDriver.onEdt(() -> d.c.projected());
        Point a = d.screenOf(ps.x(0, 1, 2), ps.y(0, 1, 2));
        Point b = new Point(a.x, a.y - 120);
        BufferedImage img0 = d.capturePanel();
        d.drag(a, b, 12);
        d.settle();
        BufferedImage img1 = d.capturePanel();
        Point origin = GuiDriver.onEdt(() -> d.frame.renderPanel().getLocationOnScreen());
        Rectangle moved = new Rectangle(a.x - origin.x - 60, b.y - origin.y, 120, 120);
        int changed = GuiDriver.differing(img0, img1, moved, 24);
        assertTrue(changed > 600, "pixels changed where the surface moved: " + changed);
        assertEquals(0, GuiDriver.differing(img0, img1, new Rectangle(0, img0.getHeight() - 30, 40, 30), 8),
                "an empty corner stays empty");
        Scene after = GuiDriver.onEdt(() -> d.c.scene());
        assertNotEquals(before.patches(), after.patches());
        assertEquals(before.patches().get(0).get(0, 0, 2), after.patches().get(0).get(0, 0, 2), "other points stay");

        d.frame.renderPanel().requestFocus();
        d.ctrl(KeyEvent.VK_Z);
        d.settle();
        Scene undone = GuiDriver.onEdt(() -> d.c.scene());
        assertArrayEquals(before.patches().get(0).copyNet(), undone.patches().get(0).copyNet(),
                "Ctrl+Z restores the exact previous points");
        assertFalse(GuiDriver.onEdt(() -> d.c.history().canUndo()), "the drag was one edit");
        assertTrue(GuiDriver.differing(img0, d.capturePanel(), moved, 24) < 50, "the picture is back");
        d.key(KeyEvent.VK_Z, KeyEvent.VK_CONTROL, KeyEvent.VK_SHIFT);
        assertEquals(after.patches(), GuiDriver.onEdt(() -> d.c.scene()).patches(), "Ctrl+Shift+Z redoes");
    }

    @Test
    @Order(3)
    void draggingEmptySpaceRotatesAndTheWheelZooms() {
        OrbitView v0 = GuiDriver.onEdt(() -> d.c.view());
        Point origin = GuiDriver.onEdt(() -> d.frame.renderPanel().getLocationOnScreen());
        d.drag(new Point(origin.x + 20, origin.y + 20), new Point(origin.x + 90, origin.y + 50), 6);
        OrbitView v1 = GuiDriver.onEdt(() -> d.c.view());
        assertNotEquals(v0.right(), v1.right());
        d.robot.mouseWheel(3);
        d.robot.waitForIdle();
        assertTrue(GuiDriver.onEdt(() -> d.c.view()).zoom() > v1.zoom(), "wheel down moves away");
        d.click(d.find("tool.resetView"));
        assertEquals(v0, GuiDriver.onEdt(() -> d.c.view()), "Reset View restores rotation and zoom");
    }

    @Test
    @Order(4)
    void eachToolboxToggleHasItsEffect() {
        ToolSettings t = d.c.tools();
        Rectangle centre = centreBox();
        BufferedImage phong = d.capturePanel();

        d.click(d.find("tool.normals"));
        d.settle();
        assertTrue(t.normals);
        double[] n = GuiDriver.mean(d.capturePanel(), centre);
        assertTrue(n[2] > n[0] + 60, "flat patch normal (0,0,1) is blue in the normals view: " + java.util.Arrays.toString(n));
        d.click(d.find("tool.normals"));

        d.click(d.find("tool.phong"));
        d.settle();
        assertFalse(t.phong);
        assertTrue(GuiDriver.differing(phong, d.capturePanel(), centre, 6) > 20, "flat shading differs from Phong");
        d.click(d.find("tool.phong"));

        d.click(d.find("tool.texture"));
        d.settle();
        assertTrue(t.texture);
        BufferedImage checker = d.capturePanel();
        Rectangle big = new Rectangle(centre.x - 60, centre.y - 40, 120, 80);
        assertTrue(GuiDriver.differing(phong, checker, big, 30) > 500, "the checker shows");
        d.click(d.find("tool.texture"));

        d.click(d.find("tool.rayTrace"));
        d.settle();
        assertFalse(t.rayTrace);
        double[] wire = GuiDriver.mean(d.capturePanel(), centre);
        assertTrue(wire[0] < 90, "wireframe view: no ray-traced surface, background shows: " + java.util.Arrays.toString(wire));
        d.click(d.find("tool.rayTrace"));
        d.settle();
        assertTrue(t.rayTrace);

        ProjectedScene ps = GuiDriver.onEdt(() -> d.c.projected());
        Point corner = d.screenOf(ps.x(0, 3, 3), ps.y(0, 3, 3));
        Point origin = GuiDriver.onEdt(() -> d.frame.renderPanel().getLocationOnScreen());
        Rectangle dot = new Rectangle(corner.x - origin.x - 1, corner.y - origin.y - 1, 3, 3);
        assertTrue(GuiDriver.mean(d.capturePanel(), dot)[1] > 200, "control point drawn white");
        d.click(d.find("tool.points"));
        d.settle();
        assertFalse(t.controlPoints);
        assertTrue(GuiDriver.mean(d.capturePanel(), dot)[1] < 200, "control point hidden");
        d.click(d.find("tool.points"));

        BufferedImage withPolygon = d.capturePanel();
        d.click(d.find("tool.polygon"));
        d.settle();
        assertFalse(t.controlPolygon);
        assertTrue(GuiDriver.differing(withPolygon, d.capturePanel(), big, 30) > 5, "polygon lines gone");
        d.click(d.find("tool.polygon"));

        d.click(d.find("tool.wireframe"));
        d.settle();
        assertTrue(t.wireframeOverlay);
        assertTrue(GuiDriver.differing(withPolygon, d.capturePanel(), big, 30) > 20, "iso-curves drawn over");
        d.click(d.find("tool.wireframe"));

        for (String id : new String[] {"shadows", "reflections", "superSampling", "bvh"}) {
            boolean was = GuiDriver.onEdt(() -> (Boolean) d.frame.actions().get(id).getValue(javax.swing.Action.SELECTED_KEY));
            d.click(d.find("tool." + id));
            boolean now = GuiDriver.onEdt(() -> (Boolean) d.frame.actions().get(id).getValue(javax.swing.Action.SELECTED_KEY));
            assertNotEquals(was, now, id + " toggled");
            d.settle();
        }
        assertFalse(t.shadows);
        assertFalse(t.reflections);
        assertTrue(t.superSampling);
        assertFalse(t.bvh);
        assertEquals(4, d.c.status().spp(), "super-sampling renders 4 spp");
        assertTrue(GuiDriver.onEdt(() -> d.frame.statusBar().text("bvh")).startsWith("BVH off"));
        for (String id : new String[] {"shadows", "reflections", "superSampling"}) {
            d.click(d.find("tool." + id));
        }
        d.settle();
        d.click(d.find("tool.bvh"));
        d.settle();
        String bvh = GuiDriver.onEdt(() -> d.frame.statusBar().text("bvh"));
        assertTrue(bvh.matches("BVH on ×\\d+\\.\\d"), "measured speed-up after off → on: " + bvh);

        // Tessellated mode: on a curved (randomized) patch a coarse K = 4 mesh differs visibly from the
        // exact surface; the status names it
        GuiDriver.onEdt(() -> d.c.randomizeControlPoints(1234));
        d.settle();
        BufferedImage exact = d.capturePanel();
        assertEquals("clipping", GuiDriver.onEdt(() -> d.frame.statusBar().text("method")));
        javax.swing.JComboBox<?> kBox = d.find("tool.tessellation");
        assertFalse(GuiDriver.onEdt(kBox::isEnabled),
                "K is only offered in tessellated mode");
        d.click(d.find("tool.tessellated"));
        d.settle();
        assertTrue(t.tessellated);
        assertEquals(ToolSettings.DEFAULT_TESSELLATION, d.c.status().tessellate(), "the render used the mesh");
        assertEquals("tessellated " + ToolSettings.DEFAULT_TESSELLATION,
                GuiDriver.onEdt(() -> d.frame.statusBar().text("method")));
        assertTrue(GuiDriver.onEdt(kBox::isEnabled));
        GuiDriver.onEdt(() -> d.c.setTessellation(4));
        d.settle();
        assertEquals(4, d.c.status().tessellate());
        assertEquals("tessellated 4", GuiDriver.onEdt(() -> d.frame.statusBar().text("method")));
        Rectangle all = new Rectangle(0, 0, exact.getWidth(), exact.getHeight());
        int facets = GuiDriver.differing(exact, d.capturePanel(), all, 6);
        assertTrue(facets > 20, "K = 4 facets differ from the exact surface: " + facets + " pixels");
        d.key(KeyEvent.VK_K, KeyEvent.VK_CONTROL);
        d.settle();
        assertFalse(t.tessellated, "Ctrl+K toggles the tessellated mode");
        assertEquals(0, d.c.status().tessellate());
        assertEquals("clipping", GuiDriver.onEdt(() -> d.frame.statusBar().text("method")));
        GuiDriver.onEdt(() -> d.c.setting(() -> t.tessellation = ToolSettings.DEFAULT_TESSELLATION));
        d.settle();
    }

    @Test
    @Order(5)
    void surfaceButtonsSlidersAndCombos() {
        ToolSettings t = d.c.tools();
        d.click(d.find("tool.randomize"));
        d.settle();
        String msg = GuiDriver.onEdt(() -> d.frame.statusBar().text("message"));
        assertTrue(msg.matches("random seed \\d+"), msg);
        assertTrue(GuiDriver.onEdt(() -> d.c.scene()).controlBounds().maxZ() > 0, "points left the plane");

        d.click(d.find("tool.gridU"));
        d.key(KeyEvent.VK_UP);
        assertEquals(5, t.gridPointsU, "spinner up adds a point along u");
        d.click(d.find("tool.gridV"));
        d.key(KeyEvent.VK_DOWN);
        assertEquals(3, t.gridPointsV);
        d.click(d.find("tool.resetPoints"));
        d.settle();
        Scene s = GuiDriver.onEdt(() -> d.c.scene());
        assertEquals(4, s.patches().get(0).degreeU());
        assertEquals(2, s.patches().get(0).degreeV());
        assertEquals(0, s.controlBounds().maxZ(), "reset is flat");

        for (String id : new String[] {"subdivision", "perspective", "interactivity"}) {
            javax.swing.JSlider slider = d.find("tool." + id);
            d.click(slider);
            d.key(KeyEvent.VK_END);
            assertEquals(slider.getMaximum(), (int) GuiDriver.onEdt(slider::getValue), id);
            d.key(KeyEvent.VK_HOME);
            assertEquals(slider.getMinimum(), (int) GuiDriver.onEdt(slider::getValue), id);
        }
        assertEquals(1, t.wireframeSubdivision);
        assertEquals(0, t.perspective);
        assertEquals(1, t.interactivity);
        d.settle();
        assertEquals(0, d.c.view().fovDegrees(), "perspective 0 is orthographic");
        GuiDriver.onEdt(() -> d.c.setting(() -> {
            t.perspective = 36;
            t.wireframeSubdivision = 12;
        }));

        d.click(d.find("tool.method"));
        d.key(KeyEvent.VK_DOWN);
        d.key(KeyEvent.VK_ENTER);
        d.settle();
        assertEquals(org.beziertracer.intersect.Method.NEWTON, t.method);
        assertEquals("newton", d.c.status().method());
        d.key(KeyEvent.VK_M, KeyEvent.VK_CONTROL);
        d.key(KeyEvent.VK_M, KeyEvent.VK_CONTROL);
        assertEquals(org.beziertracer.intersect.Method.CLIPPING, t.method, "Ctrl+M cycles the method");

        d.click(d.find("tool.light"));
        d.key(KeyEvent.VK_DOWN);
        d.key(KeyEvent.VK_ENTER);
        assertEquals(LightPlacement.AT_EYE, t.light);
        GuiDriver.onEdt(() -> d.c.setting(() -> t.light = LightPlacement.SCENE));

        GuiDriver.onEdt(() -> d.c.setting(() -> t.superSampling = true));
        d.click(d.find("tool.spp"));
        d.key(KeyEvent.VK_DOWN);
        d.key(KeyEvent.VK_ENTER);
        assertEquals(9, t.samplesPerPixel);
        GuiDriver.onEdt(() -> d.c.setting(() -> {
            t.superSampling = false;
            t.samplesPerPixel = 4;
        }));

        boolean dark = Theme.isDark();
        d.click(d.find("tool.dark"));
        assertNotEquals(dark, Theme.isDark());
        d.click(d.find("tool.dark"));
        assertEquals(dark, Theme.isDark());
        d.settle();
    }

    @Test
    @Order(6)
    void functionKeysToggleTheViews() {
        d.frame.renderPanel().requestFocus();
        d.key(KeyEvent.VK_F7);
        assertTrue(d.c.tools().normals, "F7: surface normals");
        d.key(KeyEvent.VK_F7);
        d.key(KeyEvent.VK_F2);
        assertFalse(d.c.tools().rayTrace, "F2: wireframe");
        d.key(KeyEvent.VK_F2);
        assertTrue(d.c.tools().rayTrace);
        d.settle();
    }

    @Test
    @Order(7)
    void aMalformedFileShowsAnErrorDialogAndKeepsTheOldModel() throws Exception {
        Path bad = dir.resolve("broken.bpt");
        Files.writeString(bad, "1\n3 3\n0 0 0\n1 1 nope\n");
        Scene before = GuiDriver.onEdt(() -> d.c.scene());
        BufferedImage img0 = d.capturePanel();
        SwingUtilities.invokeLater(() -> d.c.open(bad));
        JDialog dialog = waitForOptionDialog();
        assertNotNull(dialog, "an error dialog opened");
        JDialog shown = dialog;
        String message = UserMessages.check(GuiDriver.onEdt(
                () -> String.valueOf(((JOptionPane) shown.getContentPane().getComponent(0)).getMessage())));
        assertTrue(message.startsWith(bad.toString() + ":"), message);
        GuiDriver.onEdt(shown::dispose);
        d.settle();
        assertSame(before, GuiDriver.onEdt(() -> d.c.scene()), "the old model is kept");
        assertTrue(GuiDriver.differing(img0, d.capturePanel(), new Rectangle(0, 0, img0.getWidth(), img0.getHeight()), 8) < 50,
                "the old picture is still shown");
    }

    @Test
    @Order(8)
    void everyToolboxControlHasATooltipNamingItsShortcut() {
        java.util.List<String> missing = new java.util.ArrayList<>();
        int[] count = {0};
        GuiDriver.onEdt(() -> ToolboxPanel.forEachControl(d.frame.toolbox(), comp -> {
            count[0]++;
            String tip = comp.getToolTipText();
            if (tip == null || !tip.matches(".*\\((Ctrl|Shift|F\\d|Home).*\\)")) {
                missing.add(comp.getName() + ": " + tip);
            }
        }));
        assertTrue(count[0] >= 22, "toolbox controls found: " + count[0]);
        assertEquals(java.util.List.of(), missing);
    }

    @Test
    @Order(9)
    void closingWithUnsavedEditsAsksAndCancelKeepsTheWindow() {
        GuiDriver.onEdt(() -> d.c.randomizeControlPoints(5));
        assertTrue(GuiDriver.onEdt(() -> d.c.history().isDirty()));
        SwingUtilities.invokeLater(() -> d.frame.dispatchEvent(
                new java.awt.event.WindowEvent(d.frame, java.awt.event.WindowEvent.WINDOW_CLOSING)));
        JDialog dialog = waitForOptionDialog();
        String message = GuiDriver.onEdt(() -> String.valueOf(((JOptionPane) dialog.getContentPane().getComponent(0)).getMessage()));
        assertTrue(message.contains("unsaved edits"), message);
        javax.swing.AbstractButton cancel = GuiDriver.onEdt(() -> findButton(dialog, "Cancel"));
        assertNotNull(cancel, "a Cancel button");
        d.click(cancel);
        d.settle();
        assertTrue(GuiDriver.onEdt(() -> d.frame.isDisplayable() && d.frame.isShowing()), "the window stays open");
        assertTrue(GuiDriver.onEdt(() -> d.c.history().isDirty()), "the edits stay");
    }

    private static JDialog waitForOptionDialog() {
        for (int k = 0; k < 200; k++) {
            d.robot.delay(25);
            JDialog found = GuiDriver.onEdt(() -> {
                for (Window w : Window.getWindows()) {
                    if (w instanceof JDialog jd && jd.isShowing() && jd.getContentPane().getComponent(0) instanceof JOptionPane) {
                        return jd;
                    }
                }
                return null;
            });
            if (found != null) {
                return found;
            }
        }
        throw new AssertionError("no dialog opened");
    }

    private static javax.swing.AbstractButton findButton(java.awt.Container root, String text) {
        for (java.awt.Component comp : root.getComponents()) {
            if (comp instanceof javax.swing.AbstractButton b && text.equals(b.getText())) {
                return b;
            }
            if (comp instanceof java.awt.Container ct) {
                javax.swing.AbstractButton hit = findButton(ct, text);
                if (hit != null) {
                    return hit;
                }
            }
        }
        return null;
    }
}
