package org.beziertracer.app;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.render.Failures;

/**
 * The app without its windows: it owns the open {@link Document}, the {@link SettingsModel
 * settings}, the {@link ViewModel view} and its picture, the {@link OverlayModel overlay}, the
 * {@link StatusModel status}, the selection, the model's {@link Topology} and the render engine,
 * and offers the commands as small classes ({@link FileCommands}, {@link EditCommands},
 * {@link SelectionCommands}, {@link Inspector}, {@link ImageExport}, {@link PointerTool}). A window
 * calls those one-liners and repaints from the immutable snapshots; it is told of changes through
 * {@link #addListener}.
 *
 * <p><b>Threads:</b> all state belongs to the UI thread of {@link AppThreads}; whatever grows with
 * the model (reading files, copying the patch list for an edit, projecting control points, finding
 * welded points, building the render snapshot) runs on the workers and the render engine's threads
 * and comes back through the UI executor. Imports nothing from AWT or Swing.
 */
public final class AppModel {

    /** Most selected points drawn highlighted one by one (more: the drawn handles that are selected). */
    static final int SELECTED_BUDGET = OverlayBuilder.HANDLE_BUDGET;

    private final AppThreads threads;
    private final PictureEngine engine;
    private final HoverValue hover;
    private final ContinuityModel continuity;
    private final UserDialogs dialogs;
    private final AppPreferences prefs;
    private final List<Runnable> listeners = new ArrayList<>();
    private final Document document;
    private final SettingsModel settings;
    private final ViewModel view;
    private final StatusModel status;
    private final OverlayModel overlay;
    private final TopologyModel topology;
    private final DifferenceModel difference;
    private final SceneEditor editor;
    private final BackgroundTasks viewTasks;
    private final BackgroundTasks io;
    private final EditCommands edits;
    private final FileCommands files;
    private final SelectionCommands selections;
    private final Inspector inspector;
    private final ImageExport export;
    private final PointerTool pointer;
    private Selection selection = Selection.EMPTY;

    /**
     * @param prefs where recent files (and the desktop's theme) are remembered; tests pass a node of
     *              their own
     */
    public AppModel(PictureEngine engine, UserDialogs dialogs, AppThreads threads, AppPreferences prefs) {
        this.threads = threads;
        this.engine = engine;
        this.dialogs = dialogs;
        this.prefs = prefs;
        SceneDocument start = ModelLoader.builtIn("patch");
        document = new Document(start.scene(), "patch");
        settings = new SettingsModel(s -> settingsChanged());
        settings.replaceQuietly(settings.current().with(Level.EXPOSURE, prefs.exposureTenths()));
        exposureSent = settings.current().exposure();
        view = new ViewModel(ViewModel.home(start.scene(), start.scene().bounds(), settings.current().fovDegrees()),
                this::viewMoved, this::viewMoved);
        status = new StatusModel(threads.ui(), this::notifyListeners);
        overlay = new OverlayModel(threads.overlay(), threads.ui(), view::repaint, this::notifyListeners,
                e -> threads.ui().execute(() -> failed("Drawing the control points failed", e)));
        overlay.onBuilt(this::selectionBuilt);
        topology = new TopologyModel(threads.topology(), threads.ui(), e -> threads.ui().execute(() ->
                status.message("welded points not found: " + Failures.describe(e))));
        topology.onDelivered(this::topologyLanded);
        difference = new DifferenceModel(threads.difference(), threads.ui(), () -> {
            view.repaint();
            notifyListeners();
        }, e -> failed("Difference to clipping failed", e));
        continuity = new ContinuityModel(threads.difference(), threads.ui(), status, () -> {
            view.repaint();
            notifyListeners();
        }, e -> failed("Continuity analysis failed", e));
        hover = new HoverValue(threads.difference(), threads.ui(), engine::lastJob, this::notifyListeners);
        editor = new SceneEditor(threads.edits(), threads.ui(), new EditorTarget());
        viewTasks = new BackgroundTasks(threads.edits(), threads.ui());
        edits = new EditCommands(this, editor);
        io = new BackgroundTasks(threads.io(), threads.ui());
        files = new FileCommands(this, io, new DocumentLoader(io, new LoaderTarget()));
        selections = new SelectionCommands(this, viewTasks);
        inspector = new Inspector(this);
        export = new ImageExport(this, io);
        pointer = new PointerTool(this);
        engine.onStatus(status::report);
        engine.onError(msg -> threads.ui().execute(() -> dialogs.error("Rendering failed", msg)));
        requestOverlay(false);
        topology.request(document.scene(), smooth());
    }

    // ------------------------------------------------------------------ parts

    public Document document() { return document; }

    public SettingsModel settings() { return settings; }

    public ViewModel view() { return view; }

    public OverlayModel overlay() { return overlay; }

    public StatusModel status() { return status; }

    /** View → Difference to clipping: the mask for the current picture, kept up to date off the UI thread. */
    public DifferenceModel difference() { return difference; }

    /** View → Continuity: the certified borders of the current model. */
    public ContinuityModel continuity() { return continuity; }

    /** New continuity tolerances (null: the model's defaults), analysed again at once when shown. */
    public void continuityTolerances(ContinuityAnalysis.Tolerances t) {
        continuity.tolerances(t);
        checkContinuity();
    }

    /** The analysis view's value under the mouse (status bar). */
    public HoverValue hover() { return hover; }

    public FileCommands files() { return files; }

    public EditCommands edits() { return edits; }

    public SelectionCommands selections() { return selections; }

    public Inspector inspector() { return inspector; }

    public ImageExport export() { return export; }

    public PointerTool pointer() { return pointer; }

    public AppPreferences prefs() { return prefs; }

    /** The selected control points. */
    public Selection selection() { return selection; }

    public UserDialogs dialogs() { return dialogs; }

    /** Runs {@code l} on the UI thread after every change that widgets show. */
    public void addListener(Runnable l) { listeners.add(l); }

    /** View → Reset View: back to the home view of the current model (measured off the UI thread). */
    public void resetView() {
        Scene s = document.scene();
        double fov = settings.current().fovDegrees();
        viewTasks.submit("framing", () -> ViewModel.home(s, s.bounds(), fov), home -> {
            view.replace(home);
            viewMoved();
            notifyListeners();
        }, e -> failed("Reset View failed", e));
    }

    /** True while anything is pending: an edit, a load or save, an overlay, welds, a render (tests wait on this). */
    public boolean busy() {
        return engine.busy() || hover.busy() || continuity.busy() || overlay.busy() || editor.busy() || viewTasks.busy() || io.busy() || status.busy()
                || topology.busy()
                || difference.busy();
    }

    /** The names of the parts {@link #busy()} waits for that are busy now (for diagnostics: a soak that never goes idle). */
    public String busyParts() {
        String[] names = {"engine", "hover", "continuity", "overlay", "editor", "viewTasks", "io", "status", "topology",
            "difference"};
        boolean[] busy = {engine.busy(), hover.busy(), continuity.busy(), overlay.busy(), editor.busy(), viewTasks.busy(),
            io.busy(), status.busy(), topology.busy(), difference.busy()};
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < names.length; k++) {
            if (busy[k]) {
                sb.append(sb.length() == 0 ? "" : ", ").append(names[k]);
            }
        }
        return sb.length() == 0 ? "none" : sb.toString();
    }

    /** Stops rendering and the workers. */
    public void close() {
        engine.close();
        threads.close();
    }

    // ------------------------------------------------------------------ reactions

    SceneEditor editor() { return editor; }

    /** The model's welds and joins as known now (see {@link Topology} on using an older one). */
    Topology topology() { return topology.current(); }

    void notifyListeners() {
        for (Runnable l : listeners) {
            l.run();
        }
    }

    void failed(String title, Throwable e) {
        if (!(e instanceof IllegalArgumentException || e instanceof IOException || e instanceof UncheckedIOException)) {
            e.printStackTrace(); // a bug: the details go to the console, the dialog says one line
        }
        dialogs.error(title, Failures.describe(e));
    }

    /** Whether the joins are needed: "Keep tangent continuity" or "Keep curvature continuity" (which implies it) is on. */
    private boolean smooth() {
        return settings.current().on(Toggle.SMOOTH_JOINS) || settings.current().on(Toggle.CURVATURE_JOINS);
    }

    /** True from turning "Keep curvature continuity" on (or opening a model with it on) until the joins land. */
    private boolean curvatureToReport;

    /** A topology landed: with curvature kept, says once (one line) how many borders are too short for it. */
    private void topologyLanded(Topology t) {
        if (curvatureToReport && t.joins() != null && settings.current().on(Toggle.CURVATURE_JOINS)) {
            curvatureToReport = false;
            int n = t.joins().shortBorderCount();
            if (n > 0) {
                status.message("curvature continuity not kept across " + n + (n == 1 ? " border" : " borders")
                        + ": degree below " + SmoothJoins.CURVATURE_DEGREE + " across");
            }
        }
    }

    /** True when a path-traced picture was shown as a one-sample preview during the gesture in progress. */
    private boolean previewed;

    /**
     * Starts a progressive render of the current state (coalesced; never renders here). Path
     * traced, while a gesture turns the view or drags points the picture is a one-sample preview;
     * {@link #motionEnded} resumes refining.
     */
    void render() {
        rendered = settings.current();
        Picture p = view.picture();
        if (p != null && settings.current().on(Toggle.RAY_TRACE)) {
            boolean preview = settings.current().pathTraced() && pointer != null && pointer.inGesture();
            previewed |= preview;
            engine.submit(RenderRequest.of(document.scene(), view.camera(), view.view().framing(), settings.current(), p,
                    preview));
        }
        compareToClipping(p);
        checkContinuity();
        view.repaint();
    }

    /** A gesture ended: a path-traced picture shown as a preview during it refines again. */
    void motionEnded() {
        if (previewed) {
            previewed = false;
            render();
        }
    }

    /** View → Continuity on: certify the model's borders (off the UI thread; once a model); off: drop them. */
    private void checkContinuity() {
        if (settings.current().on(Toggle.CONTINUITY)) {
            continuity.request(document.scene());
        } else {
            continuity.clear();
        }
    }

    /** View → Difference to clipping on: compare the picture's primary rays (off the UI thread); off: drop the mask. */
    private void compareToClipping(Picture p) {
        Settings s = settings.current();
        if (p != null && s.on(Toggle.DIFFERENCE_TO_CLIPPING)) {
            difference.request(document.scene(), view.camera(), p.width(), p.height(), RenderChoices.intersectOptions(s),
                    s.intersectionLabel());
        } else {
            difference.clear();
        }
    }

    private void requestOverlay(boolean fresh) {
        OverlayRequest r = OverlayRequest.of(document.scene(), view.projector(), settings.current(), view.scale(), mouseX,
                mouseY, OverlayRequest.patchesOf(selection));
        if (fresh) {
            overlay.replace(r);
        } else {
            overlay.request(r);
        }
        overlay.selected(selectedHandles());
        overlay.lights(lightMarkers());
    }

    /**
     * The selected points as drawn now: each projected, for a selection of up to
     * {@link #SELECTED_BUDGET} points; for a bigger one, the drawn handles that are selected.
     */
    private List<Handle> selectedHandles() {
        if (selection.size() <= SELECTED_BUDGET) {
            return selection.drawn(document.scene(), view.projector(), SELECTED_BUDGET);
        }
        OverlayGeometry g = overlay.geometry();
        List<Handle> out = new ArrayList<>();
        for (int k = 0; k < g.handleCount(); k++) {
            Handle h = g.handle(k);
            if (selection.contains(h.ref())) {
                out.add(h);
            }
        }
        return out;
    }

    private void selectionBuilt() {
        if (selection.size() > SELECTED_BUDGET) {
            overlay.selected(selectedHandles());
        }
    }

    private List<LightMarker> lightMarkers() {
        Settings s = settings.current();
        if (!s.on(Toggle.SHOW_LIGHT)) {
            return List.of();
        }
        var camera = view.camera();
        return LightMarker.of(LightRig.shown(s, document.scene(), camera, view.view().framing()), view.projector(),
                s.light() != LightPlacement.SCENE, view.scale());
    }

    private void viewMoved() {
        requestOverlay(false);
        render();
    }

    /** The settings of the last {@link #render()} (null before it): a change of the exposure alone needs no new render. */
    private Settings rendered;
    /** The exposure the engine was last told of (or that the first requests carry). */
    private double exposureSent;

    private void settingsChanged() {
        Settings now = settings.current();
        if (now.exposure() != exposureSent) {
            // the picture is tone mapped again off the UI thread; it keeps its samples
            exposureSent = now.exposure();
            engine.exposure(exposureSent);
            prefs.setExposureTenths(now.level(Level.EXPOSURE));
        }
        if (now.sameButExposure(rendered)) {
            rendered = now;
            notifyListeners();
            return;
        }
        double fov = settings.current().fovDegrees();
        if (view.view().fovDegrees() != fov) {
            view.replace(view.view().withFov(fov));
        }
        requestOverlay(false);
        render();
        boolean curvature = settings.current().on(Toggle.CURVATURE_JOINS);
        curvatureToReport |= curvature && !curvatureWasOn;
        curvatureWasOn = curvature;
        topology.request(document.scene(), smooth());
        notifyListeners();
    }

    private boolean curvatureWasOn;

    /** The scene changed by an edit, an undo or a redo. */
    private void sceneChanged() {
        document.bump();
        overlay.hover(null);
        requestOverlay(false);
        render();
        topology.request(document.scene(), smooth());
        notifyListeners();
    }

    /** Undo or redo moved the history; a non-null framing is where the view goes. */
    void historyMoved(Framing framing) {
        if (framing != null) {
            view.replace(view.view().withFraming(framing));
        }
        sceneChanged();
    }

    /** The selection is now {@code s} (widgets that show it are told). */
    void select(Selection s) {
        if (!s.equals(selection)) {
            inspector.clearMessage();
        }
        selection = s;
        if (overlay.geometry().focused()) {
            requestOverlay(false); // dense handles: the selected patches' handles are drawn
        } else {
            overlay.selected(selectedHandles());
        }
        notifyListeners();
    }

    private double mouseX = Double.NaN, mouseY = Double.NaN;

    /**
     * The mouse is over the picture at {@code (x, y)} (device pixels; NaN: it left). With dense
     * handles ({@link OverlayGeometry#focused}) the overlay is built again for the patch under it
     * (coalesced: the newest position only) — except while it is over a drawn handle: a point on a
     * border lies in its neighbours' boxes too, and the handle about to be grabbed must stay.
     */
    void pointerAt(double x, double y) {
        mouseX = x;
        mouseY = y;
        if (overlay.geometry().focused() && overlay.hover() == null) {
            requestOverlay(false);
        }
    }

    /** A drag that started from {@code base} ended: one undoable edit called {@code name} (unless the model moved on). */
    void dragEnded(Scene base, long epoch, String name) {
        if (document.epoch() == epoch) {
            document.history().commit(name, base);
            document.bump();
            topology.request(document.scene(), smooth());
        }
        select(selection);
    }

    private final class EditorTarget implements SceneEditor.Target {
        @Override
        public Document document() { return document; }

        @Override
        public void previewed() {
            requestOverlay(false);
            render();
            notifyListeners();
        }

        @Override
        public void edited(String name, Scene after, Framing framing) {
            Framing before = framing == null ? null : view.view().framing();
            document.history().apply(name, after, before, framing);
            if (framing != null) {
                view.replace(view.view().withFraming(framing));
            }
            sceneChanged();
        }

        @Override
        public void failed(String title, Throwable e) { AppModel.this.failed(title, e); }
    }

    /**
     * The status line after an open: {@code opened cad.obj}, then the reader's notes (what it read
     * past without drawing), shown this once: {@code opened cad.obj — cad.obj: skipped 2 curv (…)}.
     */
    static String openedMessage(String name, java.util.List<String> notes) {
        return notes.isEmpty() ? "opened " + name : "opened " + name + " — " + String.join("; ", notes);
    }

    private final class LoaderTarget implements DocumentLoader.Target {
        @Override
        public void opened(DocumentLoader.Loaded l) {
            Scene scene = l.document().scene();
            Settings s = RenderChoices.lightFor(RenderChoices.fromScene(settings.current(), l.document().settings()),
                    RenderChoices.hasOwnLight(scene));
            var camera = scene.camera();
            if (camera.isPresent()) {
                s = s.with(Level.PERSPECTIVE, Settings.perspectiveOf(camera.get().fovDegrees()));
            }
            settings.replaceQuietly(s);
            document.replace(scene, l.name(), l.source());
            view.replace(ViewModel.home(scene, l.bounds(), s.fovDegrees()));
            selection = Selection.EMPTY;
            inspector.clearMessage();
            overlay.hover(null);
            requestOverlay(true);
            render();
            curvatureToReport = settings.current().on(Toggle.CURVATURE_JOINS);
            topology.request(scene, smooth());
            if (l.source() != null) {
                prefs.addRecent(l.source());
            }
            status.message(openedMessage(l.name(), l.document().notes()));
        }

        @Override
        public StatusModel status() { return status; }

    /** View → Difference to clipping: the mask for the current picture, kept up to date off the UI thread. */
    public DifferenceModel difference() { return difference; }

        @Override
        public UserDialogs dialogs() { return dialogs; }
    }
}
