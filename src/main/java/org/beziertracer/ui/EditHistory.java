package org.beziertracer.ui;

import java.util.ArrayDeque;
import java.util.Deque;

import org.beziertracer.model.Scene;

/**
 * The edited scene with undo/redo and the dirty flag. Scenes are immutable snapshots, so an edit
 * is just the pair (before, after) and undo restores the exact previous control points.
 *
 * <p>A drag is <b>one</b> edit: {@link #preview} replaces the current scene on every mouse event
 * without touching the history, and {@link #commit} records the pair once, on release.
 * The document is dirty when the current scene is not the one last loaded or saved (by
 * identity), so undoing back to the saved state clears the flag. Event-thread only.
 */
public final class EditHistory {

    /** One undoable edit. */
    public record Edit(String name, Scene before, Scene after) {}

    /** Most edits kept. */
    static final int LIMIT = 500;

    private final Deque<Edit> undo = new ArrayDeque<>();
    private final Deque<Edit> redo = new ArrayDeque<>();
    private Scene current;
    private Scene saved;

    public EditHistory(Scene initial) {
        reset(initial);
    }

    /** Starts over with a freshly loaded scene: empty history, not dirty. */
    public void reset(Scene scene) {
        current = scene;
        saved = scene;
        undo.clear();
        redo.clear();
    }

    public Scene current() { return current; }

    /** Shows {@code scene} without recording an edit (a drag in progress). */
    public void preview(Scene scene) {
        current = scene;
    }

    /** Records the edit {@code before → current}; nothing when the scene did not change. */
    public void commit(String name, Scene before) {
        if (before == current) {
            return;
        }
        undo.push(new Edit(name, before, current));
        if (undo.size() > LIMIT) {
            undo.removeLast();
        }
        redo.clear();
    }

    /** Applies and records an edit in one step. */
    public void apply(String name, Scene after) {
        Scene before = current;
        current = after;
        commit(name, before);
    }

    public boolean canUndo() { return !undo.isEmpty(); }

    public boolean canRedo() { return !redo.isEmpty(); }

    /** Name of the edit {@link #undo()} would revert, or null. */
    public String undoName() { return undo.isEmpty() ? null : undo.peek().name(); }

    public String redoName() { return redo.isEmpty() ? null : redo.peek().name(); }

    /** Reverts the last edit; returns false when there is none. */
    public boolean undo() {
        if (undo.isEmpty()) {
            return false;
        }
        Edit e = undo.pop();
        current = e.before();
        redo.push(e);
        return true;
    }

    public boolean redo() {
        if (redo.isEmpty()) {
            return false;
        }
        Edit e = redo.pop();
        current = e.after();
        undo.push(e);
        return true;
    }

    /** Marks the current scene as saved. */
    public void markSaved() { saved = current; }

    public boolean isDirty() { return current != saved; }
}
