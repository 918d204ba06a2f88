package org.beziertracer.app;

import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;

import org.beziertracer.model.Scene;

/**
 * The {@link Topology} of the open model, kept up to date off the UI thread: after every change
 * that lands (an open, an edit, an undo) the welds — and the joins while "Keep tangent
 * continuity" or "Keep curvature continuity" is on — are found again on a worker (newest only, {@link Coalescing}) and handed
 * back to the UI thread. Until then the previous topology serves, which is safe ({@link Topology}).
 * UI thread only, except where noted.
 */
final class TopologyModel {

    private record Request(Scene scene, boolean joins) {}

    private final Executor ui;
    private final Coalescing<Request> builds;
    private final AtomicInteger delivering = new AtomicInteger();
    private Topology current = Topology.NONE;
    private Request last;
    private Consumer<Topology> delivered = t -> {};

    TopologyModel(Executor worker, Executor ui, Consumer<Throwable> failed) {
        this.ui = ui;
        this.builds = new Coalescing<>(worker, this::build, failed);
    }

    private void build(Request r) {
        Topology t = Topology.of(r.scene(), r.joins());
        delivering.incrementAndGet();
        ui.execute(() -> {
            delivering.decrementAndGet();
            current = t;
            delivered.accept(t);
        });
    }

    /** {@code l} hears of every topology that lands, on the UI thread, after it became {@link #current}. */
    void onDelivered(Consumer<Topology> l) { delivered = l; }

    /** Finds the topology of {@code scene} (with joins when {@code joins}), unless it is already known or on its way. */
    void request(Scene scene, boolean joins) {
        Request r = new Request(scene, joins);
        if (r.equals(last)) {
            return;
        }
        last = r;
        builds.submit(r);
    }

    /** The newest topology: of the current scene, or of an earlier one of the same model while that one is found. */
    Topology current() { return current; }

    /** True while a topology is being found or on its way to the UI thread (any thread). */
    boolean busy() { return builds.busy() || delivering.get() > 0; }
}
