package org.beziertracer.app;

import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.Executor;

import org.beziertracer.intersect.Method;
import org.beziertracer.model.io.BuiltIns;

/**
 * A seeded stream of random app commands for the soak tests, made through the same entry points
 * the window's one-line handlers call: the pointer (press on a drawn handle or on empty space,
 * drag, release, hover, wheel), undo and redo, every {@link Toggle}, the methods, the levels, the
 * light, the built-in models, Randomize, Replace with Flat Grid and Reset View. A drag is a gesture
 * spread over several steps, and other commands may land between its steps (a key pressed while
 * the mouse is down). In path-traced rounds ({@link #pathTraced(boolean)}) Render → Path Traced stays on,
 * so the commands are edits, view and setting changes made while the picture accumulates samples.
 *
 * <p>Every step draws the same count of random numbers whatever the app's state, so a seed replays
 * the same command sequence (the threads' timing is not replayed: which frames complete and where
 * a drag lands on a stale overlay still vary). UI thread only.
 */
public final class SoakActions {

    /** What a step did. */
    public enum Kind { PRESS, DRAG, RELEASE, HOVER, WHEEL, UNDO, REDO, TOGGLE, METHOD, LEVEL, LIGHT, MODEL, CANCEL_LOAD,
        RANDOMIZE, RESET_POINTS, RESET_VIEW, RESIZE, EXPOSURE }

    /** Relative frequency of each command a step starts (a gesture in progress continues more often than not). */
    private static final Map<Kind, Integer> WEIGHTS = weights();

    private final AppModel app;
    private final Random random;
    private final Runnable beforeOpen;
    private final boolean resizes;
    private final List<String> models = BuiltIns.names();
    private final Map<Kind, Integer> counts = new EnumMap<>(Kind.class);
    private boolean pressed;
    /** Path-traced rounds: Render → Path Traced stays on (a toggle of it is taken back at once). */
    private boolean pathTraced;
    private double x, y, dx, dy;
    private int stepsLeft;

    /**
     * @param beforeOpen runs before a model switch (the GUI soak marks the document saved there, so
     *                   no unsaved-edits question blocks it; the app-layer soak lets its dialogs
     *                   answer "discard")
     * @param resizes    whether to resize the picture and change its device scale (the app-layer
     *                   soak; in the GUI soak the window owns the picture's size, and that soak
     *                   resizes the window)
     */
    public SoakActions(AppModel app, long seed, Runnable beforeOpen, boolean resizes) {
        this.app = app;
        this.random = new Random(seed);
        this.beforeOpen = beforeOpen;
        this.resizes = resizes;
    }

    private static Map<Kind, Integer> weights() {
        Map<Kind, Integer> w = new EnumMap<>(Kind.class);
        w.put(Kind.PRESS, 30);
        w.put(Kind.HOVER, 3);
        w.put(Kind.WHEEL, 4);
        w.put(Kind.UNDO, 10);
        w.put(Kind.REDO, 6);
        w.put(Kind.TOGGLE, 12);
        w.put(Kind.METHOD, 4);
        w.put(Kind.LEVEL, 8);
        w.put(Kind.LIGHT, 2);
        w.put(Kind.MODEL, 2);
        w.put(Kind.CANCEL_LOAD, 1);
        w.put(Kind.RANDOMIZE, 3);
        w.put(Kind.RESET_POINTS, 1);
        w.put(Kind.RESET_VIEW, 2);
        w.put(Kind.RESIZE, 1);
        w.put(Kind.EXPOSURE, 3);
        return w;
    }

    /** One command (UI thread); returns what it was. */
    public Kind step() {
        double r = random.nextDouble(), a = random.nextDouble(), b = random.nextDouble(), c = random.nextDouble();
        Kind kind = pressed && r < 0.6 ? Kind.DRAG : pick(r);
        if (kind == Kind.PRESS && pressed) {
            kind = Kind.RELEASE;
        }
        switch (kind) {
            case PRESS -> press(a, b, c);
            case DRAG -> drag();
            case RELEASE -> release();
            case HOVER -> app.pointer().moved(a * app.view().width(), b * app.view().height());
            case WHEEL -> app.pointer().wheel(a < 0.5 ? -1 - (int) (3 * b) : 1 + (int) (3 * b));
            case UNDO -> app.edits().undo();
            case REDO -> app.edits().redo();
            case TOGGLE -> toggle(a, b);
            case METHOD -> method(a, b);
            case LEVEL -> level(a, b);
            case LIGHT -> app.settings().cycleLight();
            case MODEL -> {
                beforeOpen.run();
                app.files().openBuiltIn(models.get((int) (a * models.size())));
            }
            case CANCEL_LOAD -> {
                if (app.status().task() != null) {
                    app.status().task().cancel();
                }
            }
            case RANDOMIZE -> app.edits().randomize((long) (a * 1_000_000));
            case RESET_POINTS -> app.edits().replaceWithFlatGrid();
            case RESET_VIEW -> app.resetView();
            case EXPOSURE -> exposure(a, b);
            case RESIZE -> {
                if (resizes) {
                    app.view().resize(120 + (int) (80 * a), 90 + (int) (60 * b), c < 0.8 ? 1 : 2);
                }
            }
        }
        counts.merge(kind, 1, Integer::sum);
        return kind;
    }

    private static Kind pick(double r) {
        int total = WEIGHTS.values().stream().mapToInt(Integer::intValue).sum();
        double at = r * total;
        for (Map.Entry<Kind, Integer> e : WEIGHTS.entrySet()) {
            at -= e.getValue();
            if (at < 0) {
                return e.getKey();
            }
        }
        return Kind.RESET_VIEW;
    }

    /** Presses on a drawn handle (most often) or anywhere (empty space rotates); the drag's direction and length. */
    private void press(double a, double b, double c) {
        OverlayGeometry g = app.overlay().geometry();
        if (a < 0.8 && g.handleCount() > 0) {
            int k = (int) (b * g.handleCount());
            x = g.handleX(k);
            y = g.handleY(k);
        } else {
            x = b * app.view().width();
            y = c * app.view().height();
        }
        double angle = 2 * Math.PI * c, length = 4 + 30 * a;
        dx = length * Math.cos(angle);
        dy = length * Math.sin(angle);
        stepsLeft = 1 + (int) (8 * b);
        pressed = true;
        app.pointer().pressed(x, y);
    }

    private void drag() {
        x += dx;
        y += dy;
        app.pointer().dragged(x, y);
        if (--stepsLeft == 0) {
            release();
        }
    }

    private void release() {
        pressed = false;
        app.pointer().released(x, y);
    }

    /**
     * A random toggle; while the ray trace or the control points are off, often that one back on
     * (the picture is what the soak checks, and hidden points cannot be dragged).
     */
    private void toggle(double a, double b) {
        Toggle t = Toggle.values()[(int) (a * Toggle.values().length)];
        Settings now = app.settings().current();
        if (!now.on(Toggle.RAY_TRACE) && b < 0.5) {
            t = Toggle.RAY_TRACE;
        } else if (!now.on(Toggle.CONTROL_POINTS) && b >= 0.5) {
            t = Toggle.CONTROL_POINTS;
        }
        if (t == Toggle.PATH_TRACED && app.settings().current().level(Level.PATH_SAMPLES) > SOAK_PATH_SAMPLES) {
            app.settings().set(Level.PATH_SAMPLES, SOAK_PATH_SAMPLES); // path traced, the picture goes idle soon
        }
        app.settings().toggle(t);
        if (pathTraced && !app.settings().current().on(Toggle.PATH_TRACED)) {
            app.settings().set(Toggle.PATH_TRACED, true); // a path-traced round stays path traced
        }
    }

    /** Render → Brighter / Darker Exposure (half a stop, within ±5), now and then Reset, or a slider's value. */
    private void exposure(double a, double b) {
        SettingsModel s = app.settings();
        if (a < 0.4) {
            s.step(Level.EXPOSURE, Level.EXPOSURE_STEP);
        } else if (a < 0.8) {
            s.step(Level.EXPOSURE, -Level.EXPOSURE_STEP);
        } else if (a < 0.9) {
            s.set(Level.EXPOSURE, 0);
        } else {
            s.set(Level.EXPOSURE, Level.EXPOSURE.min() + (int) (b * (Level.EXPOSURE.max() - Level.EXPOSURE.min() + 1)));
        }
    }

    /**
     * From now on Render → Path Traced is on (UI thread): turned on here, with
     * {@value #SOAK_PATH_ROUND_SAMPLES} samples a pixel so that commands land while the picture refines,
     * and kept on by the toggles; or, with false, left to the random toggles again.
     */
    public void pathTraced(boolean on) {
        pathTraced = on;
        if (on) {
            app.settings().set(Level.PATH_SAMPLES, SOAK_PATH_ROUND_SAMPLES);
            app.settings().set(Toggle.PATH_TRACED, true);
        }
    }

    /** Samples a pixel a path-traced picture of the soak refines to (the default 256 would keep it busy). */
    static final int SOAK_PATH_SAMPLES = 4;
    /** Samples a pixel of the path-traced rounds ({@link #pathTraced(boolean)}): enough passes for edits to land between. */
    static final int SOAK_PATH_ROUND_SAMPLES = 16;

    private void method(double a, double b) {
        if (b < 0.3) {
            app.settings().cycleMethod();
        } else {
            app.settings().set(Method.values()[(int) (a * Method.values().length)]);
        }
    }

    private void level(double a, double b) {
        SettingsModel s = app.settings();
        int up = b < 0.5 ? 1 : -1;
        switch ((int) (a * 7)) {
            case 0 -> s.cycle(Level.SAMPLES_PER_PIXEL);
            case 1 -> s.cycle(Level.TESSELLATION);
            case 2 -> s.step(Level.INTERACTIVITY, up);
            case 3 -> s.step(Level.PERSPECTIVE, 10 * up);
            case 4 -> s.step(Level.WIREFRAME_SUBDIVISION, 4 * up);
            case 5 -> s.cycle(Level.GRID_U);
            default -> s.cycle(Level.GRID_V);
        }
    }

    /**
     * Ends a drag in progress and turns the ray trace on, so the final picture is a rendered one
     * (UI thread). The tessellated mode with the BVH off gets its BVH back: that state tests every
     * triangle of the model for every ray (a teapot room at K = 64 is 262 144 triangles), and one
     * frame takes minutes; the run goes through it, but the final frame and its fresh twin would
     * not fit in the soak's time.
     */
    public void finish() {
        if (pressed) {
            release();
        }
        if (!app.settings().current().on(Toggle.RAY_TRACE)) {
            app.settings().set(Toggle.RAY_TRACE, true);
        }
        if (app.settings().current().on(Toggle.TESSELLATED) && !app.settings().current().on(Toggle.BVH)) {
            app.settings().set(Toggle.BVH, true);
        }
        if (pathTraced && !app.settings().current().on(Toggle.PATH_TRACED)) {
            app.settings().set(Toggle.PATH_TRACED, true);
        }
    }

    /**
     * Issues {@code count} commands from the calling thread onto the UI thread {@code ui}, one task
     * each (as events arrive), in bursts of 1 to 30 without waiting for the app. Between bursts
     * ({@code pace} draws them): a quarter of the time no pause, mostly a few milliseconds (a scene
     * snapshot gets prepared, a coarse pass may show), sometimes tens of milliseconds, now and then
     * long enough for whole frames to complete.
     */
    public void issue(Executor ui, int count, Random pace) throws InterruptedException {
        for (int issued = 0; issued < count; ) {
            int burst = Math.min(count - issued, 1 + pace.nextInt(30));
            for (int k = 0; k < burst; k++) {
                ui.execute(this::step);
            }
            issued += burst;
            int p = pace.nextInt(100);
            if (p >= 98) {
                Thread.sleep(100 + pace.nextInt(200));
            } else if (p >= 85) {
                Thread.sleep(20 + pace.nextInt(40));
            } else if (p >= 25) {
                Thread.sleep(1 + pace.nextInt(15));
            }
        }
    }

    /** Commands so far. */
    public int total() {
        return counts.values().stream().mapToInt(Integer::intValue).sum();
    }

    /** Commands so far, by kind, e.g. {@code PRESS=310 DRAG=901 …}. */
    public String summary() {
        StringBuilder sb = new StringBuilder();
        counts.forEach((k, n) -> sb.append(sb.length() == 0 ? "" : " ").append(k).append('=').append(n));
        return sb.toString();
    }
}
