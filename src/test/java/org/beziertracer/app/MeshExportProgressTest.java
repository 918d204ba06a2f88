package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * File → Export Mesh of a big model goes the way of a save: the status bar counts the patches
 * written with Cancel, and a cancelled export leaves the old file as it was and no temporary file.
 */
class MeshExportProgressTest {

    /** Reports at 64, 128, 192 and 200 patches. */
    static final int PATCHES = 200;

    @TempDir
    Path dir;

    private final FakeDialogs dialogs = new FakeDialogs();

    private AppModel appOnGrid() {
        AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());
        app.files().open("grid", () -> new SceneDocument(new Scene(BigModels.grid(PATCHES)), RenderSettings.defaults()));
        assertEquals(PATCHES, app.document().scene().patchCount());
        return app;
    }

    @Test
    void exportingABigModelShowsThePatchesWrittenOfAll() throws IOException {
        AppModel app = appOnGrid();
        List<String> seen = new ArrayList<>();
        app.addListener(() -> {
            Task t = app.status().task();
            if (t != null && !t.count().isEmpty()) {
                seen.add(t.text());
            }
        });
        Path p = dir.resolve("big.obj");
        app.files().exportMeshTo(p);
        assertTrue(dialogs.errors.isEmpty(), dialogs.errors.toString());
        assertEquals(List.of("exporting big.obj: 64 / 200 patches", "exporting big.obj: 128 / 200 patches",
                "exporting big.obj: 192 / 200 patches", "exporting big.obj: 200 / 200 patches"), seen);
        long triangles = 2L * PATCHES * DocumentFiles.MESH_SEGMENTS * DocumentFiles.MESH_SEGMENTS;
        assertEquals("exported " + triangles + " triangles to " + p, app.status().message());
        assertNull(app.status().task(), "the bar is gone");
        try (Stream<String> lines = Files.lines(p)) {
            assertEquals(triangles, lines.filter(l -> l.startsWith("f ")).count());
        }
        assertEquals(null, app.document().file(), "an export is no save: the document keeps its name");
    }

    @Test
    void cancellingAnExportLeavesTheOldFileAndNoTemporaryFile() throws IOException {
        AppModel app = appOnGrid();
        Path p = dir.resolve("old.obj");
        byte[] old = "# the old mesh\n".getBytes(StandardCharsets.UTF_8);
        Files.write(p, old);
        int[] cancels = {0};
        app.addListener(() -> {
            Task t = app.status().task();
            if (t != null && !t.count().isEmpty() && cancels[0]++ == 0) {
                t.cancel(); // at the first count: 64 of 200 patches
            }
        });
        app.files().exportMeshTo(p);
        assertEquals(1, cancels[0], "the export stopped at the first report after Cancel");
        assertArrayEquals(old, Files.readAllBytes(p), "the old file is untouched");
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of("old.obj"), files.map(f -> f.getFileName().toString()).toList(), "no temporary file left");
        }
        assertEquals("exporting old.obj cancelled (the file is as it was)", app.status().message());
        assertTrue(dialogs.errors.isEmpty(), "a cancel is no error: " + dialogs.errors);
        assertNull(app.status().task());
        assertFalse(Thread.currentThread().isInterrupted(), "no interrupt leaks out of the export");
    }

    @Test
    void aFailedExportIsOneLineDialogAndTheBarGoes() {
        AppModel app = appOnGrid();
        app.files().exportMeshTo(dir.resolve("missing-folder").resolve("m.obj"));
        assertEquals(1, dialogs.errors.size(), dialogs.errors.toString());
        assertTrue(dialogs.errors.get(0).contains("m.obj: cannot write: the folder"), dialogs.errors.toString());
        assertNull(app.status().task());
    }
}
