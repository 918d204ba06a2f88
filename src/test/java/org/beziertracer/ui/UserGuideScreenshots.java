package org.beziertracer.ui;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;
import javax.swing.JDialog;
import javax.swing.JSpinner;
import javax.swing.SwingUtilities;

import org.beziertracer.app.SettingsModel;
import org.beziertracer.app.Toggle;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * Regenerates the user guide's screenshots (not a test; skipped unless asked):
 * {@code xvfb-run -a -s '-screen 0 1280x800x24' ./mvnw -B -q test -Dtest=UserGuideScreenshots -Dscreenshots=docs/images}.
 */
@Tag("gui")
class UserGuideScreenshots {

    @Test
    void writeScreenshots() throws Exception {
        String out = System.getProperty("screenshots");
        Assumptions.assumeTrue(out != null && !java.awt.GraphicsEnvironment.isHeadless(),
                "screenshots are written only with -Dscreenshots=DIR under a display");
        Path dir = Path.of(out);
        Files.createDirectories(dir);
        GuiDriver d = GuiDriver.launch();
        try {
            GuiDriver.onEdt(() -> d.frame.setSize(1100, 720));
            d.settle();
            modelShots(d, dir);
            editingShots(d, dir);
            lightShot(d, dir);
            differenceShot(d, dir);
            exportDialogShot(d, dir);
        } finally {
            d.close();
        }
    }

    /** The default patch, the wireframe and normals views, the teapot and the teapot room. */
    private static void modelShots(GuiDriver d, Path dir) throws Exception {
        SettingsModel t = d.app.settings();
        // The default patch, bent, a control point under the cursor
        GuiDriver.onEdt(() -> d.app.edits().randomize(7));
        d.settle();
        Point p = d.screenOfPoint(0, 2, 1);
        d.robot.mouseMove(p.x, p.y);
        shot(d, dir, "patch.png");
        GuiDriver.onEdt(() -> t.set(Toggle.RAY_TRACE, false));
        shot(d, dir, "wireframe.png");
        GuiDriver.onEdt(() -> {
            t.set(Toggle.RAY_TRACE, true);
            t.set(Toggle.NORMALS, true);
            t.set(Toggle.CONTROL_POLYGON, false);
        });
        shot(d, dir, "normals.png");
        open(d, "teapot");
        GuiDriver.onEdt(() -> {
            t.set(Toggle.NORMALS, false);
            t.set(Toggle.CONTROL_POINTS, false);
            t.set(Toggle.CONTROL_POLYGON, false);
            t.set(Toggle.SUPER_SAMPLING, true);
        });
        shot(d, dir, "teapot.png");
        open(d, "teapot-room");
        GuiDriver.onEdt(() -> t.set(Toggle.SUPER_SAMPLING, true));
        shot(d, dir, "teapot-room.png");
        GuiDriver.onEdt(() -> t.replace(org.beziertracer.app.Settings.defaults()));
    }

    /** A rubber band being drawn on the patch; then a welded teapot point dragged with tangent continuity on. */
    private static void editingShots(GuiDriver d, Path dir) throws Exception {
        open(d, "patch");
        GuiDriver.onEdt(() -> d.app.edits().randomize(11));
        d.settle();
        d.clickAt(d.screenOfPoint(0, 0, 3));
        Point from = new Point(Integer.MAX_VALUE, Integer.MAX_VALUE), to = new Point(Integer.MIN_VALUE, Integer.MIN_VALUE);
        for (int[] ij : new int[][] {{1, 1}, {2, 1}, {1, 2}, {2, 2}}) {
            Point p = d.screenOfPoint(0, ij[0], ij[1]);
            from = new Point(Math.min(from.x, p.x - 14), Math.min(from.y, p.y - 14));
            to = new Point(Math.max(to.x, p.x + 14), Math.max(to.y, p.y + 14));
        }
        d.robot.mouseMove(from.x, from.y);
        d.robot.keyPress(KeyEvent.VK_SHIFT);
        d.robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int k = 1; k <= 10; k++) {
            d.robot.mouseMove(from.x + (to.x - from.x) * k / 10, from.y + (to.y - from.y) * k / 10);
            d.robot.delay(10);
        }
        shot(d, dir, "rubber-band.png");
        d.robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        d.robot.keyRelease(KeyEvent.VK_SHIFT);
        d.settle();
        open(d, "teapot");
        GuiDriver.onEdt(() -> {
            d.app.settings().set(Toggle.SMOOTH_JOINS, true);
            d.app.view().zoom(-4);
        });
        d.settle();
        int[] row = Borders.visibleRow(d, GuiDriver.onEdt(() -> d.app.document().scene()));
        Point p = d.screenOfPoint(row[3], row[4], row[5]);
        d.drag(p, new Point(p.x - 20, p.y + 70), 10);
        d.mouseAway();
        shot(d, dir, "teapot-edit.png");
        GuiDriver.onEdt(() -> {
            d.app.settings().set(Toggle.SMOOTH_JOINS, false);
            d.app.selections().clear();
        });
    }

    /** Show Light on the bent patch, the light dragged a little. */
    private static void lightShot(GuiDriver d, Path dir) throws Exception {
        open(d, "patch");
        GuiDriver.onEdt(() -> {
            d.app.edits().randomize(7);
            d.app.settings().set(Toggle.SHOW_LIGHT, true);
        });
        d.settle();
        var m = GuiDriver.onEdt(() -> d.app.overlay().snapshot().lights().get(0));
        Point at = d.screenOf(m.x(), m.y());
        d.drag(at, new Point(at.x + 40, at.y + 20), 8);
        d.mouseAway();
        shot(d, dir, "light.png");
        GuiDriver.onEdt(() -> d.app.settings().set(Toggle.SHOW_LIGHT, false));
    }

    /** View → Difference to Clipping on the teapot in the tessellated mode (K = 16). */
    private static void differenceShot(GuiDriver d, Path dir) throws Exception {
        open(d, "teapot");
        d.menu("View", "polygon");
        d.menu("View", "points");
        d.menu("View", "differenceToClipping");
        d.menu("Render", "tessellated");
        d.waitFor("the difference count", () -> d.frame.statusBar().text("difference").contains("tessellated"));
        shot(d, dir, "difference.png");
        d.menu("Render", "tessellated");
        d.menu("View", "differenceToClipping");
        d.menu("View", "polygon");
        d.menu("View", "points");
    }

    /** File → Export Image…'s dialog. */
    private static void exportDialogShot(GuiDriver d, Path dir) throws Exception {
        SwingUtilities.invokeLater(() -> d.frame.actions().get("exportImage").actionPerformed(null));
        JDialog dialog = d.dialogWith(JSpinner.class);
        d.robot.delay(300);
        d.robot.waitForIdle();
        Rectangle r = GuiDriver.onEdt(() -> dialog.getBounds());
        ImageIO.write(d.robot.createScreenCapture(r), "png", dir.resolve("export-image.png").toFile());
        d.key(KeyEvent.VK_ESCAPE);
        d.waitFor("the dialog to close", () -> !dialog.isShowing());
    }

    private static void open(GuiDriver d, String builtIn) {
        GuiDriver.onEdt(() -> {
            d.app.document().history().markSaved();
            d.app.files().openBuiltIn(builtIn);
        });
        d.settle();
    }

    private static void shot(GuiDriver d, Path dir, String name) throws Exception {
        d.settle();
        d.robot.delay(300);
        Rectangle r = GuiDriver.onEdt(() -> d.frame.getBounds());
        BufferedImage img = d.robot.createScreenCapture(r);
        ImageIO.write(img, "png", dir.resolve(name).toFile());
    }
}
