package org.beziertracer.app;

import java.util.List;
import java.util.function.Supplier;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The mouse in the picture (coordinates in device pixels). Hovering highlights the control point
 * under the cursor. Pressing on a point selects its handle — every welded copy, or with Alt that
 * copy only; Shift adds it to the selection, Ctrl toggles it — and dragging then moves the whole
 * selection in the plane parallel to the screen through the grabbed point, or along a world axis
 * while X, Y or Z is held ({@link #axis}): one undoable edit per drag, each step computed off the UI
 * thread. Dragging empty space turns the view (a click there clears the selection); with Shift or
 * Ctrl held it draws a rubber band whose points are added or toggled. With "Show light" on, the
 * light's marker can be dragged. The wheel zooms. Picking reads the prepared overlay (a bounded
 * number of handles), never the whole model. UI thread only.
 */
public final class PointerTool {

    /** Pick radius around a control point, in pixels at scale 1. */
    public static final double PICK_RADIUS = 9;
    /** Mouse travel, in pixels at scale 1, below which a press and release on empty space is a click. */
    public static final double CLICK_SLOP = 3;

    /** What the mouse does between press and release. */
    private interface Gesture {
        void to(double x, double y);

        void end(double x, double y);
    }

    private final AppModel app;
    private Gesture gesture;
    private Axis axis;

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
        app.pointerAt(x, y);
        app.hover().request(x, y);
    }

    /** The mouse left the picture (with dense handles, the patch it was over hides its handles again). */
    public void left() {
        app.overlay().hover(null);
        app.pointerAt(Double.NaN, Double.NaN);
    }

    /** Left button pressed at {@code (x, y)} with no modifier key held. */
    public void pressed(double x, double y) {
        pressed(x, y, Modifiers.NONE);
    }

    /** Left button pressed at {@code (x, y)} with {@code mods} held. */
    public void pressed(double x, double y, Modifiers mods) {
        gesture = lightAt(x, y);
        if (gesture != null) {
            return;
        }
        Handle hit = pick(x, y);
        Scene base = app.document().scene();
        Vec3 start = hit == null ? null : position(base, hit.ref());
        if (start != null) {
            Selection s = selectFor(hit.ref(), base, mods);
            app.select(s);
            if (s.contains(hit.ref())) {
                // A plain click (no drag) on one of several selected points selects that one alone
                Selection alone = mods.equals(Modifiers.NONE) && s.handleCount() > 1
                        ? Selection.ofHandles(List.of(app.topology().handle(hit.ref(), base))) : null;
                gesture = new MoveSelection(base, s, start, x, y, alone);
            }
        } else if (mods.selecting() && app.settings().current().pointsShown()) {
            gesture = new Band(x, y, mods.ctrl());
        } else {
            gesture = new Turn(x, y, mods);
        }
    }

    /** The selection after pressing on {@code ref} with {@code mods}. */
    private Selection selectFor(PointRef ref, Scene scene, Modifiers mods) {
        List<PointRef> handle = mods.alt() ? List.of(ref) : app.topology().handle(ref, scene);
        Selection now = app.selection();
        if (mods.shift()) {
            return now.with(handle);
        }
        if (mods.ctrl()) {
            return now.toggled(handle);
        }
        if (mods.alt()) {
            return Selection.ofHandles(List.of(handle));
        }
        // A press on a selected point keeps the selection, to drag it all
        return now.contains(ref) ? now : Selection.ofHandles(List.of(handle));
    }

    /** Where {@code ref} is in {@code scene}, or null when the scene has no such point (a stale pick). */
    static Vec3 position(Scene scene, PointRef ref) {
        if (!ref.in(scene)) {
            return null;
        }
        BezierPatch p = scene.patches().get(ref.patch());
        return new Vec3(p.get(ref.i(), ref.j(), 0), p.get(ref.i(), ref.j(), 1), p.get(ref.i(), ref.j(), 2));
    }

    public void dragged(double x, double y) {
        if (gesture != null) {
            gesture.to(x, y);
        }
    }

    public void released(double x, double y) {
        if (gesture != null) {
            Gesture g = gesture;
            gesture = null;
            g.end(x, y);
            app.motionEnded();
        }
    }

    /** True from a press until its release: a turn, a drag of points or of the light, a band. */
    public boolean inGesture() { return gesture != null; }

    /** Wheel: positive {@code clicks} move away from the model. */
    public void wheel(double clicks) {
        app.view().zoom(clicks);
    }

    /**
     * An axis key went down ({@code held}) or up: while X, Y or Z is down a drag moves the selection
     * along that world axis only. A drag in progress follows at once.
     */
    public void axis(Axis a, boolean held) {
        Axis before = axis;
        if (held) {
            axis = a;
        } else if (axis == a) {
            axis = null;
        }
        if (axis != before && gesture instanceof MoveSelection m) {
            m.step();
        }
    }

    /** The axis a drag is held to now, or null. */
    public Axis axis() { return axis; }

    /** True while control points are being dragged. */
    public boolean dragging() { return gesture instanceof MoveSelection; }

    // ------------------------------------------------------------------ gestures

    /** Drags the selection: one preview per mouse move, one undoable edit on release. */
    private final class MoveSelection implements Gesture {
        private final Scene base;
        private final long epoch;
        private final Selection selection;
        private final Vec3 start;
        private final double grabDx, grabDy;
        private final Topology topology;
        private final boolean smooth, curvature;
        private final Selection ifClicked;
        private double mouseX, mouseY;
        private Supplier<Scene> lastStep;

        /** @param ifClicked the selection after a click without a drag, or null to keep it */
        MoveSelection(Scene base, Selection selection, Vec3 start, double x, double y, Selection ifClicked) {
            this.base = base;
            this.ifClicked = ifClicked;
            this.epoch = app.document().epoch();
            this.selection = selection;
            this.start = start;
            double[] at = new double[3];
            app.view().projector().project(start.x(), start.y(), start.z(), at);
            grabDx = x - at[0];
            grabDy = y - at[1];
            topology = app.topology();
            smooth = app.settings().current().on(Toggle.SMOOTH_JOINS);
            curvature = app.settings().current().on(Toggle.CURVATURE_JOINS);
            mouseX = x;
            mouseY = y;
        }

        @Override
        public void to(double x, double y) {
            mouseX = x;
            mouseY = y;
            step();
        }

        void step() {
            ScreenProjector projector = app.view().projector();
            double px = mouseX - grabDx, py = mouseY - grabDy;
            Vec3 target = axis == null ? projector.onScreenPlane(px, py, start)
                    : projector.onLine(px, py, start, new Vec3(axis.component(0), axis.component(1), axis.component(2)));
            double[] d = {target.x() - start.x(), target.y() - start.y(), target.z() - start.z()};
            Supplier<Scene> step = () -> SelectionMove.apply(base, selection, d, topology, smooth, curvature);
            lastStep = step;
            app.editor().preview(epoch, step, () -> {});
        }

        @Override
        public void end(double x, double y) {
            String name = selection.handleCount() == 1 ? "Move control point" : "Move " + selection.handleCount() + " points";
            Runnable commit = () -> app.dragEnded(base, epoch, name);
            if (lastStep == null) {
                commit.run();
                if (ifClicked != null) {
                    app.select(ifClicked);
                }
            } else {
                app.editor().preview(epoch, lastStep, commit);
            }
        }
    }

    /** Turns the view; a press and release without travel clears the selection. */
    private final class Turn implements Gesture {
        private final double x0, y0;
        private final Modifiers mods;
        private double lastX, lastY;

        Turn(double x, double y, Modifiers mods) {
            x0 = lastX = x;
            y0 = lastY = y;
            this.mods = mods;
        }

        @Override
        public void to(double x, double y) {
            app.view().turn(lastX, lastY, x, y);
            lastX = x;
            lastY = y;
        }

        @Override
        public void end(double x, double y) {
            if (Math.hypot(x - x0, y - y0) <= CLICK_SLOP * app.view().scale() && !mods.selecting()) {
                app.select(Selection.EMPTY);
            }
        }
    }

    /** The rubber band: a rectangle on the picture; its points are found off the UI thread on release. */
    private final class Band implements Gesture {
        private final double x0, y0;
        private final boolean toggle;

        Band(double x, double y, boolean toggle) {
            x0 = x;
            y0 = y;
            this.toggle = toggle;
        }

        @Override
        public void to(double x, double y) {
            app.overlay().band(new double[] {x0, y0, x, y});
        }

        @Override
        public void end(double x, double y) {
            app.overlay().band(null);
            app.selections().band(Math.min(x0, x), Math.min(y0, y), Math.max(x0, x), Math.max(y0, y), toggle);
        }
    }

    /** The gesture of a press on the light's marker, or null when there is none under the mouse. */
    private Gesture lightAt(double x, double y) {
        Settings s = app.settings().current();
        if (!s.on(Toggle.SHOW_LIGHT) || s.light().preset() == null) {
            return null;
        }
        double r = PICK_RADIUS * app.view().scale();
        for (LightMarker m : app.overlay().snapshot().lights()) {
            if (m.draggable() && Math.hypot(m.x() - x, m.y() - y) <= r) {
                return new MoveLight(x, y);
            }
        }
        return null;
    }

    /** Drags the light in the plane parallel to the screen through it (a setting: not an undoable edit). */
    private final class MoveLight implements Gesture {
        private final double x0, y0;
        private final Vec3 start;
        private final double[] at = new double[3];

        MoveLight(double x, double y) {
            x0 = x;
            y0 = y;
            Settings s = app.settings().current();
            start = LightRig.position(s.light(), s.lightOffset(), app.view().camera(), app.view().view().framing());
            app.view().projector().project(start.x(), start.y(), start.z(), at);
        }

        @Override
        public void to(double x, double y) {
            Settings s = app.settings().current();
            Vec3 p = app.view().projector().onScreenPlane(at[0] + x - x0, at[1] + y - y0, start);
            app.settings().replace(s.withLightOffset(LightRig.offsetOf(s.light(), p, app.view().camera(),
                    app.view().view().framing())));
        }

        @Override
        public void end(double x, double y) {}
    }
}
