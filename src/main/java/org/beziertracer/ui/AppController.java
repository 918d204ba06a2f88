package org.beziertracer.ui;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import javax.swing.SwingUtilities;

import org.beziertracer.intersect.Method;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;

/**
 * Owns the document (current scene, undo history, dirty flag, file), the view, the toolbox
 * settings, the picture and the render engine. Panels and actions call its one-line entry
 * points; it tells them to refresh through {@link #addListener}.
 *
 * <p><b>Threads:</b> every method runs on the event thread except {@link #reportStatus}, which
 * render threads call and which hands over to the event thread through one pending slot.
 * Mouse coordinates are in device pixels of the picture.
 */
public final class AppController {

    /** Pick radius around a control point, in device pixels at scale 1. */
    static final double PICK_RADIUS = 9;
    /** Rotation per dragged pixel at scale 1. */
    static final double RADIANS_PER_PIXEL = 0.01;

    private final EditHistory history;
    private final ToolSettings tools = new ToolSettings();
    private final PictureEngine engine;
    private final List<Runnable> listeners = new ArrayList<>();
    private final AtomicReference<RenderStatus> pendingStatus = new AtomicReference<>();
    private final AtomicBoolean statusPosted = new AtomicBoolean();
    private UserDialogs dialogs;
    private Runnable repaint = () -> {};
    private String documentName;
    private Path file;
    private OrbitView view;
    private FrameBuffer buffer;
    private double scale = 1;
    private long seed;
    private RenderStatus status;
    private String message = "";
    private ProjectedScene projected;
    // Mouse state
    private PointRef hover;
    private PointRef dragged;
    private Scene dragBefore;
    private Vec3 dragStart;
    private double grabDx, grabDy, lastX, lastY;
    private boolean rotating;

    public AppController(PictureEngine engine, UserDialogs dialogs) {
        this.engine = engine;
        this.dialogs = dialogs;
        SceneDocument doc = ModelLoader.builtIn("patch");
        this.history = new EditHistory(doc.scene());
        this.documentName = "patch";
        this.view = homeView(doc.scene());
        engine.onStatus(this::reportStatus);
        engine.onError(msg -> SwingUtilities.invokeLater(() -> dialogs.error("Rendering failed", msg)));
    }

    // ------------------------------------------------------------------ wiring and state

    public void addListener(Runnable l) { listeners.add(l); }

    public void setRepaint(Runnable r) { repaint = r; }

    public void setDialogs(UserDialogs d) { dialogs = d; }

    public UserDialogs dialogs() { return dialogs; }

    public ToolSettings tools() { return tools; }

    public EditHistory history() { return history; }

    public Scene scene() { return history.current(); }

    public OrbitView view() { return view; }

    public FrameBuffer buffer() { return buffer; }

    public PointRef hover() { return hover; }

    public PointRef dragged() { return dragged; }

    public long seed() { return seed; }

    /** Device pixels per user-space pixel (2 under GDK_SCALE=2). */
    public double scale() { return scale; }

    public RenderStatus status() { return status; }

    public String message() { return message; }

    public PictureEngine engine() { return engine; }

    public String title() {
        return (history.isDirty() ? "*" : "") + documentName + " — Bézier Tracer";
    }

    public String documentName() { return documentName; }

    private void changed() {
        projected = null;
        for (Runnable l : listeners) {
            l.run();
        }
        repaint.run();
    }

    /** The projection of the current view onto the picture. */
    public ScreenProjector projector() {
        int w = buffer == null ? 800 : buffer.width(), h = buffer == null ? 600 : buffer.height();
        return new ScreenProjector(view.camera((double) w / h), w, h);
    }

    /** The current scene's control nets on screen (cached until the next change). */
    public ProjectedScene projected() {
        if (projected == null || projected.scene() != scene()) {
            projected = new ProjectedScene(scene(), projector());
        }
        return projected;
    }

    // ------------------------------------------------------------------ rendering

    /** The panel's size in device pixels changed (or the first layout). */
    public void viewport(int width, int height, double deviceScale) {
        scale = deviceScale;
        if (buffer != null && buffer.width() == width && buffer.height() == height) {
            return;
        }
        buffer = new FrameBuffer(width, height, repaint);
        buffer.clear(0x202428);
        projected = null;
        render();
    }

    /** Starts a progressive render of the current state (coalesced; never renders here). */
    public void render() {
        projected = null;
        if (buffer == null || !tools.rayTrace) {
            repaint.run();
            return;
        }
        Scene rendered = tools.light.apply(scene());
        CameraSpec cam = view.camera((double) buffer.width() / buffer.height());
        engine.submit(new RenderRequest(rendered, cam, tools.renderSettings(buffer.width(), buffer.height()),
                tools.interactivity, buffer, tools.tessellate()));
        repaint.run();
    }

    /** Render threads: the latest status; shown on the event thread, coalesced. */
    public void reportStatus(RenderStatus s) {
        pendingStatus.set(s);
        if (statusPosted.compareAndSet(false, true)) {
            SwingUtilities.invokeLater(() -> {
                statusPosted.set(false);
                status = pendingStatus.get();
                for (Runnable l : listeners) {
                    l.run();
                }
            });
        }
    }

    // ------------------------------------------------------------------ mouse

    public void mouseMoved(double x, double y) {
        PointRef h = pickable() ? projected().pick(x, y, PICK_RADIUS * scale) : null;
        if (!java.util.Objects.equals(h, hover)) {
            hover = h;
            repaint.run();
        }
    }

    private boolean pickable() { return tools.controlPoints || !tools.rayTrace; }

    public void mousePressed(double x, double y) {
        lastX = x;
        lastY = y;
        PointRef hit = pickable() ? projected().pick(x, y, PICK_RADIUS * scale) : null;
        if (hit == null) {
            rotating = true;
            return;
        }
        dragged = hit;
        dragBefore = scene();
        var p = scene().patches().get(hit.patch());
        dragStart = new Vec3(p.get(hit.i(), hit.j(), 0), p.get(hit.i(), hit.j(), 1), p.get(hit.i(), hit.j(), 2));
        grabDx = x - projected().x(hit.patch(), hit.i(), hit.j());
        grabDy = y - projected().y(hit.patch(), hit.i(), hit.j());
        repaint.run();
    }

    public void mouseDragged(double x, double y) {
        if (dragged != null) {
            Vec3 q = projector().onScreenPlane(x - grabDx, y - grabDy, dragStart);
            history.preview(NetEdits.movePoint(scene(), dragged, q.x(), q.y(), q.z()));
            render();
        } else if (rotating) {
            view = view.rotated(x - lastX, y - lastY, RADIANS_PER_PIXEL / scale);
            render();
        }
        lastX = x;
        lastY = y;
    }

    public void mouseReleased(double x, double y) {
        if (dragged != null) {
            history.commit("Move control point", dragBefore);
            dragged = null;
            dragBefore = null;
            changed();
        }
        rotating = false;
    }

    /** Wheel: positive {@code clicks} move away from the surface. */
    public void mouseWheel(double clicks) {
        view = view.zoomed(Math.pow(1.1, clicks));
        render();
    }

    // ------------------------------------------------------------------ edits

    public void undo() {
        if (history.undo()) {
            afterEdit();
        }
    }

    public void redo() {
        if (history.redo()) {
            afterEdit();
        }
    }

    private void afterEdit() {
        hover = null;
        changed();
        render();
    }

    public void resetControlPoints() {
        Scene before = scene();
        history.apply("Reset control points", NetEdits.resetGrid(scene(), tools.gridPointsU, tools.gridPointsV));
        if (before.patchCount() != scene().patchCount()) {
            view = view.reframed(scene().controlBounds());
        }
        afterEdit();
    }

    public void randomizeControlPoints() {
        seed = (System.nanoTime() ^ (seed * 0x9E3779B97F4A7C15L)) & 0xFFFFF;
        randomizeControlPoints(seed);
    }

    /** Randomizes with a given seed (shown in the status bar). */
    public void randomizeControlPoints(long newSeed) {
        seed = newSeed;
        history.apply("Randomize control points", NetEdits.randomize(scene(), seed));
        message = "random seed " + seed;
        afterEdit();
    }

    // ------------------------------------------------------------------ view and settings

    public void resetView() {
        view = homeView(scene()).withFov(tools.fovDegrees());
        changed();
        render();
    }

    private OrbitView homeView(Scene s) {
        return s.camera().map(c -> OrbitView.fromCamera(c, s.controlBounds()))
                .orElseGet(() -> OrbitView.fit(s.controlBounds(), tools.fovDegrees()));
    }

    /** Applies a toolbox change: {@code edit} mutates the settings, then the picture follows. */
    public void setting(Runnable edit) {
        edit.run();
        if (view.fovDegrees() != tools.fovDegrees()) {
            view = view.withFov(tools.fovDegrees());
        }
        changed();
        render();
    }

    public void toggleRayTrace() { setting(() -> tools.rayTrace = !tools.rayTrace); }

    public void setMethod(Method m) { setting(() -> tools.method = m); }

    /** Tessellated mode on or off (the exact surface when off). */
    public void setTessellated(boolean on) { setting(() -> tools.tessellated = on); }

    /** K of the tessellated mode (1..{@value org.beziertracer.geometry.Tessellator#MAX_SEGMENTS}). */
    public void setTessellation(int k) {
        if (k < 1 || k > org.beziertracer.geometry.Tessellator.MAX_SEGMENTS) {
            throw new IllegalArgumentException("tessellation must be 1.." + org.beziertracer.geometry.Tessellator.MAX_SEGMENTS
                    + ", got " + k);
        }
        setting(() -> tools.tessellation = k);
    }

    // ------------------------------------------------------------------ files

    /** File → Open: asks for a file unless unsaved edits are kept. */
    public void open() {
        if (!confirmDiscard()) {
            return;
        }
        Path p = dialogs.chooseOpen();
        if (p != null) {
            load(p.getFileName().toString(), () -> ModelLoader.load(p), p);
        }
    }

    /** Opens a file without asking for it (also used by tests); keeps the old model on error. */
    public boolean open(Path p) {
        return confirmDiscard() && load(p.getFileName().toString(), () -> ModelLoader.load(p), p);
    }

    /** Models menu. */
    public boolean openBuiltIn(String name) {
        return confirmDiscard() && load(name, () -> ModelLoader.builtIn(name), null);
    }

    private boolean load(String name, java.util.function.Supplier<SceneDocument> loader, Path source) {
        SceneDocument doc;
        try {
            doc = loader.get();
        } catch (RuntimeException | OutOfMemoryError e) {
            dialogs.error("Cannot open " + name, oneLine(e));
            return false;
        }
        history.reset(doc.scene());
        documentName = name;
        file = source != null && ModelLoader.savesInPlace(source) ? source : null;
        hover = null;
        tools.apply(doc.settings());
        tools.light = LightPlacement.SCENE;
        doc.scene().camera().ifPresent(c -> tools.perspective = ToolSettings.perspectiveOf(
                Math.min(OrbitView.MAX_FOV_DEGREES, c.fovDegrees())));
        view = homeView(doc.scene()).withFov(tools.fovDegrees());
        message = "opened " + name;
        changed();
        render();
        return true;
    }

    /** True when there are no unsaved edits or the user saved or discarded them. */
    public boolean confirmDiscard() {
        if (!history.isDirty()) {
            return true;
        }
        return switch (dialogs.confirmDiscard(documentName)) {
            case SAVE -> save();
            case DISCARD -> true;
            case CANCEL -> false;
        };
    }

    /** File → Save: to the current file, or asks for one. */
    public boolean save() {
        return file == null ? saveAs() : saveTo(file);
    }

    public boolean saveAs() {
        Path p = dialogs.chooseSave("Save surface", ModelLoader.saveExtensions());
        return p != null && saveTo(p);
    }

    /** Saves the patches atomically as BPT or OBJ. */
    public boolean saveTo(Path p) {
        try {
            DocumentFiles.saveModel(p, scene());
        } catch (IOException | RuntimeException e) {
            dialogs.error("Cannot save " + p.getFileName(), oneLine(e));
            return false;
        }
        file = p;
        documentName = p.getFileName().toString();
        history.markSaved();
        message = "saved " + p;
        changed();
        return true;
    }

    public void exportPng() {
        Path p = dialogs.chooseSave("Export picture", "png");
        if (p != null) {
            exportPngTo(p);
        }
    }

    public boolean exportPngTo(Path p) {
        try {
            DocumentFiles.exportPng(p, snapshotImage());
            message = "exported " + p;
            changed();
            return true;
        } catch (IOException | RuntimeException e) {
            dialogs.error("Cannot export " + p.getFileName(), oneLine(e));
            return false;
        }
    }

    /** The picture as shown (ray-traced image, or the wireframe drawn on its background). */
    public BufferedImage snapshotImage() {
        return PictureSnapshot.of(this);
    }

    public void exportMesh() {
        Path p = dialogs.chooseSave("Export tessellated mesh", "obj");
        if (p != null) {
            try {
                var mesh = DocumentFiles.exportMesh(p, scene());
                message = "exported " + mesh.triangleCount() + " triangles to " + p;
                changed();
            } catch (IOException | RuntimeException e) {
                dialogs.error("Cannot export " + p.getFileName(), oneLine(e));
            }
        }
    }

    private static String oneLine(Throwable e) {
        return org.beziertracer.render.Failures.describe(e);
    }

    /** Window closing: true when it may close (edits saved or discarded); stops the engine. */
    public boolean quit() {
        if (!confirmDiscard()) {
            return false;
        }
        engine.close();
        return true;
    }
}
