package org.beziertracer.app;

import java.util.List;
import java.util.Objects;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

/**
 * The overlay as the view shows it: requests are built into {@link OverlayGeometry} on the
 * overlay worker (newest only, {@link Coalescing}), the result comes back on the UI thread and
 * the view repaints; the hovered handle is set on the UI thread. {@link #snapshot} is what the
 * painter reads. UI thread only, except where noted.
 */
public final class OverlayModel {

    private final Executor ui;
    private final Runnable repaint;
    private final Runnable countChanged;
    private final Coalescing<OverlayRequest> builds;
    private final AtomicInteger delivering = new AtomicInteger();
    private OverlaySnapshot snapshot = OverlaySnapshot.EMPTY;
    private long builtCount;
    private Runnable onBuilt = () -> {};

    /**
     * @param countChanged runs (UI thread) when a delivered overlay counts other patches or points
     *                     than the one before (the status bar shows them)
     */
    OverlayModel(Executor worker, Executor ui, Runnable repaint, Runnable countChanged, Consumer<Throwable> failed) {
        this.ui = ui;
        this.repaint = repaint;
        this.countChanged = countChanged;
        this.builds = new Coalescing<>(worker, this::build, failed);
    }

    /** The last overlay built (overlay worker only: builds run one at a time). */
    private OverlayGeometry lastBuilt;

    private void build(OverlayRequest r) {
        OverlayGeometry g = OverlayBuilder.build(lastBuilt, r);
        lastBuilt = g;
        delivering.incrementAndGet();
        ui.execute(() -> {
            delivering.decrementAndGet();
            OverlayGeometry old = snapshot.geometry();
            snapshot = snapshot.withGeometry(g, relocate(snapshot.hover(), g));
            builtCount++;
            onBuilt.run();
            repaint.run();
            if (old.pointCount() != g.pointCount() || old.scene() == null
                    || old.scene().patchCount() != g.scene().patchCount()) {
                countChanged.run();
            }
        });
    }

    /** The hovered point where {@code g} draws it (it moves with the view), or null when {@code g} does not. */
    private static Handle relocate(Handle h, OverlayGeometry g) {
        if (h == null) {
            return null;
        }
        for (int k = 0; k < g.handleCount(); k++) {
            Handle c = g.handle(k);
            if (c.ref().equals(h.ref())) {
                return c;
            }
        }
        return null;
    }

    /** Runs {@code r} (UI thread) whenever a built overlay is delivered, before the repaint. */
    void onBuilt(Runnable r) { onBuilt = r; }

    /** Builds the overlay for {@code r} off this thread; the current one stays shown meanwhile. */
    void request(OverlayRequest r) {
        builds.submit(r);
    }

    /** Like {@link #request}, but shows nothing until it is built (a newly opened model). */
    void replace(OverlayRequest r) {
        snapshot = snapshot.withGeometry(OverlayGeometry.EMPTY, null);
        repaint.run();
        builds.submit(r);
    }

    /** What the painter draws. */
    public OverlaySnapshot snapshot() { return snapshot; }

    public OverlayGeometry geometry() { return snapshot.geometry(); }

    /** Overlays delivered so far (tests wait for a new one). */
    public long builtCount() { return builtCount; }

    public Handle hover() { return snapshot.hover(); }

    /** Sets the hovered handle; repaints when it changed. */
    void hover(Handle h) {
        if (!Objects.equals(h, snapshot.hover())) {
            snapshot = snapshot.withHover(h);
            repaint.run();
        }
    }

    /** The selected points as drawn now; repaints. */
    void selected(List<Handle> handles) {
        snapshot = snapshot.withSelected(handles);
        repaint.run();
    }

    /** The rubber band being drawn ({@code x0, y0, x1, y1}), or null; repaints. */
    void band(double[] rectangle) {
        snapshot = snapshot.withBand(rectangle);
        repaint.run();
    }

    /** The light markers to draw (empty: none); repaints when they changed. */
    void lights(List<LightMarker> markers) {
        if (!markers.equals(snapshot.lights())) {
            snapshot = snapshot.withLights(markers);
            repaint.run();
        }
    }

    /** True while an overlay is being built or on its way to the UI thread (any thread). */
    public boolean busy() {
        return builds.busy() || delivering.get() > 0;
    }
}
