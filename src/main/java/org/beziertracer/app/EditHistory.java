package org.beziertracer.app;

import java.util.ArrayDeque;
import java.util.Deque;

import org.beziertracer.model.Scene;

/**
 * The edited scene with undo/redo and the dirty flag. Scenes are immutable snapshots, so an edit
 * is just the pair (before, after) and undo restores the exact previous control points. An edit
 * that re-framed the view (Replace with Flat Grid to a grid of another size) also keeps the framing
 * before and after, and undo and redo hand it back so the view follows.
 *
 * <p>A drag is <b>one</b> edit: {@link #preview} replaces the current scene on every mouse event
 * without touching the history, and {@link #commit} records the pair once, on release.
 * The document is dirty when the current scene is not the one last loaded or saved (by
 * identity), so undoing back to the saved state clears the flag. UI thread only.
 */
public final class EditHistory {

    /**
     * One undoable edit.
     *
     * @param framingBefore the view's framing before the edit, or null when the edit did not re-frame
     * @param framingAfter  the framing the edit set, or null when it did not re-frame
     */
    public record Edit(String name, Scene before, Scene after, Framing framingBefore, Framing framingAfter) {}

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
        record(new Edit(name, before, current, null, null));
    }

    /** Applies and records an edit that keeps the framing. */
    public void apply(String name, Scene after) {
        apply(name, after, null, null);
    }

    /** Applies and records an edit; non-null framings mean the edit re-framed the view. */
    public void apply(String name, Scene after, Framing framingBefore, Framing framingAfter) {
        Scene before = current;
        current = after;
        record(new Edit(name, before, after, framingBefore, framingAfter));
    }

    private void record(Edit e) {
        if (e.before() == e.after()) {
            return;
        }
        undo.push(e);
        if (undo.size() > LIMIT) {
            undo.removeLast();
        }
        redo.clear();
    }

    public boolean canUndo() { return !undo.isEmpty(); }

    public boolean canRedo() { return !redo.isEmpty(); }

    /** Name of the edit {@link #undo()} would revert, or the empty string. */
    public String undoName() { return undo.isEmpty() ? "" : undo.peek().name(); }

    /** Name of the edit {@link #redo()} would re-apply, or the empty string. */
    public String redoName() { return redo.isEmpty() ? "" : redo.peek().name(); }

    /** Reverts the last edit and returns it, or returns null when there is none. */
    public Edit undo() {
        if (undo.isEmpty()) {
            return null;
        }
        Edit e = undo.pop();
        current = e.before();
        redo.push(e);
        return e;
    }

    /** Re-applies the edit last undone and returns it, or returns null when there is none. */
    public Edit redo() {
        if (redo.isEmpty()) {
            return null;
        }
        Edit e = redo.pop();
        current = e.after();
        undo.push(e);
        return e;
    }

    /** Marks {@code scene} as the saved one (the document stays dirty if edits followed it). */
    public void markSaved(Scene scene) { saved = scene; }

    /** Marks the current scene as saved. */
    public void markSaved() { saved = current; }

    public boolean isDirty() { return current != saved; }
}
