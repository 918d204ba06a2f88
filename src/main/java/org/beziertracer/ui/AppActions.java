package org.beziertracer.ui;

import org.beziertracer.model.io.FilePaths;
import org.beziertracer.render.ShadingMode;

import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;
import java.util.function.Supplier;

import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.KeyStroke;

import java.nio.file.Path;

import org.beziertracer.app.AppModel;
import org.beziertracer.app.AppPreferences;
import org.beziertracer.app.EditCommands;
import org.beziertracer.app.EditHistory;
import org.beziertracer.app.FileCommands;
import org.beziertracer.app.Level;
import org.beziertracer.app.ModelLoader;
import org.beziertracer.app.SelectionCommands;
import org.beziertracer.app.SettingsModel;
import org.beziertracer.app.Toggle;
import org.beziertracer.intersect.Method;

/**
 * Every command of the app as a Swing {@link Action}, with its name, tooltip (which names the
 * shortcut) and keyboard accelerator — one source for the menus, the toolbox and the key
 * bindings. Each handler is a one-liner into the app layer ({@link AppModel}'s commands). Event
 * thread only.
 */
public final class AppActions {

    private static final int CTRL = InputEvent.CTRL_DOWN_MASK;
    private static final int SHIFT = InputEvent.SHIFT_DOWN_MASK;
    private static final int ALT = InputEvent.ALT_DOWN_MASK;

    private final AppModel app;
    private final Map<String, Action> byId = new LinkedHashMap<>();
    private final List<Runnable> syncs = new ArrayList<>();

    /**
     * @param picture     the picture as shown (for Export Picture)
     * @param toggleTheme switches light ↔ dark
     * @param dark        true while the dark theme is on
     * @param quit        File → Quit
     */
    public AppActions(AppModel app, Supplier<BufferedImage> picture, Runnable toggleTheme, BooleanSupplier dark,
                      Runnable quit) {
        this.app = app;
        addFileActions(app.files(), picture, quit);
        addRecentActions();
        addEditActions(app.edits());
        addSelectionActions(app.selections());
        addViewActions(app.settings());
        addRenderActions(app.settings());
        Action theme = add("dark", "Dark Theme", "Switch between the light and the dark theme", key(KeyEvent.VK_T, CTRL | SHIFT),
                toggleTheme);
        syncs.add(() -> theme.putValue(Action.SELECTED_KEY, dark.getAsBoolean()));
        for (String name : ModelLoader.BUILT_INS) {
            add("model:" + name, name, "Open the built-in " + name, null, () -> app.files().openBuiltIn(name));
        }
        app.addListener(this::refresh);
        refresh();
    }

    private void addFileActions(FileCommands f, Supplier<BufferedImage> picture, Runnable quit) {
        add("open", "Open…", "Open a BPT or OBJ model or a scene file", key(KeyEvent.VK_O, CTRL), f::open);
        add("save", "Save", "Save the edited surface (BPT or OBJ)", key(KeyEvent.VK_S, CTRL), f::save);
        add("saveAs", "Save As…", "Save the edited surface to a new BPT or OBJ file", key(KeyEvent.VK_S, CTRL | SHIFT), f::saveAs);
        add("exportPng", "Export Picture (PNG)…", "Save the current picture as a PNG image", key(KeyEvent.VK_E, CTRL),
                () -> f.export("Export picture", "png", () -> PngFiles.content(picture.get())));
        add("exportImage", "Export Image…", "Ray trace the current view off screen at a size, samples per pixel and "
                + "sampler of your choice and save it as a PNG image (progress and Cancel in the status bar)",
                key(KeyEvent.VK_E, CTRL | ALT), () -> app.export().export(PngFiles::encoder));
        add("exportMesh", "Export Mesh (OBJ)…", "Tessellate the surface into triangles and save an OBJ mesh",
                key(KeyEvent.VK_E, CTRL | SHIFT), f::exportMesh);
        add("quit", "Quit", "Close the app (asks about unsaved edits)", key(KeyEvent.VK_Q, CTRL), quit);
    }

    /** File → Open Recent: one action per place in the list, named after the file there ({@link #refresh}). */
    private void addRecentActions() {
        for (int k = 0; k < AppPreferences.MAX_RECENT; k++) {
            int place = k;
            add("recent" + k, " ", "Open file " + (k + 1) + " of File → Open Recent again", key(KeyEvent.VK_1 + k, CTRL),
                    () -> openRecent(place)).putValue(ShortcutList.NAME, "Open Recent File " + (k + 1));
        }
    }

    private void openRecent(int place) {
        java.util.List<Path> recent = app.prefs().recentFiles();
        if (place < recent.size()) {
            app.files().openRecent(recent.get(place));
        }
    }

    /** Files in File → Open Recent now. */
    public int recentCount() { return app.prefs().recentFiles().size(); }

    private void addSelectionActions(SelectionCommands c) {
        add("selectAll", "Select All", "Select every control point (welded copies together)", key(KeyEvent.VK_A, CTRL),
                c::selectAll);
        add("clearSelection", "Clear Selection", "Select no control point (also a click on empty space)",
                key(KeyEvent.VK_ESCAPE, 0), c::clear);
        String tip = " in the plane of the screen, " + SelectionCommands.NUDGE_PIXELS + " pixel (with Shift: "
                + SelectionCommands.NUDGE_PIXELS * SelectionCommands.NUDGE_SHIFT_FACTOR + ")";
        add("nudgeLeft", "Nudge Left", "Move the selected points left" + tip, key(KeyEvent.VK_LEFT, 0), () -> c.nudge(-1, 0));
        add("nudgeRight", "Nudge Right", "Move the selected points right" + tip, key(KeyEvent.VK_RIGHT, 0), () -> c.nudge(1, 0));
        add("nudgeUp", "Nudge Up", "Move the selected points up" + tip, key(KeyEvent.VK_UP, 0), () -> c.nudge(0, -1));
        add("nudgeDown", "Nudge Down", "Move the selected points down" + tip, key(KeyEvent.VK_DOWN, 0), () -> c.nudge(0, 1));
        int f = SelectionCommands.NUDGE_SHIFT_FACTOR;
        add("nudgeLeft10", "Nudge Left ×10", "Move the selected points left" + tip, key(KeyEvent.VK_LEFT, SHIFT),
                () -> c.nudge(-f, 0));
        add("nudgeRight10", "Nudge Right ×10", "Move the selected points right" + tip, key(KeyEvent.VK_RIGHT, SHIFT),
                () -> c.nudge(f, 0));
        add("nudgeUp10", "Nudge Up ×10", "Move the selected points up" + tip, key(KeyEvent.VK_UP, SHIFT), () -> c.nudge(0, -f));
        add("nudgeDown10", "Nudge Down ×10", "Move the selected points down" + tip, key(KeyEvent.VK_DOWN, SHIFT),
                () -> c.nudge(0, f));
        toggle("smoothJoins", Toggle.SMOOTH_JOINS, "Keep Tangent Continuity", "When a border point or its inner "
                + "neighbour moves, the neighbour across the border follows, so the surface stays smooth where it was",
                key(KeyEvent.VK_G, CTRL));
        toggle("curvatureJoins", Toggle.CURVATURE_JOINS, "Keep Curvature Continuity", "Also keeps the surface "
                + "curvature-continuous (G2) where it is: the second row of control points across a border follows so "
                + "each cross-border row stays C2. Needs degree 3 or more on both sides of a border (bicubic and up); "
                + "implies Keep Tangent Continuity", key(KeyEvent.VK_G, CTRL | ALT));
    }

    private void addEditActions(EditCommands e) {
        add("undo", "Undo", "Undo the last edit", key(KeyEvent.VK_Z, CTRL), e::undo);
        add("redo", "Redo", "Redo the edit just undone", key(KeyEvent.VK_Z, CTRL | SHIFT), e::redo);
        add("resetPoints", "Replace with Flat Grid", "Replace the whole model by one flat square grid of control points "
                + "of the size chosen in New grid u × v (undoable)", key(KeyEvent.VK_R, CTRL), e::replaceWithFlatGrid);
        add("revertPoints", "Revert to Original", "Put every control point back where it was when the model was opened "
                + "(undoable)", key(KeyEvent.VK_R, CTRL | ALT), e::revertToOriginal);
        add("randomize", "Randomize Control Points", "Random Z offsets within a fixed range (seed in the status bar)",
                key(KeyEvent.VK_R, CTRL | SHIFT), e::randomize);
    }

    private void addViewActions(SettingsModel s) {
        add("resetView", "Reset View", "Back to the original rotation and zoom", key(KeyEvent.VK_HOME, 0), app::resetView);
        add("zoomIn", "Zoom In", "Move towards the surface (also the mouse wheel)", key(KeyEvent.VK_EQUALS, CTRL),
                () -> app.view().zoom(-1));
        add("zoomOut", "Zoom Out", "Move away from the surface (also the mouse wheel)", key(KeyEvent.VK_MINUS, CTRL),
                () -> app.view().zoom(1));
        add("rayTrace", "Switch to Wireframe", "Switch between the ray-traced surface and the wireframe view",
                key(KeyEvent.VK_F2, 0), () -> s.toggle(Toggle.RAY_TRACE));
        toggle("polygon", Toggle.CONTROL_POLYGON, "Control Polygon", "Show the control polygon", key(KeyEvent.VK_F3, 0));
        toggle("points", Toggle.CONTROL_POINTS, "Control Points", "Show (and allow dragging) the control points",
                key(KeyEvent.VK_F4, 0));
        add("finer", "Finer Wireframe", "More wireframe subdivisions", key(KeyEvent.VK_CLOSE_BRACKET, CTRL),
                () -> s.step(Level.WIREFRAME_SUBDIVISION, 1));
        add("coarser", "Coarser Wireframe", "Fewer wireframe subdivisions", key(KeyEvent.VK_OPEN_BRACKET, CTRL),
                () -> s.step(Level.WIREFRAME_SUBDIVISION, -1));
        add("morePerspective", "More Perspective", "Stronger perspective divergence", key(KeyEvent.VK_CLOSE_BRACKET, CTRL | SHIFT),
                () -> s.step(Level.PERSPECTIVE, 10));
        add("lessPerspective", "Less Perspective", "Weaker perspective (0 = parallel rays)", key(KeyEvent.VK_OPEN_BRACKET, CTRL | SHIFT),
                () -> s.step(Level.PERSPECTIVE, -10));
        add("gridU", "More Points along u", "Grid of a new patch: one more control point along u (2..10, wraps)",
                key(KeyEvent.VK_U, CTRL | SHIFT), () -> s.cycle(Level.GRID_U));
        toggle("differenceToClipping", Toggle.DIFFERENCE_TO_CLIPPING, "Difference to Clipping", "Mark in red the "
                + "pixels where the selected method's hit differs from Bézier clipping's (another patch, a miss, or "
                + "a distance more than 1e-6 of the scene size away); the status bar counts them", key(KeyEvent.VK_D, CTRL));
        toggle("continuity", Toggle.CONTINUITY, "Continuity", "Certify every shared border G0, G1 or G2 (proved bounds "
                + "over the whole border), list them worst first and mark them on the view: green G2, yellow G1, red G0",
                key(KeyEvent.VK_G, CTRL | SHIFT));
        toggle("inspector", Toggle.INSPECTOR, "Inspector", "Show the panel with the selected points' patch, indices "
                + "and coordinates (type a value and press Enter to move them)", key(KeyEvent.VK_I, CTRL));
        add("gridV", "More Points along v", "Grid of a new patch: one more control point along v (2..10, wraps)",
                key(KeyEvent.VK_V, CTRL | SHIFT), () -> s.cycle(Level.GRID_V));
        addAnalysisActions(s);
    }

    /** The analysis views' ids, in the order of View → Analysis: {@code analysis:none}, then one a view. */
    static final java.util.List<String> ANALYSIS_IDS = java.util.stream.Stream.concat(java.util.stream.Stream.of("none"),
            java.util.Arrays.stream(ShadingMode.values()).filter(ShadingMode::isAnalysis).map(ShadingMode::label))
            .map(id -> "analysis:" + id).toList();

    /** View → Analysis: one checked item a view (and None), the one shown checked. */
    private void addAnalysisActions(SettingsModel s) {
        for (String id : ANALYSIS_IDS) {
            String label = id.substring("analysis:".length());
            ShadingMode view = label.equals("none") ? null : ShadingMode.parse(label);
            String name = view == null ? "None (Shading)" : ANALYSIS_NAMES.get(view);
            Action a = add(id, name, view == null ? "Show the shading again" : ANALYSIS_TIPS.get(view), null,
                    () -> s.setAnalysis(view));
            syncs.add(() -> a.putValue(Action.SELECTED_KEY, app.settings().current().analysis() == view));
        }
        add("analysisSettings", "Analysis Settings…", "Zebra bars, isophote step, the curvature colour scale "
                + "(automatic or fixed) and the draft's pull direction and tolerance", null, () -> {
                    org.beziertracer.render.Analysis a = app.dialogs().analysisSettings(s.current().analysisSettings());
                    if (a != null) {
                        s.setAnalysisSettings(a);
                    }
                });
    }

    private static final java.util.Map<ShadingMode, String> ANALYSIS_NAMES = java.util.Map.of(
            ShadingMode.ZEBRA, "Zebra Stripes", ShadingMode.EMAP, "Environment Map", ShadingMode.ISOPHOTES, "Isophotes",
            ShadingMode.GAUSSIAN, "Gaussian Curvature", ShadingMode.MEAN, "Mean Curvature",
            ShadingMode.MIN_RADIUS, "Minimum Radius", ShadingMode.MAX_RADIUS, "Maximum Radius",
            ShadingMode.DRAFT, "Draft Angle");

    private static final java.util.Map<ShadingMode, String> ANALYSIS_TIPS = java.util.Map.of(
            ShadingMode.ZEBRA, "Reflection of parallel light bars: a jump in the stripes is a G1 break, a kink a G2 break",
            ShadingMode.EMAP, "The built-in studio reflected in the surface, as a polished part shows it",
            ShadingMode.ISOPHOTES, "Lines of constant N·L every 10° (light from the eye)",
            ShadingMode.GAUSSIAN, "K = k1·k2 from exact second derivatives: blue saddle, red dome (scale in the status bar)",
            ShadingMode.MEAN, "H = (k1 + k2)/2 from exact second derivatives, signed against the surface's normal",
            ShadingMode.MIN_RADIUS, "The tightest bend, 1/max(|k1|, |k2|), on a logarithmic scale",
            ShadingMode.MAX_RADIUS, "The gentlest bend, 1/min(|k1|, |k2|), on a logarithmic scale (flat: yellow)",
            ShadingMode.DRAFT, "Draft against the z axis: green positive, red negative, yellow within ±1°");

    private void addRenderActions(SettingsModel s) {
        toggle("phong", Toggle.PHONG, "Phong Shading", "Phong lighting (off: flat, unlit colour)", key(KeyEvent.VK_F5, 0));
        toggle("texture", Toggle.TEXTURE, "Texture (Checker)", "Procedural checker texture in (u,v)", key(KeyEvent.VK_F6, 0));
        toggle("normals", Toggle.NORMALS, "Surface Normals (RGB)", "Colour = (n + 1) / 2 of the unit normal",
                key(KeyEvent.VK_F7, 0));
        toggle("wireframe", Toggle.WIREFRAME, "Wireframe View", "Draw the iso-curves of the projected surface over the picture",
                key(KeyEvent.VK_F8, 0));
        toggle("superSampling", Toggle.SUPER_SAMPLING, "Super-Sampling", "Several jittered samples per pixel (anti-aliasing)",
                key(KeyEvent.VK_F9, 0));
        toggle("shadows", Toggle.SHADOWS, "Shadows", "Shadow rays towards each light", key(KeyEvent.VK_F11, 0));
        toggle("reflections", Toggle.REFLECTIONS, "Reflections", "Whitted reflection and refraction rays",
                key(KeyEvent.VK_F12, 0));
        toggle("bvh", Toggle.BVH, "Sub-patch BVH", "Pre-split patches in a BVH (off: whole patches in a list); "
                + "the status bar shows the measured speed-up", key(KeyEvent.VK_B, CTRL));
        toggle("tessellated", Toggle.TESSELLATED, "Tessellated (K×K)", "Render every patch as a uniform K×K triangle mesh "
                + "with analytic vertex normals (off: the exact surface); the status bar shows \"tessellated K\"",
                key(KeyEvent.VK_K, CTRL));
        add("tessellation", "Next Tessellation K", "Cycle K of the tessellated mode (4, 8, 16, 32, 64)",
                key(KeyEvent.VK_K, CTRL | SHIFT), () -> s.cycle(Level.TESSELLATION));
        add("method", "Next Intersection Method", "Cycle " + String.join(" → ", Method.labels()),
                key(KeyEvent.VK_M, CTRL), s::cycleMethod);
        add("light", "Next Light Position", "Cycle the light position (above left of the eye, at the eye, fixed "
                + "beside the model, the scene's own)", key(KeyEvent.VK_L, CTRL), s::cycleLight);
        toggle("showLight", Toggle.SHOW_LIGHT, "Show Light", "Draw the light as a marker in the view; drag the marker "
                + "to move the light", key(KeyEvent.VK_L, CTRL | SHIFT));
        toggle("pathTraced", Toggle.PATH_TRACED, "Path Traced", "Physically based path tracing (area lights, environment, "
                + "metal and glass) that refines while nothing changes, up to the target samples or time; off: Whitted",
                key(KeyEvent.VK_P, CTRL | ALT));
        add("pathSamples", "Next Path-Traced Samples", "Cycle the samples a pixel the path-traced picture refines to "
                + "(16, 64, 256, 1024)", null, () -> s.cycle(Level.PATH_SAMPLES));
        add("pathSeconds", "Next Path-Traced Time Limit", "Cycle the time the path-traced picture may refine "
                + "(no limit, 10, 30, 60, 300 s)", null, () -> s.cycle(Level.PATH_SECONDS));
        add("brighter", "Brighter Exposure (+½ stop)", "Path traced: half a stop more exposure before the tone curve "
                + "(up to +5); the picture keeps refining", key(KeyEvent.VK_EQUALS, CTRL | ALT),
                () -> s.step(Level.EXPOSURE, Level.EXPOSURE_STEP));
        add("darker", "Darker Exposure (−½ stop)", "Path traced: half a stop less exposure before the tone curve "
                + "(down to −5); the picture keeps refining", key(KeyEvent.VK_MINUS, CTRL | ALT),
                () -> s.step(Level.EXPOSURE, -Level.EXPOSURE_STEP));
        add("resetExposure", "Reset Exposure", "Path traced: back to 0 stops of exposure (as render --exposure 0)",
                key(KeyEvent.VK_0, CTRL | ALT), () -> s.set(Level.EXPOSURE, 0));
        syncs.add(() -> {
            get("resetExposure").putValue(Action.NAME, "Reset Exposure (now "
                    + exposureText(app.settings().current().level(Level.EXPOSURE)) + ")");
            get("pathSamples").putValue(Action.NAME, "Next Path-Traced Samples (now "
                    + app.settings().current().level(Level.PATH_SAMPLES) + ")");
            int sec = app.settings().current().level(Level.PATH_SECONDS);
            get("pathSeconds").putValue(Action.NAME, "Next Path-Traced Time Limit (now "
                    + (sec == 0 ? "none" : sec + " s") + ")");
        });
        add("spp", "Next Samples per Pixel", "Cycle the super-sampling rate (4, 9, 16)", key(KeyEvent.VK_P, CTRL | SHIFT),
                () -> s.cycle(Level.SAMPLES_PER_PIXEL));
        add("moreInteractive", "More Passes per Frame", "Show the picture after more progressive passes",
                key(KeyEvent.VK_PERIOD, CTRL), () -> s.step(Level.INTERACTIVITY, 1));
        add("lessInteractive", "Fewer Passes per Frame", "Show the picture after fewer progressive passes",
                key(KeyEvent.VK_COMMA, CTRL), () -> s.step(Level.INTERACTIVITY, -1));
    }

    /** An exposure of {@code tenths} tenths of a stop as the menus show it: {@code 0 EV}, {@code +1.5 EV}, {@code −0.5 EV}. */
    static String exposureText(int tenths) {
        String v = tenths % 10 == 0 ? Integer.toString(Math.abs(tenths) / 10)
                : Math.abs(tenths) / 10 + "." + Math.abs(tenths) % 10;
        return (tenths > 0 ? "+" : tenths < 0 ? "\u2212" : "") + v + " EV";
    }

    private static KeyStroke key(int code, int modifiers) {
        return KeyStroke.getKeyStroke(code, modifiers);
    }

    /** The action with this id (see the constructor for the ids). */
    public Action get(String id) {
        Action a = byId.get(id);
        if (a == null) {
            throw new IllegalArgumentException("no action " + id);
        }
        return a;
    }

    public Map<String, Action> all() { return byId; }

    private Action add(String id, String name, String tip, KeyStroke key, Runnable run) {
        Action a = new AbstractAction(name) {
            @Override
            public void actionPerformed(ActionEvent e) {
                run.run();
            }
        };
        a.putValue(Action.SHORT_DESCRIPTION, key == null ? tip : tip + " (" + keyText(key) + ")");
        a.putValue(Action.LONG_DESCRIPTION, tip);
        a.putValue(Action.ACCELERATOR_KEY, key);
        a.putValue("id", id);
        byId.put(id, a);
        return a;
    }

    private void toggle(String id, Toggle t, String name, String tip, KeyStroke key) {
        Action a = add(id, name, tip, key, () -> app.settings().toggle(t));
        syncs.add(() -> a.putValue(Action.SELECTED_KEY, app.settings().current().on(t)));
    }

    /** Text of a shortcut as shown in tooltips, e.g. {@code Ctrl+Shift+Z}. */
    public static String keyText(KeyStroke k) {
        String mods = InputEvent.getModifiersExText(k.getModifiers());
        String key = KeyEvent.getKeyText(k.getKeyCode());
        return mods.isEmpty() ? key : mods + "+" + key;
    }

    /** Brings check marks, names and enabled states in line with the app. */
    public void refresh() {
        for (Runnable s : syncs) {
            s.run();
        }
        EditHistory h = app.document().history();
        get("rayTrace").putValue(Action.NAME, app.settings().current().on(Toggle.RAY_TRACE)
                ? "Switch to Wireframe" : "Switch to Ray Trace");
        get("undo").setEnabled(h.canUndo());
        get("revertPoints").setEnabled(app.document().scene() != app.document().original());
        get("resetPoints").putValue(Action.NAME, "Replace with Flat " + app.settings().current().level(Level.GRID_U) + "×"
                + app.settings().current().level(Level.GRID_V) + " Grid");
        get("redo").setEnabled(h.canRedo());
        get("undo").putValue(Action.NAME, h.canUndo() ? "Undo " + h.undoName() : "Undo");
        get("redo").putValue(Action.NAME, h.canRedo() ? "Redo " + h.redoName() : "Redo");
        java.util.List<Path> recent = app.prefs().recentFiles();
        for (int k = 0; k < AppPreferences.MAX_RECENT; k++) {
            Action a = get("recent" + k);
            a.setEnabled(k < recent.size());
            a.putValue(Action.NAME, k < recent.size() ? (k + 1) + "  " + FilePaths.name(recent.get(k)) : " ");
            String where = k < recent.size() ? recent.get(k).toString() : "";
            a.putValue(Action.SHORT_DESCRIPTION, "Open " + where + " again (" + keyText((KeyStroke)
                    a.getValue(Action.ACCELERATOR_KEY)) + ")");
        }
        boolean selected = !app.selection().isEmpty();
        for (String id : new String[] {"clearSelection", "nudgeLeft", "nudgeRight", "nudgeUp", "nudgeDown",
                "nudgeLeft10", "nudgeRight10", "nudgeUp10", "nudgeDown10"}) {
            get(id).setEnabled(selected);
        }
    }
}
