package org.beziertracer.app;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.Scene;

/**
 * The Edit menu's selection commands: Select All, Clear Selection (Escape), the rubber band's
 * result, and nudging the selection with the arrow keys — {@value #NUDGE_PIXELS} pixel in the
 * plane of the screen, ten with Shift, each nudge one undoable edit. What reads the whole model
 * (finding the points in a rectangle) runs off the UI thread. UI thread only.
 */
public final class SelectionCommands {

    /** A nudge moves the selection by this many pixels on the screen (at scale 1). */
    public static final int NUDGE_PIXELS = 1;
    /** Shift multiplies a nudge by this. */
    public static final int NUDGE_SHIFT_FACTOR = 10;

    private final AppModel app;
    private final BackgroundTasks tasks;

    SelectionCommands(AppModel app, BackgroundTasks tasks) {
        this.app = app;
        this.tasks = tasks;
    }

    /** Edit → Select All: every control point (up to {@link Selection#MAX_POINTS}). */
    public void selectAll() {
        if (!app.settings().current().pointsShown()) {
            return;
        }
        Scene scene = app.document().scene();
        Topology topology = app.topology();
        long epoch = app.document().epoch();
        tasks.submit("selecting", () -> PointsInRectangle.find(scene, null, 0, 0, 0, 0, topology), handles -> {
            if (app.document().epoch() == epoch) {
                app.select(Selection.ofHandles(handles));
            }
        }, e -> app.failed("Select All failed", e));
    }

    /** Edit → Clear Selection (Escape). */
    public void clear() {
        app.select(Selection.EMPTY);
    }

    /** The rubber band {@code [x0, x1] × [y0, y1]} (picture pixels) was let go: its points are added, or toggled. */
    void band(double x0, double y0, double x1, double y1, boolean toggle) {
        Scene scene = app.document().scene();
        ScreenProjector projector = app.view().projector();
        Topology topology = app.topology();
        long epoch = app.document().epoch();
        tasks.submit("selecting", () -> PointsInRectangle.find(scene, projector, x0, y0, x1, y1, topology), handles -> {
            if (app.document().epoch() == epoch) {
                app.select(app.selection().combined(handles, toggle));
            }
        }, e -> app.failed("Selecting failed", e));
    }

    /**
     * Moves the selection by {@code (dx, dy)} nudges on the screen (right and down positive), in the
     * plane parallel to the screen through the first selected point: one undoable edit.
     */
    public void nudge(int dx, int dy) {
        Selection selection = app.selection();
        Scene scene = app.document().scene();
        Vec3 p = selection.isEmpty() ? null : PointerTool.position(scene, selection.primary());
        if (p == null) {
            app.status().message("select control points to nudge them");
            return;
        }
        ScreenProjector projector = app.view().projector();
        double[] at = new double[3];
        if (!projector.project(p.x(), p.y(), p.z(), at)) {
            return;
        }
        double step = NUDGE_PIXELS * app.view().scale();
        Vec3 to = projector.onScreenPlane(at[0] + dx * step, at[1] + dy * step, p);
        move("Nudge", selection, new double[] {to.x() - p.x(), to.y() - p.y(), to.z() - p.z()});
    }

    /** Moves {@code selection} by {@code d} as one undoable edit called {@code name} (off the UI thread). */
    void move(String name, Selection selection, double[] d) {
        Topology topology = app.topology();
        boolean smooth = app.settings().current().on(Toggle.SMOOTH_JOINS);
        boolean curvature = app.settings().current().on(Toggle.CURVATURE_JOINS);
        app.editor().apply(name, base -> new SceneEditor.Outcome(
                SelectionMove.apply(base, selection, d, topology, smooth, curvature), null));
    }
}
