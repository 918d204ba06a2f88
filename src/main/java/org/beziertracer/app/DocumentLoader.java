package org.beziertracer.app;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CancellationException;

import org.beziertracer.math.Aabb;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.render.Failures;

/**
 * Opens models off the UI thread: the file is read, and the model's bounds measured, on the io
 * worker while the status bar shows the task with a Cancel button; the current model stays until
 * the new one is complete. A failed load shows its one-line message and keeps the current model;
 * a cancelled one (or one replaced by a newer Open) is dropped. UI thread only.
 */
final class DocumentLoader {

    /** A model read and measured off the UI thread. */
    record Loaded(String name, Path source, SceneDocument document, Aabb bounds) {}

    /** What the app does with a loaded model. */
    interface Target {
        void opened(Loaded loaded);

        StatusModel status();

        UserDialogs dialogs();
    }

    private final BackgroundTasks io;
    private final Target target;
    private Task running;

    DocumentLoader(BackgroundTasks io, Target target) {
        this.io = io;
        this.target = target;
    }

    /**
     * Starts loading {@code name} with {@code read}; {@code source} is the file (null for a
     * built-in). A load still in progress is cancelled.
     */
    void load(String name, Callable<SceneDocument> read, Path source) {
        if (running != null) {
            running.cancel();
        }
        Task task = new Task("opening " + name);
        running = task;
        target.status().task(task);
        io.submit(task, () -> {
            SceneDocument doc = read.call();
            return new Loaded(name, source, doc, doc.scene().bounds());
        }, loaded -> {
            ended(task);
            target.opened(loaded);
        }, e -> {
            ended(task);
            if (e instanceof CancellationException) {
                target.status().message("opening " + name + " cancelled");
            } else {
                target.dialogs().error("Cannot open " + name, Failures.describe(e));
            }
        });
    }

    private void ended(Task t) {
        if (running == t) {
            running = null;
        }
        target.status().endTask(t);
    }

    /** True while a load runs. */
    boolean loading() { return running != null; }
}
