package org.beziertracer.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Frame;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;

import javax.imageio.ImageIO;
import javax.swing.JDialog;
import javax.swing.JFrame;
import javax.swing.JList;
import javax.swing.JOptionPane;
import javax.swing.JSpinner;
import javax.swing.TransferHandler;

import org.beziertracer.app.MemoryPreferences;
import org.beziertracer.cli.BezierTracerCommand;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;

/**
 * GUI tests of getting models in and pictures out: File → Open Recent, a file dragged onto the
 * window, File → Export Image… with its progress bar and Cancel, a big save and a big mesh export with
 * their counts and Cancel, and the app opened on a model from
 * the command line. Checks are on the window's title and pixels and on the files written.
 */
@Tag("gui")
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class FilesGuiTest extends GuiSession {

    @TempDir
    Path dir;

    /** Saves the default patch, bent, as {@code name} through File → Save As; returns its picture. */
    private BufferedImage saveBent(Path file) {
        d.menu("Surface", "randomize");
        d.menu("View", "resetView");
        d.settle();
        d.menu("File", "saveAs");
        d.chooseFile(file);
        d.settle();
        return d.capturePanel();
    }

    @Test
    @Order(1)
    void openRecentReopensTheLastFilesFromTheMenuAndByShortcut() {
        Path file = dir.resolve("recent-bent.bpt");
        BufferedImage bent = saveBent(file);
        d.menu("Models", "model:teapot");
        d.settle();
        assertTrue(title().startsWith("teapot"));
        d.menuPath("File", "openRecent", "recent0");
        d.settle();
        assertEquals("recent-bent.bpt — Bézier Tracer", title());
        assertTrue(GuiDriver.differing(bent, d.capturePanel(), 24) < 50, "File → Open Recent shows the saved surface");
        d.menu("Models", "model:teapot");
        d.settle();
        d.focusPicture();
        d.ctrl(KeyEvent.VK_1);
        d.settle();
        assertEquals("recent-bent.bpt — Bézier Tracer", title(), "Ctrl+1 opens the newest recent file");
        assertEquals(file.toAbsolutePath(), d.prefs.recentFiles().get(0), "kept in the app's own preferences");
    }

    @Test
    @Order(2)
    void aModelFileDraggedOntoTheWindowOpens() throws Exception {
        Path file = dir.resolve("dropped.bpt");
        org.beziertracer.model.io.FileFormats.BPT.write(file, new org.beziertracer.model.io.SceneDocument(
                Models.teapot(), org.beziertracer.model.RenderSettings.defaults()));
        BufferedImage patch = d.capturePanel();
        dropOnPicture(file.toFile());
        d.waitFor("the dropped file to open", () -> d.frame.getTitle().startsWith("dropped.bpt"));
        d.settle();
        assertTrue(GuiDriver.differing(patch, d.capturePanel(), 24) > 2000, "the teapot shows");
    }

    /** Drags {@code file} with the mouse from a window of its own onto the middle of the picture. */
    private static void dropOnPicture(File file) {
        JFrame source = GuiDriver.onEdt(() -> dragSource(file));
        try {
            d.waitFor("the drag source to show", source::isShowing);
            JList<?> list = (JList<?>) GuiDriver.descendant(source, JList.class);
            Point from = GuiDriver.onEdt(() -> {
                Point s = list.getLocationOnScreen();
                Rectangle cell = list.getCellBounds(0, 0);
                return new Point(s.x + cell.x + cell.width / 2, s.y + cell.y + cell.height / 2);
            });
            Point to = d.screenOf(GuiDriver.onEdt(() -> d.app.view().width()) / 2.0,
                    GuiDriver.onEdt(() -> d.app.view().height()) / 2.0);
            d.drag(from, to, 40);
        } finally {
            GuiDriver.onEdt(source::dispose);
        }
    }

    /** A small window listing {@code file}, from which it can be dragged (as from a file manager). */
    private static JFrame dragSource(File file) {
        JFrame f = new JFrame("drag source");
        JList<String> list = new JList<>(new String[] {file.getName()});
        list.setDragEnabled(true);
        list.setTransferHandler(new TransferHandler() {
            @Override
            public int getSourceActions(javax.swing.JComponent c) { return COPY; }

            @Override
            protected Transferable createTransferable(javax.swing.JComponent c) {
                return new Transferable() {
                    @Override
                    public DataFlavor[] getTransferDataFlavors() { return new DataFlavor[] {DataFlavor.javaFileListFlavor}; }

                    @Override
                    public boolean isDataFlavorSupported(DataFlavor flavor) { return DataFlavor.javaFileListFlavor.equals(flavor); }

                    @Override
                    public Object getTransferData(DataFlavor flavor) { return List.of(file); }
                };
            }
        });
        f.add(list);
        f.setBounds(1000, 40, 240, 120);
        f.setVisible(true);
        return f;
    }

    @Test
    @Order(3)
    void exportImageAsksSizeSamplesAndSamplerAndWritesThePng() throws Exception {
        Path png = dir.resolve("export.png");
        exportThroughTheDialog(png, "200", "150", "4");
        d.waitFor("the export to finish", () -> d.app.status().message().startsWith("exported"));
        BufferedImage img = ImageIO.read(png.toFile());
        assertEquals(200, img.getWidth());
        assertEquals(150, img.getHeight());
        double[] middle = GuiDriver.mean(img, new Rectangle(90, 65, 20, 20));
        double[] corner = GuiDriver.mean(img, new Rectangle(0, 0, 10, 10));
        assertTrue(middle[0] > corner[0] + 40, "the lit surface in the middle, the background in the corner: "
                + GuiDriver.save(img, "export"));
        assertEquals("exported 200×150 image to " + png, d.status("message"));
        d.menu("File", "exportImage");
        JDialog again = d.dialogWith(JSpinner.class);
        assertEquals(org.beziertracer.render.SamplerKind.REGULAR, GuiDriver.onEdt(() ->
                ((javax.swing.JComboBox<?>) GuiDriver.find(again, "export.sampler")).getSelectedItem()),
                "the choices are offered again next time");
        assertEquals(200, (int) GuiDriver.onEdt(() -> ((JSpinner) GuiDriver.find(again, "export.width")).getValue()));
        d.click(GuiDriver.onEdt(() -> GuiDriver.button(again, "Cancel")));
        d.waitFor("the dialog to close", () -> !again.isShowing());
        d.settle();
        assertEquals("exported 200×150 image to " + png, d.status("message"), "Cancel exports nothing");
    }

    @Test
    @Order(7)
    void exportImageOffersThePathTracerAndWritesTheLinearPfm() throws Exception {
        Path pfm = dir.resolve("path.pfm");
        d.menu("File", "exportImage");
        JDialog options = d.dialogWith(JSpinner.class);
        JSpinner seconds = (JSpinner) GuiDriver.find(options, "export.seconds");
        javax.swing.JCheckBox path = (javax.swing.JCheckBox) GuiDriver.find(options, "export.path");
        assertFalse(GuiDriver.onEdt(() -> path.isSelected() || seconds.isEnabled()), "Whitted first: no time limit");
        d.typeSpinner(options, "export.width", "64");
        d.typeSpinner(options, "export.height", "48");
        d.typeSpinner(options, "export.spp", "2");
        d.click(path);
        d.waitFor("the time limit enabled", seconds::isEnabled);
        assertEquals(0, (int) GuiDriver.onEdt(() -> (Integer) seconds.getValue()), "no time limit offered");
        d.click(GuiDriver.onEdt(() -> GuiDriver.button(options, "OK")));
        d.chooseFile(pfm);
        d.waitFor("the export to finish", () -> d.app.status().message().startsWith("exported"));
        byte[] bytes = Files.readAllBytes(pfm);
        String header = "PF\n64 48\n-1.0\n";
        assertEquals(header, new String(bytes, 0, header.length(), java.nio.charset.StandardCharsets.US_ASCII));
        assertEquals(header.length() + 12 * 64 * 48, bytes.length, "three floats a pixel");
        d.menu("File", "exportImage");
        JDialog again = d.dialogWith(JSpinner.class);
        assertTrue(GuiDriver.onEdt(() -> ((javax.swing.JCheckBox) GuiDriver.find(again, "export.path")).isSelected()),
                "path traced is offered again");
        d.click(GuiDriver.onEdt(() -> GuiDriver.button(again, "Cancel")));
        d.waitFor("the dialog to close", () -> !again.isShowing());
    }

    /** File → Export Image…: types the size and samples, picks the first sampler (regular), OK, then the file. */
    private static void exportThroughTheDialog(Path png, String width, String height, String spp) {
        d.menu("File", "exportImage");
        JDialog options = d.dialogWith(JSpinner.class);
        d.typeSpinner(options, "export.width", width);
        d.typeSpinner(options, "export.height", height);
        d.typeSpinner(options, "export.spp", spp);
        javax.swing.JComboBox<?> sampler = (javax.swing.JComboBox<?>) GuiDriver.find(options, "export.sampler");
        d.click(sampler);
        d.key(KeyEvent.VK_HOME);
        d.key(KeyEvent.VK_ENTER);
        d.waitFor("the regular sampler", () -> sampler.getSelectedIndex() == 0);
        d.click(GuiDriver.onEdt(() -> GuiDriver.button(options, "OK")));
        d.chooseFile(png);
    }

    @Test
    @Order(4)
    void aBigExportShowsItsProgressAndCancelWritesNoFile() throws Exception {
        d.menu("Models", "model:teapot");
        d.settle();
        Path png = dir.resolve("big.png");
        exportThroughTheDialog(png, "4000", "3000", "64");
        javax.swing.JProgressBar bar = d.find("status.progress");
        d.waitFor("a progress bar that fills", () -> bar.isShowing() && !bar.isIndeterminate() && bar.getValue() > 0);
        assertEquals("exporting big.png", GuiDriver.onEdt(() -> bar.getString()));
        d.click(d.find("status.cancel"));
        d.waitFor("the progress bar to go", () -> !bar.isShowing());
        d.settle();
        assertEquals("export of big.png cancelled", d.status("message"));
        assertFalse(Files.exists(png), "no file");
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "and no temporary file left");
        }
    }

    @Test
    @Order(5)
    void theCommandLineOpensTheAppOnAModel() throws Exception {
        AtomicReference<java.util.concurrent.CompletableFuture<AppFrame>> started = new AtomicReference<>();
        int code = BezierTracerCommand.run(new String[] {"teapot"},
                model -> started.set(BezierTracerApp.start(MemoryPreferences.fresh(), model)));
        assertEquals(BezierTracerCommand.APP_RUNNING, code);
        AppFrame second = started.get().get(30, TimeUnit.SECONDS);
        try {
            d.waitFor("the second window on the teapot", () -> second.getTitle().startsWith("teapot")
                    && !second.app().busy());
            Frame[] frames = Frame.getFrames();
            assertTrue(java.util.Arrays.stream(frames).anyMatch(f -> f == second && f.isShowing()));
            BufferedImage img = d.capture(second.renderPanel());
            double[] middle = GuiDriver.mean(img, new Rectangle(img.getWidth() / 2 - 20, img.getHeight() / 2 - 10, 40, 20));
            assertTrue(middle[0] > 90, "the teapot is drawn: " + java.util.Arrays.toString(middle) + " "
                    + GuiDriver.save(img, "cli-teapot"));
            assertEquals("32 patches, 512 points; new grid 4×4", GuiDriver.onEdt(() -> second.statusBar().text("model")));
        } finally {
            GuiDriver.onEdt(() -> {
                second.app().document().history().markSaved();
                second.close();
            });
        }
    }

    @Test
    @Order(6)
    void aDroppedFileThatCannotBeOpenedSaysWhatCan() throws Exception {
        Path png = Files.writeString(dir.resolve("photo.png"), "x");
        dropOnPicture(png.toFile());
        JDialog dialog = d.dialogWith(JOptionPane.class);
        assertEquals(png + ": cannot open this kind of file; drop a .bpt, .obj, .igs, .iges, .stp, .step or .json file", d.optionMessage(dialog));
        d.click(GuiDriver.onEdt(() -> GuiDriver.button(dialog, "OK")));
        d.waitFor("the dialog to close", () -> !dialog.isShowing());
        assertEquals("patch — Bézier Tracer", title(), "the model stays");
    }

    @Test
    @Order(7)
    void aBigSaveCountsThePatchesWrittenAndCancelKeepsTheOldFile() throws Exception {
        org.beziertracer.model.Scene big = new org.beziertracer.model.Scene(org.beziertracer.app.BigModels.grid(200_000));
        GuiDriver.onEdt(() -> d.app.files().open("grid", () -> new org.beziertracer.model.io.SceneDocument(big,
                org.beziertracer.model.RenderSettings.defaults())));
        d.waitFor("the big model", () -> d.app.document().scene() == big);
        d.settle();
        Path obj = Files.writeString(dir.resolve("old.obj"), "# the old file\n");
        GuiDriver.onEdt(() -> d.app.files().saveTo(obj, () -> { }));
        javax.swing.JProgressBar bar = d.find("status.progress");
        d.waitFor("a bar that counts patches", () -> bar.isShowing() && !bar.isIndeterminate()
                && bar.getString().endsWith(" / 200,000 patches"));
        String shown = GuiDriver.onEdt(bar::getString);
        assertTrue(shown.matches("saving old\\.obj: [0-9,]+ / 200,000 patches"), shown);
        d.click(d.find("status.cancel"));
        d.waitFor("the progress bar to go", () -> !bar.isShowing());
        d.settle();
        assertEquals("saving old.obj cancelled (the file is as it was)", d.status("message"));
        assertEquals("# the old file\n", Files.readString(obj), "the old file is untouched");
        try (var files = Files.list(dir)) {
            assertEquals(List.of("old.obj"), files.map(f -> f.getFileName().toString()).toList(), "no temporary file");
        }
        d.menu("Models", "model:patch");
        d.settle();
    }

    @Test
    @Order(8)
    void aBigMeshExportCountsThePatchesWrittenAndCancelKeepsTheOldFile() throws Exception {
        org.beziertracer.model.Scene big = new org.beziertracer.model.Scene(org.beziertracer.app.BigModels.grid(20_000));
        GuiDriver.onEdt(() -> d.app.files().open("grid", () -> new org.beziertracer.model.io.SceneDocument(big,
                org.beziertracer.model.RenderSettings.defaults())));
        d.waitFor("the big model", () -> d.app.document().scene() == big);
        d.settle();
        Path obj = Files.writeString(dir.resolve("old-mesh.obj"), "# the old mesh\n");
        GuiDriver.onEdt(() -> d.app.files().exportMeshTo(obj));
        javax.swing.JProgressBar bar = d.find("status.progress");
        d.waitFor("a bar that counts patches", () -> bar.isShowing() && !bar.isIndeterminate()
                && bar.getString().endsWith(" / 20,000 patches"));
        String shown = GuiDriver.onEdt(bar::getString);
        assertTrue(shown.matches("exporting old-mesh\\.obj: [0-9,]+ / 20,000 patches"), shown);
        d.click(d.find("status.cancel"));
        d.waitFor("the progress bar to go", () -> !bar.isShowing());
        d.settle();
        assertEquals("exporting old-mesh.obj cancelled (the file is as it was)", d.status("message"));
        assertEquals("# the old mesh\n", Files.readString(obj), "the old file is untouched");
        try (var files = Files.list(dir)) {
            assertEquals(List.of("old-mesh.obj"), files.map(f -> f.getFileName().toString())
                    .filter(f -> f.contains("old-mesh")).toList(), "no temporary file");
        }
        d.menu("Models", "model:patch");
        d.settle();
    }
}
