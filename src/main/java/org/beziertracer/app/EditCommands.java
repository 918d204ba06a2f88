package org.beziertracer.app;

import org.beziertracer.model.Scene;

/**
 * The Edit and Surface menus: undo and redo (in constant time, on the UI thread), Replace with Flat
 * Grid, Revert to Original and Randomize Control Points (computed off it by {@link SceneEditor}). Undoing an edit that
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

    /** The undoable edit's name of {@link #replaceWithFlatGrid}. */
    public static final String FLAT_GRID = "Replace with flat grid";
    /** The undoable edit's name of {@link #revertToOriginal}. */
    public static final String REVERT = "Revert to original";

    /**
     * Surface → Replace with Flat Grid (formerly "Reset Control Points"): the whole model becomes
     * one flat square grid of the chosen size; when the number of patches changes, the view is
     * re-framed on the grid (keeping rotation and zoom).
     */
    public void replaceWithFlatGrid() {
        Settings s = app.settings().current();
        int u = s.level(Level.GRID_U), v = s.level(Level.GRID_V);
        editor.apply(FLAT_GRID, before -> reframed(before, NetEdits.resetGrid(before, u, v)));
    }

    /**
     * Surface → Revert to Original: the model's points (patches, weights, trims) as they were opened,
     * as one undoable edit; the view is re-framed when the number of patches changes. Nothing
     * happens (and the status bar says so) when the model is the original already.
     */
    public void revertToOriginal() {
        Scene original = app.document().original();
        if (app.document().scene() == original) {
            app.status().message(app.document().name() + " is as it was opened");
            return;
        }
        editor.apply(REVERT, before -> reframed(before, original));
    }

    private static SceneEditor.Outcome reframed(Scene before, Scene after) {
        Framing framing = before.patchCount() != after.patchCount() ? Framing.of(after.controlBounds()) : null;
        return new SceneEditor.Outcome(after, framing);
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
