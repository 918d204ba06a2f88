package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.Scene;
import org.beziertracer.model.io.FileFormats;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.SceneDocument;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Dropped files, the command line's model, File → Open Recent. */
class FileOpeningTest {

    @TempDir
    Path dir;

    private final FakeDialogs dialogs = new FakeDialogs();
    private final AppPreferences prefs = MemoryPreferences.fresh();
    private final AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), prefs);

    private Path teapotFile(String name) throws Exception {
        Path p = dir.resolve(name);
        FileFormats.find(name).orElseThrow().write(p, new SceneDocument(Models.teapot(),
                org.beziertracer.model.RenderSettings.defaults()));
        return p;
    }

    @Test
    void aDroppedModelOpensAndADroppedPictureSaysWhatCanBeDropped() throws Exception {
        Path png = Files.writeString(dir.resolve("photo.png"), "not a model");
        Scene before = app.document().scene();
        app.files().openDropped(List.of(png));
        assertEquals(1, dialogs.errors.size());
        assertEquals(png + ": cannot open this kind of file; drop a .bpt, .obj, .igs, .iges, .stp, .step or .json file", dialogs.errors.get(0));
        assertSame(before, app.document().scene());
        Path obj = teapotFile("pot.obj");
        app.files().openDropped(List.of(png, obj));
        assertEquals("pot.obj", app.document().name(), "the first file that can be opened");
        assertEquals(32, app.document().scene().patchCount());
    }

    @Test
    void theCommandLinesArgumentIsABuiltInOrAFile() throws Exception {
        app.files().openArgument("teapot");
        assertEquals("teapot", app.document().name());
        Path bpt = teapotFile("mine.bpt");
        app.files().openArgument(bpt.toString());
        assertEquals("mine.bpt", app.document().name());
        assertEquals(bpt, app.document().file(), "saved back in place");
        app.files().openArgument(dir.resolve("missing.bpt").toString());
        assertEquals(1, dialogs.errors.size(), "a missing file is a one-line error");
        assertEquals("mine.bpt", app.document().name(), "and keeps the model");
    }

    @Test
    void openRecentListsTheLastEightFilesNewestFirstAndForgetsOnesThatAreGone() throws Exception {
        List<Path> files = new ArrayList<>();
        for (int k = 0; k < 10; k++) {
            files.add(teapotFile("pot" + k + ".bpt"));
            app.files().open(files.get(k));
        }
        List<Path> recent = prefs.recentFiles();
        assertEquals(AppPreferences.MAX_RECENT, recent.size());
        assertEquals(files.get(9).toAbsolutePath(), recent.get(0), "newest first");
        assertEquals(files.get(2).toAbsolutePath(), recent.get(7));
        app.files().open(files.get(5));
        assertEquals(files.get(5).toAbsolutePath(), prefs.recentFiles().get(0), "once, moved to the front");
        assertEquals(AppPreferences.MAX_RECENT, prefs.recentFiles().size());
        Path saved = dir.resolve("saved.obj");
        app.files().saveTo(saved, () -> {});
        assertEquals(saved.toAbsolutePath(), prefs.recentFiles().get(0), "a saved file is recent too");
        Files.delete(files.get(8));
        app.files().openRecent(files.get(8).toAbsolutePath());
        assertEquals(1, dialogs.errors.size());
        assertTrue(dialogs.errors.get(0).contains("no such file"), dialogs.errors.get(0));
        assertTrue(!prefs.recentFiles().contains(files.get(8).toAbsolutePath()), "taken off the list");
        app.files().openRecent(files.get(3).toAbsolutePath());
        assertEquals("pot3.bpt", app.document().name());
        AppPreferences again = new AppPreferences(prefs.node());
        assertEquals(prefs.recentFiles(), again.recentFiles(), "kept in the preferences node");
    }
}
