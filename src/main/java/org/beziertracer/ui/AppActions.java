package org.beziertracer.ui;

import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;

import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.KeyStroke;

import org.beziertracer.intersect.Method;

/**
 * Every command of the app as a Swing {@link Action}, with its name, tooltip (which names the
 * shortcut) and keyboard accelerator — one source for the menus, the toolbox and the key
 * bindings. Each handler is a one-liner into {@link AppController}. Event thread only.
 */
public final class AppActions {

    private static final int CTRL = InputEvent.CTRL_DOWN_MASK;
    private static final int SHIFT = InputEvent.SHIFT_DOWN_MASK;

    private final AppController c;
    private final Map<String, Action> byId = new LinkedHashMap<>();
    private final List<Runnable> syncs = new ArrayList<>();

    public AppActions(AppController controller, Runnable toggleTheme, BooleanSupplier dark, Runnable quit) {
        this.c = controller;
        ToolSettings t = c.tools();
        // File
        add("open", "Open…", "Open a BPT or OBJ model or a scene file", key(KeyEvent.VK_O, CTRL), c::open);
        add("save", "Save", "Save the edited surface (BPT or OBJ)", key(KeyEvent.VK_S, CTRL), c::save);
        add("saveAs", "Save As…", "Save the edited surface to a new BPT or OBJ file", key(KeyEvent.VK_S, CTRL | SHIFT), c::saveAs);
        add("exportPng", "Export Picture (PNG)…", "Save the current picture as a PNG image", key(KeyEvent.VK_E, CTRL), c::exportPng);
        add("exportMesh", "Export Mesh (OBJ)…", "Tessellate the surface into triangles and save an OBJ mesh",
                key(KeyEvent.VK_E, CTRL | SHIFT), c::exportMesh);
        add("quit", "Quit", "Close the app (asks about unsaved edits)", key(KeyEvent.VK_Q, CTRL), quit);
        // Edit
        add("undo", "Undo", "Undo the last edit", key(KeyEvent.VK_Z, CTRL), c::undo);
        add("redo", "Redo", "Redo the edit just undone", key(KeyEvent.VK_Z, CTRL | SHIFT), c::redo);
        // Toolbox: edits and view
        add("resetPoints", "Reset Control Points", "Replace the surface by a flat square grid of the chosen size",
                key(KeyEvent.VK_R, CTRL), c::resetControlPoints);
        add("randomize", "Randomize Control Points", "Random Z offsets within a fixed range (seed in the status bar)",
                key(KeyEvent.VK_R, CTRL | SHIFT), c::randomizeControlPoints);
        add("resetView", "Reset View", "Back to the original rotation and zoom", key(KeyEvent.VK_HOME, 0), c::resetView);
        add("zoomIn", "Zoom In", "Move towards the surface (also the mouse wheel)", key(KeyEvent.VK_EQUALS, CTRL),
                () -> c.mouseWheel(-1));
        add("zoomOut", "Zoom Out", "Move away from the surface (also the mouse wheel)", key(KeyEvent.VK_MINUS, CTRL),
                () -> c.mouseWheel(1));
        add("rayTrace", "Switch to Wireframe", "Switch between the ray-traced surface and the wireframe view",
                key(KeyEvent.VK_F2, 0), c::toggleRayTrace);
        toggle("polygon", "Control Polygon", "Show the control polygon", key(KeyEvent.VK_F3, 0),
                () -> t.controlPolygon, () -> t.controlPolygon = !t.controlPolygon);
        toggle("points", "Control Points", "Show (and allow dragging) the control points", key(KeyEvent.VK_F4, 0),
                () -> t.controlPoints, () -> t.controlPoints = !t.controlPoints);
        toggle("phong", "Phong Shading", "Phong lighting (off: flat, unlit colour)", key(KeyEvent.VK_F5, 0),
                () -> t.phong, () -> t.phong = !t.phong);
        toggle("texture", "Texture (Checker)", "Procedural checker texture in (u,v)", key(KeyEvent.VK_F6, 0),
                () -> t.texture, () -> t.texture = !t.texture);
        toggle("normals", "Surface Normals (RGB)", "Colour = (n + 1) / 2 of the unit normal", key(KeyEvent.VK_F7, 0),
                () -> t.normals, () -> t.normals = !t.normals);
        toggle("wireframe", "Wireframe View", "Draw the iso-curves of the projected surface over the picture",
                key(KeyEvent.VK_F8, 0), () -> t.wireframeOverlay, () -> t.wireframeOverlay = !t.wireframeOverlay);
        toggle("superSampling", "Super-Sampling", "Several jittered samples per pixel (anti-aliasing)",
                key(KeyEvent.VK_F9, 0), () -> t.superSampling, () -> t.superSampling = !t.superSampling);
        toggle("shadows", "Shadows", "Shadow rays towards each light", key(KeyEvent.VK_F11, 0),
                () -> t.shadows, () -> t.shadows = !t.shadows);
        toggle("reflections", "Reflections", "Whitted reflection and refraction rays", key(KeyEvent.VK_F12, 0),
                () -> t.reflections, () -> t.reflections = !t.reflections);
        toggle("bvh", "Sub-patch BVH", "Pre-split patches in a BVH (off: whole patches in a list); "
                + "the status bar shows the measured speed-up", key(KeyEvent.VK_B, CTRL), () -> t.bvh, () -> t.bvh = !t.bvh);
        toggle("tessellated", "Tessellated (K×K)", "Render every patch as a uniform K×K triangle mesh with analytic "
                + "vertex normals (off: the exact surface); the status bar shows \"tessellated K\"",
                key(KeyEvent.VK_K, CTRL), () -> t.tessellated, () -> t.tessellated = !t.tessellated);
        add("tessellation", "Next Tessellation K", "Cycle K of the tessellated mode (4, 8, 16, 32, 64)",
                key(KeyEvent.VK_K, CTRL | SHIFT),
                () -> c.setTessellation(next(ToolSettings.TESSELLATION_CHOICES, t.tessellation)));
        add("method", "Next Intersection Method", "Cycle clipping → Newton → subdivision", key(KeyEvent.VK_M, CTRL),
                () -> c.setMethod(Method.values()[(t.method.ordinal() + 1) % Method.values().length]));
        add("light", "Next Light Position", "Cycle the light position", key(KeyEvent.VK_L, CTRL),
                () -> c.setting(() -> t.light = LightPlacement.values()[(t.light.ordinal() + 1) % LightPlacement.values().length]));
        add("spp", "Next Samples per Pixel", "Cycle the super-sampling rate (4, 9, 16)", key(KeyEvent.VK_P, CTRL | SHIFT),
                () -> c.setting(() -> t.samplesPerPixel = next(ToolSettings.SPP_CHOICES, t.samplesPerPixel)));
        add("finer", "Finer Wireframe", "More wireframe subdivisions", key(KeyEvent.VK_CLOSE_BRACKET, CTRL),
                () -> c.setting(() -> t.wireframeSubdivision = Math.min(64, t.wireframeSubdivision + 1)));
        add("coarser", "Coarser Wireframe", "Fewer wireframe subdivisions", key(KeyEvent.VK_OPEN_BRACKET, CTRL),
                () -> c.setting(() -> t.wireframeSubdivision = Math.max(1, t.wireframeSubdivision - 1)));
        add("moreInteractive", "More Passes per Frame", "Show the picture after more progressive passes",
                key(KeyEvent.VK_PERIOD, CTRL), () -> c.setting(() -> t.interactivity = Math.min(8, t.interactivity + 1)));
        add("lessInteractive", "Fewer Passes per Frame", "Show the picture after fewer progressive passes",
                key(KeyEvent.VK_COMMA, CTRL), () -> c.setting(() -> t.interactivity = Math.max(1, t.interactivity - 1)));
        add("morePerspective", "More Perspective", "Stronger perspective divergence", key(KeyEvent.VK_CLOSE_BRACKET, CTRL | SHIFT),
                () -> c.setting(() -> t.perspective = Math.min(100, t.perspective + 10)));
        add("lessPerspective", "Less Perspective", "Weaker perspective (0 = parallel rays)", key(KeyEvent.VK_OPEN_BRACKET, CTRL | SHIFT),
                () -> c.setting(() -> t.perspective = Math.max(0, t.perspective - 10)));
        add("gridU", "More Points along u", "Grid of a new patch: one more control point along u (2..10, wraps)",
                key(KeyEvent.VK_U, CTRL | SHIFT), () -> c.setting(() -> t.gridPointsU = t.gridPointsU >= 10 ? 2 : t.gridPointsU + 1));
        add("gridV", "More Points along v", "Grid of a new patch: one more control point along v (2..10, wraps)",
                key(KeyEvent.VK_V, CTRL | SHIFT), () -> c.setting(() -> t.gridPointsV = t.gridPointsV >= 10 ? 2 : t.gridPointsV + 1));
        toggle("dark", "Dark Theme", "Switch between the light and the dark theme", key(KeyEvent.VK_T, CTRL | SHIFT),
                dark, toggleTheme);
        for (String name : ModelLoader.BUILT_INS) {
            add("model:" + name, name, "Open the built-in " + name, null, () -> c.openBuiltIn(name));
        }
        c.addListener(this::refresh);
        refresh();
    }

    private static int next(int[] choices, int current) {
        for (int k = 0; k < choices.length; k++) {
            if (choices[k] == current) {
                return choices[(k + 1) % choices.length];
            }
        }
        return choices[0];
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
        a.putValue(Action.ACCELERATOR_KEY, key);
        a.putValue("id", id);
        byId.put(id, a);
        return a;
    }

    private void toggle(String id, String name, String tip, KeyStroke key, BooleanSupplier get, Runnable flip) {
        Action a = add(id, name, tip, key, () -> c.setting(flip));
        syncs.add(() -> a.putValue(Action.SELECTED_KEY, get.getAsBoolean()));
    }

    /** Text of a shortcut as shown in tooltips, e.g. {@code Ctrl+Shift+Z}. */
    public static String keyText(KeyStroke k) {
        String mods = InputEvent.getModifiersExText(k.getModifiers());
        String key = KeyEvent.getKeyText(k.getKeyCode());
        return mods.isEmpty() ? key : mods + "+" + key;
    }

    /** Brings check marks and enabled states in line with the controller. */
    public void refresh() {
        for (Runnable s : syncs) {
            s.run();
        }
        get("rayTrace").putValue(Action.NAME, c.tools().rayTrace ? "Switch to Wireframe" : "Switch to Ray Trace");
        get("undo").setEnabled(c.history().canUndo());
        get("redo").setEnabled(c.history().canRedo());
        get("undo").putValue(Action.NAME, c.history().canUndo() ? "Undo " + c.history().undoName() : "Undo");
        get("redo").putValue(Action.NAME, c.history().canRedo() ? "Redo " + c.history().redoName() : "Redo");
    }
}
