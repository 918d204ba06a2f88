package org.beziertracer.app;

import org.beziertracer.model.Scene;

/**
 * The Edit and Surface menus: undo and redo (in constant time, on the UI thread), Reset and
 * Randomize Control Points (computed off it by {@link SceneEditor}). Undoing an edit that
 * re-framed the view puts the framing back too. UI thread only.
 */
public final class EditCommands {

    private final AppModel app;
    private final SceneEditor editor;
    private long seed;

    EditCommands(AppModel app, SceneEditor editor) {
        this.app = app;
        this.editor = editor;
    }

    public void undo() {
        EditHistory.Edit e = app.document().history().undo();
        if (e != null) {
            app.historyMoved(e.framingBefore());
        }
    }

    public void redo() {
        EditHistory.Edit e = app.document().history().redo();
        if (e != null) {
            app.historyMoved(e.framingAfter());
        }
    }

    /**
     * Surface → Reset Control Points: one flat square grid of the chosen size; when the number of
     * patches changes, the view is re-framed on the grid (keeping rotation and zoom).
     */
    public void resetControlPoints() {
        Settings s = app.settings().current();
        int u = s.level(Level.GRID_U), v = s.level(Level.GRID_V);
        editor.apply("Reset control points", before -> {
            Scene after = NetEdits.resetGrid(before, u, v);
            Framing framing = before.patchCount() != after.patchCount() ? Framing.of(after.controlBounds()) : null;
            return new SceneEditor.Outcome(after, framing);
        });
    }

    /** Surface → Randomize Control Points with a new seed (shown in the status bar). */
    public void randomize() {
        randomize((System.nanoTime() ^ (seed * 0x9E3779B97F4A7C15L)) & 0xFFFFF);
    }

    /** Randomizes with a given seed. */
    public void randomize(long newSeed) {
        seed = newSeed;
        editor.apply("Randomize control points", before -> new SceneEditor.Outcome(NetEdits.randomize(before, newSeed), null));
        app.status().message("random seed " + newSeed);
    }

    /** The last random seed. */
    public long seed() { return seed; }
}
