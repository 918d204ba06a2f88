package org.beziertracer.app;

import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;

/**
 * View → Difference to clipping, kept up to date: each {@link #request} (UI thread, constant time)
 * makes the shown {@link DifferenceMask} stale and hands the comparison to a worker through
 * {@link Coalescing}, so during a drag only the newest request is computed. Requests are numbered;
 * a comparison checks its number once per row and stops as soon as a newer request (or
 * {@link #clear}) has replaced it, and a result arrives on the UI thread only while its number is
 * still the newest. The worker keeps one {@link SnapshotCache} per method, so a camera change
 * reuses both snapshots. A request equal to the one shown or being computed is ignored (a toggle
 * that does not change the picture costs nothing).
 */
public final class DifferenceModel {

    /** What one comparison needs; equal requests give the same mask. */
    record Request(Scene scene, CameraSpec camera, int width, int height, IntersectOptions method, String label) {}

    private record Numbered(long number, Request request) {}

    private final Executor ui;
    private final Runnable onChange;
    private final Coalescing<Numbered> work;
    private final AtomicLong newest = new AtomicLong();
    private final AtomicInteger delivering = new AtomicInteger();
    // Worker thread only
    private final SnapshotCache methodSnapshots = new SnapshotCache();
    private final SnapshotCache clippingSnapshots = new SnapshotCache();
    // UI thread only
    private Request wanted;
    private DifferenceMask current;
    /** A comparison was asked for since the worker last let its snapshots go. */
    private boolean holding;

    /**
     * @param onChange runs on the UI thread when a mask arrives or goes
     * @param failed   runs on the UI thread when a comparison failed
     */
    DifferenceModel(Executor worker, Executor ui, Runnable onChange, Consumer<Throwable> failed) {
        this.ui = ui;
        this.onChange = onChange;
        this.work = new Coalescing<>(worker, this::compute, e -> deliver(() -> {
            wanted = null;
            failed.accept(e);
        }));
    }

    /** The mask for the newest request, or null while it is being computed (or when none was asked for). */
    public DifferenceMask current() { return current; }

    /** True while a comparison was asked for and its mask has not arrived. */
    public boolean computing() { return wanted != null && current == null; }

    /** True while a comparison waits, runs or has its result on the way (tests wait on this). */
    public boolean busy() { return work.busy() || delivering.get() > 0; }

    /**
     * Compare {@code scene} seen by {@code camera} at {@code width × height} with the options
     * {@code method} against clipping; {@code label} names the method in the status bar.
     */
    void request(Scene scene, CameraSpec camera, int width, int height, IntersectOptions method, String label) {
        Request r = new Request(scene, camera, width, height, method, label);
        if (r.equals(wanted)) {
            return;
        }
        wanted = r;
        holding = true;
        boolean had = current != null;
        current = null;
        work.submit(new Numbered(newest.incrementAndGet(), r));
        if (had) {
            onChange.run();
        }
    }

    /**
     * No comparison wanted: the one in progress stops, the mask goes, and the worker lets go of
     * its two snapshots (a model and method switched away from must not stay in memory while the
     * view is off).
     */
    void clear() {
        long number = newest.incrementAndGet();
        if (holding) {
            holding = false;
            work.submit(new Numbered(number, null));
        }
        boolean had = wanted != null;
        wanted = null;
        current = null;
        if (had) {
            onChange.run();
        }
    }

    /** Worker thread. */
    private void compute(Numbered n) {
        Request r = n.request();
        if (r == null) {
            // a release is never stale: later clears do not submit another
            methodSnapshots.release();
            clippingSnapshots.release();
            return;
        }
        if (n.number() != newest.get()) {
            return;
        }
        SceneIntersector a = methodSnapshots.prepare(r.scene(), r.method());
        SceneIntersector b = clippingSnapshots.prepare(r.scene(), clippingFor(r.method()));
        DifferenceMask mask = DifferenceMask.compare(a, b, r.camera(), r.width(), r.height(), r.label(),
                () -> n.number() != newest.get());
        if (mask != null) {
            deliver(() -> {
                if (n.number() == newest.get()) {
                    current = mask;
                    onChange.run();
                }
            });
        }
    }

    /** The reference: exact Bézier clipping with the same BVH switch. */
    static IntersectOptions clippingFor(IntersectOptions method) {
        return IntersectOptions.defaults().withMethod(Method.CLIPPING).withBvh(method.bvh());
    }

    private void deliver(Runnable onUi) {
        delivering.incrementAndGet();
        ui.execute(() -> {
            try {
                onUi.run();
            } finally {
                delivering.decrementAndGet();
            }
        });
    }
}
