package org.beziertracer.app;

import java.nio.file.Path;

import org.beziertracer.model.Scene;

/**
 * The open model: its scene with the undo history and dirty flag, its name and the file it is
 * saved to (none for a built-in model or a scene file, whose planes, spheres and lights a model
 * file cannot hold).
 *
 * <p>The <b>epoch</b> counts every change that is not a drag preview (open, edit, undo, redo);
 * background edits carry the epoch they started from and are dropped when it moved meanwhile, so a
 * late result never lands on another model or undoes an undo. UI thread only.
 */
public final class Document {

    private final EditHistory history;
    private Scene original;
    private String name;
    private Path file;
    private long epoch;

    Document(Scene scene, String name) {
        this.history = new EditHistory(scene);
        this.original = scene;
        this.name = name;
    }

    /** The scene as it was opened, before any edit (Surface → Revert to Original goes back to it). */
    public Scene original() { return original; }

    public Scene scene() { return history.current(); }

    public EditHistory history() { return history; }

    /** The name shown in the title: a file name or a built-in name. */
    public String name() { return name; }

    /** Where Save writes without asking, or null. */
    public Path file() { return file; }

    public boolean isDirty() { return history.isDirty(); }

    /** Window title: a star for unsaved edits, the name, the app. */
    public String title() {
        return (isDirty() ? "*" : "") + name + " — Bézier Tracer";
    }

    public long epoch() { return epoch; }

    /** Counts a change (see the class comment). */
    void bump() { epoch++; }

    /** Starts over on a freshly opened scene. {@code source} is the file it came from, or null. */
    void replace(Scene scene, String newName, Path source) {
        history.reset(scene);
        original = scene;
        name = newName;
        file = source != null && ModelLoader.savesInPlace(source) ? source : null;
        bump();
    }

    /** {@code scene} was written to {@code target}. */
    void saved(Scene scene, Path target) {
        history.markSaved(scene);
        file = target;
        name = org.beziertracer.model.io.FilePaths.name(target);
    }
}
