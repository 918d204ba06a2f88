package org.beziertracer.app;

import java.util.function.Supplier;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The mouse in the picture (coordinates in device pixels): hovering highlights the control point
 * under the cursor; pressing on one selects it and dragging moves the selection in the plane
 * parallel to the screen through the grabbed point — one undoable edit per drag, the scene of each
 * step computed off the UI thread; dragging empty space rotates the view; the wheel zooms.
 * Picking reads the prepared overlay (a bounded number of handles), never the whole model. UI
 * thread only.
 */
public final class PointerTool {

    /** Pick radius around a control point, in pixels at scale 1. */
    public static final double PICK_RADIUS = 9;

    /** A drag of the selection: where it started and the scene it started from. */
    private record Drag(Scene base, long epoch, Selection selection, Vec3 start, double grabDx, double grabDy) {}

    private final AppModel app;
    private Drag drag;
    private Supplier<Scene> lastStep;
    private boolean rotating;
    private double lastX, lastY;

    PointerTool(AppModel app) {
        this.app = app;
    }

    private Handle pick(double x, double y) {
        if (!app.settings().current().pointsShown()) {
            return null;
        }
        return app.overlay().geometry().pick(x, y, PICK_RADIUS * app.view().scale());
    }

    public void moved(double x, double y) {
        app.overlay().hover(pick(x, y));
    }

    public void pressed(double x, double y) {
        lastX = x;
        lastY = y;
        Handle hit = pick(x, y);
        Scene base = app.document().scene();
        Vec3 start = hit == null ? null : position(base, hit.ref());
        if (start == null) {
            rotating = true;
            return;
        }
        double[] at = new double[3];
        app.view().projector().project(start.x(), start.y(), start.z(), at);
        drag = new Drag(base, app.document().epoch(), Selection.of(hit.ref()), start, x - at[0], y - at[1]);
        lastStep = null;
        app.select(drag.selection());
    }

    /** Where {@code ref} is in {@code scene}, or null when the scene has no such point (a stale pick). */
    private static Vec3 position(Scene scene, PointRef ref) {
        if (ref.patch() >= scene.patchCount()) {
            return null;
        }
        BezierPatch p = scene.patches().get(ref.patch());
        if (ref.i() > p.degreeU() || ref.j() > p.degreeV()) {
            return null;
        }
        return new Vec3(p.get(ref.i(), ref.j(), 0), p.get(ref.i(), ref.j(), 1), p.get(ref.i(), ref.j(), 2));
    }

    public void dragged(double x, double y) {
        if (drag != null) {
            Drag d = drag;
            Vec3 delta = app.view().projector().onScreenPlane(x - d.grabDx(), y - d.grabDy(), d.start()).sub(d.start());
            lastStep = () -> NetEdits.moveBy(d.base(), d.selection(), delta.x(), delta.y(), delta.z());
            app.editor().preview(d.epoch(), lastStep, () -> {});
        } else if (rotating) {
            app.view().rotate(x - lastX, y - lastY);
        }
        lastX = x;
        lastY = y;
    }

    public void released(double x, double y) {
        if (drag != null) {
            Drag d = drag;
            drag = null;
            Runnable commit = () -> app.dragEnded(d.base(), d.epoch());
            if (lastStep == null) {
                commit.run();
            } else {
                app.editor().preview(d.epoch(), lastStep, commit);
            }
        }
        rotating = false;
    }

    /** Wheel: positive {@code clicks} move away from the model. */
    public void wheel(double clicks) {
        app.view().zoom(clicks);
    }

    /** True while a control point is being dragged. */
    public boolean dragging() { return drag != null; }
}
