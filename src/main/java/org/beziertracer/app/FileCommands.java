package org.beziertracer.app;

import java.io.InterruptedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;
import java.util.function.Consumer;
import java.util.function.Supplier;

import org.beziertracer.model.Scene;
import org.beziertracer.model.io.AtomicFiles;
import org.beziertracer.model.io.BuiltIns;
import org.beziertracer.model.io.FilePaths;
import org.beziertracer.model.io.FileFormats;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.WriteProgress;
import org.beziertracer.render.Failures;

/**
 * The File and Models menus: open (asking about unsaved edits first) — from the file dialog, Open
 * Recent, a file dropped on the window or the command line — save, save as, export, quit. Files
 * are read and written off the UI thread ({@link DocumentLoader}, {@link BackgroundTasks}); what
 * follows a save (closing, opening another model) waits for it. Every failure is a one-line
 * dialog. Files opened or saved go first in the recent files ({@link AppPreferences}). UI thread
 * only.
 */
public final class FileCommands {

    private final AppModel app;
    private final BackgroundTasks io;
    private final DocumentLoader loader;

    FileCommands(AppModel app, BackgroundTasks io, DocumentLoader loader) {
        this.app = app;
        this.io = io;
        this.loader = loader;
    }

    /** File → Open: asks for a file (after the unsaved-edits question) and opens it. */
    public void open() {
        confirmDiscard(() -> {
            Path p = app.dialogs().chooseOpen();
            if (p != null) {
                load(p);
            }
        });
    }

    /** Opens {@code p} without asking for it (after the unsaved-edits question). */
    public void open(Path p) {
        confirmDiscard(() -> load(p));
    }

    private void load(Path p) {
        loader.load(name(p), () -> ModelLoader.load(p), p);
    }

    /**
     * Opens what {@code read} returns, called {@code name} (after the unsaved-edits question): a
     * model made in memory, a file dropped on the window. {@code read} runs off the UI thread and
     * is interrupted when the user cancels.
     */
    public void open(String name, Callable<SceneDocument> read) {
        confirmDiscard(() -> loader.load(name, read, null));
    }

    /** File → Open Recent: {@code p} again; a file that is gone is taken off the list with a one-line error. */
    public void openRecent(Path p) {
        if (!Files.isRegularFile(p)) {
            app.prefs().removeRecent(p);
            app.notifyListeners();
            app.dialogs().error("Cannot open " + name(p), p + ": no such file (taken off the recent files)");
            return;
        }
        open(p);
    }

    /**
     * Files dropped on the window: opens the first one the format registry can read
     * ({@link FileFormats}); when none, says which kinds can be opened.
     */
    public void openDropped(List<Path> files) {
        Optional<Path> first = files.stream().filter(f -> FileFormats.find(f.toString()).isPresent()).findFirst();
        if (first.isPresent()) {
            open(first.get());
        } else if (!files.isEmpty()) {
            Path f = files.get(0);
            app.dialogs().error("Cannot open " + name(f), f + ": cannot open this kind of file; drop a "
                    + FileFormats.extensionList(ModelLoader.OPEN_FORMATS) + " file");
        }
    }

    /**
     * What the command line named ({@code java -jar beziertracer.jar FILE_OR_BUILTIN}): a built-in
     * model or scene by name, else a file.
     */
    public void openArgument(String arg) {
        if (BuiltIns.find(arg).isPresent()) {
            openBuiltIn(arg);
        } else {
            Optional<Path> p = FilePaths.find(arg);
            if (p.isPresent()) {
                open(p.get());
            } else {
                app.dialogs().error("Cannot open " + arg, arg + ": " + FilePaths.invalidName());
            }
        }
    }

    private static String name(Path p) {
        return FilePaths.name(p);
    }

    /** Models menu: a built-in model or scene. */
    public void openBuiltIn(String name) {
        confirmDiscard(() -> loader.load(name, () -> ModelLoader.builtIn(name), null));
    }

    /** File → Save: to the current file, or asks for one. */
    public void save() { save(() -> {}); }

    /** File → Save As. */
    public void saveAs() { saveAs(() -> {}); }

    private void save(Runnable then) {
        Path file = app.document().file();
        if (file == null) {
            saveAs(then);
        } else {
            saveTo(file, then);
        }
    }

    private void saveAs(Runnable then) {
        Path p = app.dialogs().chooseSave("Save surface", ModelLoader.saveExtensions());
        if (p != null) {
            saveTo(p, then);
        }
    }

    /**
     * Saves the patches atomically in the format the extension names, then runs {@code then}. The
     * status bar shows the patches written of all with Cancel; a cancelled save leaves the old file
     * as it was (and no temporary file).
     */
    public void saveTo(Path p, Runnable then) {
        Scene scene = app.document().scene();
        writeCounting("saving", "Cannot save ", p, progress -> {
            DocumentFiles.saveModel(p, scene, progress);
            return p;
        }, saved -> {
            app.document().saved(scene, p);
            app.prefs().addRecent(p);
            app.status().message("saved " + FilePaths.text(p));
            then.run();
        });
    }

    /** File → Export Mesh: asks for a file, then {@link #exportMeshTo}. */
    public void exportMesh() {
        Path p = app.dialogs().chooseSave("Export tessellated mesh", "obj");
        if (p != null) {
            exportMeshTo(p);
        }
    }

    /**
     * Tessellates the surface and writes a triangle OBJ atomically, as a save: the status bar shows
     * the patches written of all with Cancel, and a cancelled export leaves the old file as it was.
     */
    public void exportMeshTo(Path p) {
        Scene scene = app.document().scene();
        writeCounting("exporting", "Cannot export ", p, progress -> DocumentFiles.exportMesh(p, scene, progress),
                triangles -> app.status().message("exported " + triangles + " triangles to " + FilePaths.text(p)));
    }

    /** A file write that reports the patches written ({@link WriteProgress}) and stops when cancelled. */
    @FunctionalInterface
    private interface CountedWrite<T> {
        T write(WriteProgress progress) throws Exception;
    }

    /**
     * Runs {@code write} off the UI thread as a task labelled {@code verb name}: the status bar
     * shows {@code verb name: N / M patches} with Cancel, and Cancel stops the write at its next
     * report (the atomic write then leaves the old file and no temporary file). Afterwards, on the
     * UI thread: {@code done} with the result; a cancel says so in the status bar; a failure is a
     * one-line dialog titled {@code failTitle name}.
     */
    private <T> void writeCounting(String verb, String failTitle, Path p, CountedWrite<T> write, Consumer<T> done) {
        Task task = new Task(verb + " " + name(p));
        app.status().task(task);
        io.submit(task, () -> write.write((written, total) -> {
            task.progress(written, total, "patches");
            if (Thread.currentThread().isInterrupted()) {
                throw new InterruptedIOException(verb + " " + name(p) + " was cancelled");
            }
        }), result -> {
            app.status().endTask(task);
            done.accept(result);
        }, e -> {
            app.status().endTask(task);
            if (e instanceof CancellationException) {
                app.status().message(verb + " " + name(p) + " cancelled (the file is as it was)");
            }
            failed(failTitle + name(p), e);
        });
    }

    /**
     * Asks where to write a {@code extension} file, then writes what {@code content} makes (made
     * on this thread, written atomically off it); e.g. the picture as PNG.
     */
    public void export(String title, String extension, Supplier<AtomicFiles.BinaryContent> content) {
        Path p = app.dialogs().chooseSave(title, extension);
        if (p != null) {
            exportTo(p, content.get());
        }
    }

    /** Writes {@code content} to {@code p} atomically, off this thread. */
    public void exportTo(Path p, AtomicFiles.BinaryContent content) {
        io.submit("exporting " + name(p), () -> {
            AtomicFiles.writeBytes(p, content);
            return p;
        }, done -> app.status().message("exported " + FilePaths.text(p)), e -> failed("Cannot export " + name(p), e));
    }

    private void failed(String title, Throwable e) {
        if (!(e instanceof CancellationException)) {
            app.dialogs().error(title, Failures.describe(e));
        }
    }

    /** Runs {@code proceed} when there are no unsaved edits or the user saved or discarded them. */
    public void confirmDiscard(Runnable proceed) {
        if (!app.document().isDirty()) {
            proceed.run();
            return;
        }
        switch (app.dialogs().confirmDiscard(app.document().name())) {
            case SAVE -> save(proceed);
            case DISCARD -> proceed.run();
            case CANCEL -> { }
        }
    }

    /** Window closing: after the unsaved-edits question, stops the app's threads and runs {@code close}. */
    public void quit(Runnable close) {
        confirmDiscard(() -> {
            app.close();
            close.run();
        });
    }
}
