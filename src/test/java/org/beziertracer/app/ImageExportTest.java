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

    @Test
    void sizesAndSamplesAreCheckedInOneLine() {
        assertEquals("the image size must be 1..16384 pixels a side, got 0×10",
                UserMessages.of(IllegalArgumentException.class, () -> new ExportOptions(0, 10, 1, SamplerKind.REGULAR)));
        assertEquals("samples per pixel must be 1..1024, got 5000",
                UserMessages.of(IllegalArgumentException.class, () -> new ExportOptions(10, 10, 5000, SamplerKind.REGULAR)));
        assertTrue(UserMessages.of(IllegalArgumentException.class,
                () -> new ExportOptions(16000, 16000, 1, SamplerKind.REGULAR)).contains("too big"));
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
