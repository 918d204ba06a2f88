package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.WriteProgress;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** File → Save of a big model: the status bar counts the patches written; Cancel leaves the old file. */
class SaveProgressTest {

    static final int PATCHES = 5_000;

    @TempDir
    Path dir;

    private final FakeDialogs dialogs = new FakeDialogs();
    private final AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());

    private void openBigGrid() {
        app.files().open("grid", () -> new SceneDocument(new Scene(BigModels.grid(PATCHES)), RenderSettings.defaults()));
        assertEquals(PATCHES, app.document().scene().patchCount());
    }

    /** The status bar's task texts, one per refresh that showed a count. */
    private List<String> watchTask(java.util.function.Consumer<Task> onCount) {
        List<String> seen = new ArrayList<>();
        app.addListener(() -> {
            Task t = app.status().task();
            if (t != null && !t.count().isEmpty()) {
                seen.add(t.text());
                onCount.accept(t);
            }
        });
        return seen;
    }

    @Test
    void savingABigModelShowsThePatchesWrittenOfAllInEveryFormat() throws IOException {
        openBigGrid();
        List<String> seen = watchTask(t -> { });
        for (String ext : List.of("bpt", "obj", "igs", "stp")) {
            seen.clear();
            Path p = dir.resolve("big." + ext);
            app.files().saveTo(p, () -> { });
            assertTrue(dialogs.errors.isEmpty(), dialogs.errors.toString());
            assertEquals("saving big." + ext + ": 1,024 / 5,000 patches", seen.get(0), ext);
            assertEquals("saving big." + ext + ": 5,000 / 5,000 patches", seen.get(seen.size() - 1), ext);
            assertEquals(PATCHES / WriteProgress.STEP + 1, seen.size(), ext + ": a report a step and the last: " + seen);
            assertEquals("saved " + p, app.status().message());
            assertNull(app.status().task(), "the bar is gone");
            assertEquals(PATCHES, org.beziertracer.model.io.FileFormats.find(p.toString()).orElseThrow().read(p)
                    .scene().patchCount(), ext);
        }
    }

    @Test
    void cancellingASaveLeavesTheOldFileAndNoTemporaryFile() throws IOException {
        for (String ext : List.of("bpt", "obj", "igs", "stp")) {
            Path p = dir.resolve("old." + ext);
            byte[] old = ("the old " + ext + " file\n").getBytes(java.nio.charset.StandardCharsets.UTF_8);
            Files.write(p, old);
            AppModel fresh = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());
            fresh.files().open("grid", () -> new SceneDocument(new Scene(BigModels.grid(PATCHES)), RenderSettings.defaults()));
            int[] cancels = {0};
            fresh.addListener(() -> {
                Task t = fresh.status().task();
                if (t != null && !t.count().isEmpty() && cancels[0]++ == 0) {
                    t.cancel(); // at the first count: 1,024 of 5,000 patches
                }
            });
            fresh.files().saveTo(p, () -> { });
            assertEquals(1, cancels[0], ext + ": the save stopped at the first report after Cancel");
            assertArrayEquals(old, Files.readAllBytes(p), ext + ": the old file is untouched");
            try (Stream<Path> files = Files.list(dir)) {
                assertEquals(List.of(p.getFileName().toString()), files.map(f -> f.getFileName().toString())
                        .filter(f -> f.startsWith("old." + ext) || f.startsWith(".old." + ext)).toList(),
                        ext + ": no temporary file left");
            }
            assertEquals("saving old." + ext + " cancelled (the file is as it was)", fresh.status().message());
            assertTrue(dialogs.errors.isEmpty(), "a cancel is no error: " + dialogs.errors);
            assertNull(fresh.status().task());
            assertFalse(Thread.currentThread().isInterrupted(), "no interrupt leaks out of the save");
            assertEquals(null, fresh.document().file(), ext + ": the document was not saved");
        }
    }
}
