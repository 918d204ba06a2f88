package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.beziertracer.UserMessages;
import org.beziertracer.render.SamplerKind;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** File → Export Image…: asks size, samples and sampler, renders off screen with progress, writes atomically, cancels. */
class ImageExportTest {

    @TempDir
    Path dir;

    /** Writes the raw pixels (4 bytes each), so the test can read them back without an image library. */
    static final ImageExport.ImageEncoder RAW = (w, h, argb) -> out -> {
        ByteBuffer b = ByteBuffer.allocate(4 * argb.length);
        b.asIntBuffer().put(argb);
        out.write(b.array());
    };

    @Test
    void theImageIsRenderedAtTheAskedSizeWithTheViewAndTheSampler() throws Exception {
        FakeDialogs dialogs = new FakeDialogs();
        AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());
        app.view().resize(640, 480, 1);
        dialogs.export = new ExportOptions(64, 40, 4, SamplerKind.REGULAR);
        Path png = dir.resolve("out.png");
        dialogs.save = png;
        app.export().export(RAW);
        assertEquals(ExportOptions.first(640, 480), dialogs.offered, "the first offer is the picture's size");
        assertEquals(java.util.List.of(), dialogs.errors);
        byte[] bytes = Files.readAllBytes(png);
        assertEquals(4 * 64 * 40, bytes.length);
        int[] px = new int[64 * 40];
        ByteBuffer.wrap(bytes).asIntBuffer().get(px);
        assertTrue((px[20 * 64 + 32] & 0xFFFFFF) != (px[0] & 0xFFFFFF), "the surface in the middle, background in the corner");
        assertEquals("exported 64×40 image to " + png, app.status().message());
        assertNull(app.status().task(), "the progress bar is gone");
        app.export().export(RAW);
        assertEquals(dialogs.export, dialogs.offered, "the next offer is the last choice");
    }

    @Test
    void cancellingStopsTheRenderAndWritesNoFile() throws Exception {
        LinkedBlockingQueue<Runnable> ui = new LinkedBlockingQueue<>();
        ExecutorService io = Executors.newSingleThreadExecutor();
        try {
            AppThreads threads = new AppThreads(ui::add, Runnable::run, io, Runnable::run, Runnable::run, Runnable::run);
            FakeDialogs dialogs = new FakeDialogs();
            AppModel app = new AppModel(new FakeEngine(), dialogs, threads, MemoryPreferences.fresh());
            drain(ui);
            app.files().openBuiltIn("teapot");
            runUntil(ui, () -> app.document().scene().patchCount() == 32);
            Path png = dir.resolve("big.png");
            app.export().exportTo(png, new ExportOptions(3000, 2000, 64, SamplerKind.JITTERED), RAW);
            Task task = app.status().task();
            assertNotNull(task);
            assertEquals("exporting big.png", task.label());
            runUntil(ui, () -> task.progress() > 0);
            assertTrue(task.progress() < 1, "progress is reported while it renders: " + task.progress());
            task.cancel();
            runUntil(ui, () -> app.status().task() == null);
            assertEquals("export of big.png cancelled", app.status().message());
            assertFalse(Files.exists(png), "no file");
            try (var files = Files.list(dir)) {
                assertEquals(0, files.count(), "and no temporary file");
            }
            assertEquals(java.util.List.of(), dialogs.errors);
        } finally {
            io.shutdownNow();
        }
    }

    /** The teapot in the app (direct threads, fake engine), its picture 64×40. */
    private AppModel teapotApp(FakeDialogs dialogs) {
        AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());
        app.view().resize(64, 40, 1);
        app.files().openBuiltIn("teapot");
        return app;
    }

    private static int[] pixels(byte[] raw) {
        int[] px = new int[raw.length / 4];
        ByteBuffer.wrap(raw).asIntBuffer().get(px);
        return px;
    }

    @Test
    void aPathTracedExportTakesTheAppsExposure() throws Exception {
        FakeDialogs dialogs = new FakeDialogs();
        AppModel app = teapotApp(dialogs);
        app.settings().replace(app.settings().current().with(Toggle.PATH_TRACED, true).with(Level.EXPOSURE, 15));
        ExportOptions o = new ExportOptions(48, 32, 4, SamplerKind.JITTERED, true, 0);
        app.export().exportTo(dir.resolve("bright.png"), o, RAW);
        app.export().exportTo(dir.resolve("bright.pfm"), o, RAW);
        int[] png = pixels(Files.readAllBytes(dir.resolve("bright.png")));
        byte[] pfm = Files.readAllBytes(dir.resolve("bright.pfm"));
        int header = "PF\n48 32\n-1.0\n".length();
        ByteBuffer floats = ByteBuffer.wrap(pfm, header, 12 * 48 * 32).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        double scale = Math.pow(2, Double.parseDouble("1.5")); // render --exposure 1.5
        int differ = 0, brighter = 0, lit = 0;
        for (int y = 31; y >= 0; y--) { // rows bottom-up
            for (int x = 0; x < 48; x++) {
                float r = floats.getFloat(), g = floats.getFloat(), b = floats.getFloat();
                differ += org.beziertracer.render.ToneMap.argb(r, g, b, scale) == png[y * 48 + x] ? 0 : 1;
                int atZero = org.beziertracer.render.ToneMap.argb(r, g, b, 1) & 0xFF;
                lit += r + g + b > 0.01f ? 1 : 0;
                brighter += atZero < (png[y * 48 + x] & 0xFF) ? 1 : 0;
            }
        }
        assertEquals(0, differ, "the PNG is the .pfm through the tone map at +1.5 EV");
        assertTrue(lit > 100 && brighter > lit / 2, "brighter than at 0 EV: " + brighter + " of the " + lit + " lit pixels");
        assertEquals(java.util.List.of(), dialogs.errors);
    }

    @Test
    void aPathTracedExportIsToneMappedAndItsPfmHoldsTheSameLinearPicture() throws Exception {
        FakeDialogs dialogs = new FakeDialogs();
        AppModel app = teapotApp(dialogs);
        app.settings().replace(app.settings().current().with(Toggle.PATH_TRACED, true).with(Level.PATH_SAMPLES, 16));
        dialogs.export = new ExportOptions(48, 32, 4, SamplerKind.JITTERED, true, 0);
        dialogs.save = dir.resolve("path.png");
        app.export().export(RAW);
        assertEquals(ExportOptions.first(64, 40, app.settings().current()), dialogs.offered,
                "path traced: the first offer is the picture's target samples, path traced");
        assertTrue(dialogs.offered.pathTraced() && dialogs.offered.spp() == 16, dialogs.offered.toString());
        int[] png = pixels(Files.readAllBytes(dialogs.save));
        assertEquals(48 * 32, png.length);
        app.export().exportTo(dir.resolve("path.PFM"), dialogs.export, RAW);
        byte[] pfm = Files.readAllBytes(dir.resolve("path.PFM"));
        byte[] header = "PF\n48 32\n-1.0\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        assertEquals(new String(header, java.nio.charset.StandardCharsets.US_ASCII),
                new String(pfm, 0, header.length, java.nio.charset.StandardCharsets.US_ASCII), "a .pfm name: the linear image");
        assertEquals(header.length + 12 * 48 * 32, pfm.length);
        ByteBuffer floats = ByteBuffer.wrap(pfm, header.length, 12 * 48 * 32).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        int differ = 0;
        for (int y = 31; y >= 0; y--) { // rows bottom-up
            for (int x = 0; x < 48; x++) {
                int mapped = org.beziertracer.render.ToneMap.argb(floats.getFloat(), floats.getFloat(), floats.getFloat(), 1);
                differ += mapped == png[y * 48 + x] ? 0 : 1;
            }
        }
        assertEquals(0, differ, "the PNG is the .pfm through the ACES tone map");
        dialogs.export = new ExportOptions(48, 32, 4, SamplerKind.JITTERED);
        dialogs.save = dir.resolve("whitted.png");
        app.export().export(RAW);
        int[] whitted = pixels(Files.readAllBytes(dialogs.save));
        int changed = 0;
        for (int k = 0; k < png.length; k++) {
            changed += whitted[k] == png[k] ? 0 : 1;
        }
        assertTrue(changed > png.length / 4, "the path tracer, not Whitted, made the first: " + changed + " pixels differ");
        assertEquals(java.util.List.of(), dialogs.errors);
    }

    @Test
    void aTimeBudgetEndsAPathTracedExportBeforeItsSamples() throws Exception {
        FakeDialogs dialogs = new FakeDialogs();
        AppModel app = teapotApp(dialogs);
        ExportOptions o = new ExportOptions(64, 48, 1024, SamplerKind.JITTERED, true, 1);
        Task task = new Task("budget");
        var camera = app.view().view().camera(64 / 48.0);
        org.beziertracer.render.RenderResult r = ImageExport.render(app.document().scene(), camera, null,
                app.settings().current(), o, task);
        int n = r.film().sampleCount(10, 10);
        assertTrue(n >= 2 && n < 1024, "stopped by the 1 s budget after " + n + " samples a pixel");
        assertEquals(n, r.film().sampleCount(63, 47), "every pixel has as many");
        assertTrue(r.stats().millis() >= 1000, "not before the budget: " + r.stats().millis());
    }

    @Test
    void sizesAndSamplesAreCheckedInOneLine() {
        assertEquals("the image size must be 1..16384 pixels a side, got 0×10",
                UserMessages.of(IllegalArgumentException.class, () -> new ExportOptions(0, 10, 1, SamplerKind.REGULAR)));
        assertEquals("samples per pixel must be 1..1024, got 5000",
                UserMessages.of(IllegalArgumentException.class, () -> new ExportOptions(10, 10, 5000, SamplerKind.REGULAR)));
        assertTrue(UserMessages.of(IllegalArgumentException.class,
                () -> new ExportOptions(16000, 16000, 1, SamplerKind.REGULAR)).contains("too big"));
        assertEquals("a time limit needs the path tracer", UserMessages.of(IllegalArgumentException.class,
                () -> new ExportOptions(10, 10, 4, SamplerKind.JITTERED, false, 5)));
        assertEquals("the time limit must be 0..86400 seconds (0 = none), got -1", UserMessages.of(
                IllegalArgumentException.class, () -> new ExportOptions(10, 10, 4, SamplerKind.JITTERED, true, -1)));
    }

    private static void drain(LinkedBlockingQueue<Runnable> ui) {
        for (Runnable r = ui.poll(); r != null; r = ui.poll()) {
            r.run();
        }
    }

    private static void runUntil(LinkedBlockingQueue<Runnable> ui, java.util.function.BooleanSupplier done)
            throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!done.getAsBoolean()) {
            assertTrue(System.nanoTime() < end, "timed out");
            Runnable r = ui.poll(20, TimeUnit.MILLISECONDS);
            if (r != null) {
                r.run();
            }
        }
    }
}
