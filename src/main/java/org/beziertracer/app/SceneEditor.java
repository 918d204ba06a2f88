package org.beziertracer.app;

import java.util.concurrent.CancellationException;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import java.util.function.Function;
import java.util.function.Supplier;

import org.beziertracer.model.Scene;

/**
 * Applies scene edits off the UI thread — building a new {@link Scene} copies the patch list, which
 * grows with the model — and brings the result back to the UI thread, where the document takes it.
 * Drag previews coalesce (only the newest is computed); whole-model edits run in order. Every
 * edit carries the document's {@linkplain Document#epoch() epoch} from when it was asked for and
 * is dropped when the epoch moved meanwhile (another model opened, an undo). UI thread only,
 * except where noted.
 */
final class SceneEditor {

    /**
     * A whole-model edit's result.
     *
     * @param after   the new scene
     * @param framing the view's new framing, or null when the edit keeps it
     */
    record Outcome(Scene after, Framing framing) {}

    /** What the document does with results (implemented by the app). */
    interface Target {
        Document document();

        /** A preview replaced the current scene. */
        void previewed();

        /** A recorded edit replaced it; {@code framing} non-null re-frames the view. */
        void edited(String name, Scene after, Framing framing);

        void failed(String title, Throwable e);
    }

    private record Preview(long epoch, Supplier<Scene> edit, Runnable then) {}

    private final Executor ui;
    private final Target target;
    private final Coalescing<Preview> previews;
    private final BackgroundTasks tasks;
    private final AtomicInteger delivering = new AtomicInteger();
    // Worker-thread state: the last preview computed, reused when the same edit comes again (release)
    private Supplier<Scene> lastEdit;
    private Scene lastScene;

    SceneEditor(Executor worker, Executor ui, Target target) {
        this.ui = ui;
        this.target = target;
        this.previews = new Coalescing<>(worker, this::computePreview, e -> ui.execute(() -> target.failed("Edit failed", e)));
        this.tasks = new BackgroundTasks(worker, ui);
    }

    /**
     * Shows the scene {@code edit} computes (a drag step), unless the document's epoch is no longer
     * {@code epoch}; then runs {@code then} on the UI thread. A newer preview replaces this one if it
     * has not started; {@code then} of a replaced preview does not run.
     */
    void preview(long epoch, Supplier<Scene> edit, Runnable then) {
        previews.submit(new Preview(epoch, edit, then));
    }

    private void computePreview(Preview p) {
        if (p.edit() != lastEdit) {
            lastScene = p.edit().get();
            lastEdit = p.edit();
        }
        Scene s = lastScene;
        delivering.incrementAndGet();
        ui.execute(() -> {
            delivering.decrementAndGet();
            Document doc = target.document();
            if (doc.epoch() == p.epoch() && doc.scene() != s) {
                doc.history().preview(s);
                target.previewed();
            }
            p.then().run();
        });
    }

    /** Computes {@code edit} from the current scene off the UI thread, then records it as one undoable edit. */
    void apply(String name, Function<Scene, Outcome> edit) {
        Document doc = target.document();
        long epoch = doc.epoch();
        Scene base = doc.scene();
        Consumer<Outcome> done = o -> {
            if (doc.epoch() == epoch) {
                target.edited(name, o.after(), o.framing());
            }
        };
        tasks.submit(name, () -> edit.apply(base), done, e -> {
            if (!(e instanceof CancellationException)) {
                target.failed(name + " failed", e);
            }
        });
    }

    /** True while an edit waits, runs or is on its way to the UI thread (any thread). */
    boolean busy() {
        return previews.busy() || delivering.get() > 0 || tasks.busy();
    }
}
