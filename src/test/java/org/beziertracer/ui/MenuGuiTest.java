package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;
import javax.swing.AbstractButton;
import javax.swing.JDialog;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;

import org.beziertracer.UserMessages;
import org.beziertracer.app.DocumentFiles;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.render.Failures;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

/**
 * GUI tests of the menus and dialogs: every command is chosen by clicking its menu item with
 * {@link java.awt.Robot}, file names are typed into the real file chooser, and the checks are on
 * the files written, the dialogs shown and the screen's pixels.
 */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class MenuGuiTest extends GuiSession {

    @TempDir
    Path dir;

    /** Clicks the button labelled {@code text} in {@code dialog} and waits for the dialog to close. */
    private static void press(JDialog dialog, String text) {
        AbstractButton b = GuiDriver.onEdt(() -> GuiDriver.button(dialog, text));
        assertNotNull(b, "a " + text + " button");
        d.clickUntil(b, "the dialog to close", () -> !dialog.isShowing());
    }

    @Test
    @Order(1)
    void saveAsWritesTheSurfaceAndOpenReadsItBack() throws Exception {
        d.menu("Surface", "randomize");
        d.menu("View", "resetView"); // framed on the bent surface, as opening it will frame it
        d.settle();
        BufferedImage bent = d.capturePanel();
        assertTrue(title().startsWith("*"), title());
        Path file = dir.resolve("bent.bpt");
        d.menu("File", "saveAs");
        d.chooseFile(file);
        d.settle();
        assertEquals(GuiDriver.onEdt(() -> d.app.document().scene()).patches(), Models.load(file.toString()).patches(),
                "the saved file holds the surface as shown");
        assertEquals("bent.bpt — Bézier Tracer", title(), "saved: no star, the file's name");

        d.menu("Models", "model:patch");
        d.settle();
        assertTrue(GuiDriver.differing(bent, d.capturePanel(), 24) > 500, "the flat patch");
        d.menu("File", "open");
        d.chooseFile(file);
        d.settle();
        assertEquals("bent.bpt — Bézier Tracer", title());
        BufferedImage reopened = d.capturePanel();
        assertTrue(GuiDriver.differing(bent, reopened, 24) < 50, "File → Open shows the saved surface: "
                + GuiDriver.save(bent, "saved-bent") + " " + GuiDriver.save(reopened, "reopened"));
        assertEquals("opened bent.bpt", d.status("message"));
    }

    @Test
    @Order(9)
    void viewContinuityListsTheTeapotsBordersWorstFirstAndMarksThemOnTheView() {
        d.menu("Models", "model:teapot");
        d.settle();
        BufferedImage before = d.capturePanel();
        d.menu("View", "continuity");
        d.settle();
        ContinuityPanel panel = GuiDriver.onEdt(() -> d.frame.continuity());
        d.waitFor("the borders certified", () -> panel.summary().endsWith(" open"));
        assertEquals("52 borders: 32 G2, 16 G1, 4 G0, 0 open", GuiDriver.onEdt(panel::summary));
        assertEquals(52, (int) GuiDriver.onEdt(panel::rowCount));
        BufferedImage marked = d.capturePanel();
        GuiDriver.save(d.capture(d.frame.getContentPane()), "continuity-teapot");
        int green = 0;
        for (int y = 0; y < marked.getHeight(); y++) {
            for (int x = 0; x < marked.getWidth(); x++) {
                int c = marked.getRGB(x, y), r = c >> 16 & 0xFF, g = c >> 8 & 0xFF, b = c & 0xFF;
                if (g > 150 && r < 110 && b < 130 && (before.getRGB(x, y) & 0xFFFFFF) != (c & 0xFFFFFF)) {
                    green++;
                }
            }
        }
        assertTrue(green > 100, "the G2 borders are marked green on the view: " + green + " pixels");
        // a looser G1 tolerance than the lid's 116.6° crease: no border is G0 only any more
        javax.swing.JSpinner g1 = (javax.swing.JSpinner) GuiDriver.find(d.frame, "continuity.g1");
        GuiDriver.onEdt(() -> {
            g1.setValue(120.0);
            return null;
        });
        d.click(GuiDriver.find(d.frame, "continuity.apply"));
        d.waitFor("the new classes", () -> panel.summary().contains(" 0 G0"));
        assertEquals("52 borders: 32 G2, 20 G1, 0 G0, 0 open", GuiDriver.onEdt(panel::summary));
        d.menu("View", "continuity");
        d.settle();
        assertTrue(!GuiDriver.onEdt(panel::isVisible), "the panel goes with the toggle");
    }

    @Test
    @Order(8)
    void viewAnalysisShowsACurvatureViewWithItsScaleInTheStatusBar() {
        d.menu("Models", "model:teapot");
        d.settle();
        BufferedImage shaded = d.capturePanel();
        d.menuPath("View", "analysis", "analysis:gaussian");
        d.settle();
        GuiDriver.save(d.capture(d.frame.getContentPane()), "analysis-gaussian");
        String scale = d.status("legend");
        assertTrue(scale.startsWith("gaussian ") && scale.contains(" … "), "the scale is shown: " + scale);
        BufferedImage analysed = d.capturePanel();
        assertTrue(GuiDriver.differing(shaded, analysed, 24) > shaded.getWidth() * shaded.getHeight() / 50,
                "the picture changed to the curvature colours");
        // the value under the mouse: the teapot's body at the picture's centre
        int w = GuiDriver.onEdt(() -> d.app.view().width()), h = GuiDriver.onEdt(() -> d.app.view().height());
        java.awt.Point centre = d.screenOf(w / 2.0, h / 2.0);
        d.robot.mouseMove(centre.x, centre.y);
        d.robot.mouseMove(centre.x + 1, centre.y);
        d.waitFor("the value under the mouse", () -> d.app.hover().text().startsWith("K = "));
        d.settle();
        String legend = d.status("legend");
        assertTrue(legend.contains(" · K = ") && legend.contains(" on patch "), legend);
        d.mouseAway();
        d.menuPath("View", "analysis", "analysis:zebra");
        d.settle();
        assertEquals(org.beziertracer.render.ShadingMode.ZEBRA, GuiDriver.onEdt(() -> d.app.settings().current().analysis()));
        assertEquals("zebra", d.status("legend"));
        BufferedImage sixteen = d.capturePanel();
        // the colour legend in the bottom-right corner: there for the curvature view, not for zebra (each
        // picture's own corner: a longer status text may have wrapped the status bar onto a second row)
        assertTrue(GuiDriver.differing(corner(analysed), corner(sixteen), 24) > 1000, "the curvature view's legend");
        d.menuPath("View", "analysis", "analysisSettings");
        JDialog settings = d.dialogWith(javax.swing.JSpinner.class);
        d.typeSpinner(settings, "analysis.zebraStripes", "6");
        d.click(GuiDriver.onEdt(() -> GuiDriver.button(settings, "OK")));
        d.waitFor("the dialog to close", () -> !settings.isShowing());
        d.settle();
        assertEquals(6, (int) GuiDriver.onEdt(() -> d.app.settings().current().analysisSettings().zebraStripes()));
        assertTrue(GuiDriver.differing(sixteen, d.capturePanel(), 24) > 200, "fewer, wider stripes");
        d.menuPath("View", "analysis", "analysis:none");
        d.settle();
        assertEquals("", d.status("legend"), "no legend for the shading");
        assertEquals(null, GuiDriver.onEdt(() -> d.app.settings().current().analysis()));
    }

    @Test
    @Order(2)
    void exportPictureWritesWhatThePanelShows() throws Exception {
        d.menu("Surface", "randomize");
        d.settle();
        BufferedImage shown = d.capturePanel();
        Path png = dir.resolve("picture.png");
        d.menu("File", "exportPng");
        d.chooseFile(png);
        d.settle();
        BufferedImage written = ImageIO.read(png.toFile());
        assertEquals((int) GuiDriver.onEdt(() -> d.app.view().width()), written.getWidth(), "at device resolution");
        // The screen capture is in user-space pixels: compare at that size (the same under scale 1)
        BufferedImage atScreenSize = new BufferedImage(shown.getWidth(), shown.getHeight(), BufferedImage.TYPE_INT_RGB);
        java.awt.Graphics2D g = atScreenSize.createGraphics();
        g.setRenderingHint(java.awt.RenderingHints.KEY_INTERPOLATION, java.awt.RenderingHints.VALUE_INTERPOLATION_BILINEAR);
        g.drawImage(written, 0, 0, shown.getWidth(), shown.getHeight(), null);
        g.dispose();
        boolean scaled = written.getWidth() != shown.getWidth();
        int off = GuiDriver.differing(shown, atScreenSize, scaled ? 40 : 8);
        assertTrue(off < shown.getWidth() * shown.getHeight() / (scaled ? 50 : 200),
                "the PNG is the picture: " + off + " pixels differ");
        assertEquals("exported " + png, d.status("message"));
    }

    @Test
    @Order(3)
    void exportMeshWritesTwoTrianglesPerCell() throws Exception {
        d.menu("Models", "model:teapot");
        d.settle();
        Path obj = dir.resolve("mesh.obj");
        d.menu("File", "exportMesh");
        d.chooseFile(obj);
        d.settle();
        long faces = Files.readAllLines(obj).stream().filter(l -> l.startsWith("f ")).count();
        assertEquals(32L * 2 * DocumentFiles.MESH_SEGMENTS * DocumentFiles.MESH_SEGMENTS, faces);
        assertTrue(d.status("message").startsWith("exported " + faces + " triangles"), d.status("message"));
    }

    @Test
    @Order(4)
    void aMalformedFileShowsAnErrorDialogAndKeepsTheOldModel() throws Exception {
        Path bad = dir.resolve("broken.bpt");
        Files.writeString(bad, "1\n3 3\n0 0 0\n1 1 nope\n");
        BufferedImage img0 = d.capturePanel();
        d.menu("File", "open");
        d.chooseFile(bad);
        JDialog dialog = d.dialogWith(JOptionPane.class);
        String message = UserMessages.check(d.optionMessage(dialog));
        assertTrue(message.startsWith(bad + ":"), message);
        press(dialog, "OK");
        d.settle();
        assertEquals("patch — Bézier Tracer", title(), "the old model is kept");
        assertTrue(GuiDriver.differing(img0, d.capturePanel(), 8) < 50, "the old picture is still shown");
    }

    @Test
    @Order(5)
    void quittingWithUnsavedEditsAsksAndCancelKeepsTheWindow() {
        d.tool("randomize");
        d.settle();
        SwingUtilities.invokeLater(() -> { }); // let the menu bar settle after the click
        d.menu("File", "quit");
        JDialog dialog = d.dialogWith(JOptionPane.class);
        assertTrue(d.optionMessage(dialog).contains("unsaved edits"), d.optionMessage(dialog));
        press(dialog, "Cancel");
        d.settle();
        assertTrue(GuiDriver.onEdt(() -> d.frame.isDisplayable() && d.frame.isShowing()), "the window stays open");
        assertTrue(title().startsWith("*"), "the edits stay: " + title());
    }

    @Test
    @Order(6)
    void anUncaughtErrorShowsOneLineAndTheAppKeepsRunning() {
        SwingUtilities.invokeLater(() -> {
            throw new IllegalArgumentException("thrown on purpose by the test");
        });
        JDialog dialog = d.dialogWith(JOptionPane.class);
        assertEquals(UncaughtErrors.TITLE, GuiDriver.onEdt(dialog::getTitle));
        assertEquals("thrown on purpose by the test", d.optionMessage(dialog));
        press(dialog, "OK");
        NullPointerException bug = new NullPointerException("Cannot invoke \"java.nio.file.Path.toString()\" because it is null");
        SwingUtilities.invokeLater(() -> {
            throw bug;
        });
        dialog = d.dialogWith(JOptionPane.class);
        assertEquals(Failures.describe(bug), UserMessages.check(d.optionMessage(dialog)),
                "no class name and no \"null\" reach the user");
        press(dialog, "OK");
        BufferedImage before = d.capturePanel();
        Rectangle centre = centreBox();
        d.tool("normals");
        d.settle();
        assertTrue(GuiDriver.differing(before, d.capturePanel(), centre, 30) > 20, "the app still works");
    }

    @Test
    @Order(7)
    void openingShowsProgressWithCancelAndCancelKeepsTheCurrentModel() throws Exception {
        BufferedImage img0 = d.capturePanel();
        CountDownLatch started = new CountDownLatch(1);
        CountDownLatch never = new CountDownLatch(1);
        GuiDriver.onEdt(() -> d.app.files().open("slow model", () -> {
            started.countDown();
            never.await();
            return new SceneDocument(Models.teapot(), RenderSettings.defaults());
        }));
        assertTrue(started.await(10, TimeUnit.SECONDS));
        java.awt.Component progress = d.find("status.progress");
        java.awt.Component cancel = d.find("status.cancel");
        d.waitFor("the progress bar", () -> progress.isShowing() && cancel.isShowing());
        assertEquals("opening slow model", GuiDriver.onEdt(() -> ((javax.swing.JProgressBar) progress).getString()));
        d.click(cancel);
        d.waitFor("the progress bar to go", () -> !progress.isShowing());
        d.settle();
        assertEquals("opening slow model cancelled", d.status("message"));
        assertEquals("patch — Bézier Tracer", title());
        assertTrue(GuiDriver.differing(img0, d.capturePanel(), 8) < 50, "the current model is still shown");
    }

    /** The 240×80 bottom-right corner of a picture. */
    private static BufferedImage corner(BufferedImage img) {
        return img.getSubimage(img.getWidth() - 240, img.getHeight() - 80, 240, 80);
    }
}
