package org.beziertracer.ui;

import java.util.Objects;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.render.Camera;
import org.beziertracer.render.Failures;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.FrameStats;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.RenderSession;

/**
 * The ray-traced picture: a {@link RenderSession} fed from one "scene-prep" thread.
 *
 * <p><b>Coalescing.</b> {@link #submit} (event thread) cancels the render in progress at once
 * (workers stop within one tile), parks the request in a single slot and wakes the prep thread,
 * which always takes the <i>newest</i> request: during a drag, mouse events that arrive while a
 * snapshot is being prepared replace each other and only the latest is rendered.
 *
 * <p><b>Snapshots.</b> The prep thread compares the request's scene with the last snapshot's:
 * equal (a camera or shading change) → the same {@link SceneIntersector}; one patch differs (a
 * dragged point) → {@link SceneIntersector#withPatch}, which re-splits that patch and refits the
 * BVH; otherwise a full build.
 *
 * <p><b>Sink.</b> Tiles of the newest generation are copied into the request's
 * {@link FrameBuffer} on the worker threads; nothing here touches Swing.
 *
 * <p><b>BVH speed-up.</b> The last full-frame time is kept per BVH switch for the same picture
 * (scene, camera, other settings); when both are known the status reports off/on.
 */
public final class RayTraceEngine implements PictureEngine {

    private final RenderSession session;
    private final ExecutorService prep = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "scene-prep");
        t.setDaemon(true);
        return t;
    });
    private final AtomicReference<RenderRequest> pending = new AtomicReference<>();
    private final AtomicBoolean preparing = new AtomicBoolean();
    private volatile Consumer<RenderStatus> listener = s -> {};
    private volatile Consumer<String> errors = m -> {};
    private volatile FrameBuffer target;
    private volatile RenderRequest current;
    private volatile double prepMillis;
    private volatile boolean frameDone = true;
    // Prep-thread state
    private SceneIntersector snapshot;
    // BVH speed-up measurement
    private volatile Object timedKey;
    private volatile double millisBvhOn, millisBvhOff;

    public RayTraceEngine() {
        session = new RenderSession(new Sink());
    }

    @Override
    public void onStatus(Consumer<RenderStatus> l) { listener = l; }

    @Override
    public void onError(Consumer<String> l) { errors = l; }

    private void fail(Throwable e) {
        frameDone = true;
        errors.accept(Failures.describe(e));
    }

    @Override
    public void submit(RenderRequest request) {
        session.cancel();
        frameDone = false;
        pending.set(request);
        if (preparing.compareAndSet(false, true)) {
            prep.execute(this::drain);
        }
    }

    @Override
    public boolean busy() {
        return pending.get() != null || preparing.get() || !frameDone;
    }

    private void drain() {
        try {
            for (RenderRequest r = pending.getAndSet(null); r != null; r = pending.getAndSet(null)) {
                start(r);
            }
        } catch (RuntimeException | OutOfMemoryError e) {
            fail(e);
        } finally {
            preparing.set(false);
        }
        // A request that slipped in between the last poll and clearing the flag
        if (pending.get() != null && preparing.compareAndSet(false, true)) {
            prep.execute(this::drain);
        }
    }

    private void start(RenderRequest r) {
        long t0 = System.nanoTime();
        RenderSettings s = r.settings();
        IntersectOptions io = IntersectOptions.defaults().withMethod(Method.parse(s.method())).withBvh(s.bvh())
                .withTessellate(r.tessellate());
        snapshot = update(snapshot, r.scene(), io);
        prepMillis = (System.nanoTime() - t0) / 1e6;
        RenderOptions options = RenderOptions.defaults().withPassesPerFrame(Math.max(1, Math.min(16, r.passesPerFrame())))
                .withTessellate(r.tessellate());
        RenderJob job = new RenderJob(snapshot, new Camera(r.camera()), s, options);
        session.cancel();
        target = r.target();
        current = r;
        if (pending.get() == null) {
            session.start(job);
            session.completion().whenComplete((result, e) -> {
                Throwable cause = e instanceof java.util.concurrent.CompletionException && e.getCause() != null ? e.getCause() : e;
                if (cause != null && !(cause instanceof java.util.concurrent.CancellationException)) {
                    fail(cause);
                }
            });
        }
    }

    /** The snapshot for {@code scene}: reused, patched (one patch changed) or rebuilt. */
    static SceneIntersector update(SceneIntersector old, Scene scene, IntersectOptions io) {
        if (old == null || !old.options().equals(io)) {
            return SceneIntersector.build(scene, io);
        }
        Scene prev = old.scene();
        if (prev == scene) {
            return old;
        }
        if (prev.patchCount() != scene.patchCount() || !prev.planes().equals(scene.planes())
                || !prev.spheres().equals(scene.spheres()) || !prev.lights().equals(scene.lights())
                || !prev.materials().equals(scene.materials()) || !prev.camera().equals(scene.camera())) {
            return SceneIntersector.build(scene, io);
        }
        int changed = -1;
        for (int k = 0; k < scene.patchCount(); k++) {
            if (prev.patchMaterial(k) != scene.patchMaterial(k)) {
                return SceneIntersector.build(scene, io);
            }
            if (!prev.patches().get(k).equals(scene.patches().get(k))) {
                if (changed >= 0) {
                    return SceneIntersector.build(scene, io);
                }
                changed = k;
            }
        }
        return changed < 0 ? old : old.withPatch(changed, scene.patches().get(changed));
    }

    /** What must match for two frame times to be comparable: everything but the BVH switch. */
    private record TimingKey(Scene scene, CameraSpec camera, RenderSettings settings, int tessellate) {
        static TimingKey of(RenderRequest r) {
            RenderSettings s = r.settings();
            return new TimingKey(r.scene(), r.camera(), new RenderSettings(s.width(), s.height(), s.spp(), s.sampler(),
                    s.method(), true, s.shading(), s.checker(), s.shadows(), s.maxDepth()), r.tessellate());
        }
    }

    private final class Sink implements FrameSink {
        @Override
        public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
            FrameBuffer fb = target;
            if (generation == session.generation() && fb != null) {
                fb.tile(x0, y0, w, h, argb, stride);
            }
        }

        @Override
        public void passDone(int generation, int pass, int passCount, FrameStats stats) {
            RenderRequest r = current;
            if (generation != session.generation() || r == null) {
                return;
            }
            double speedUp = 0;
            if (pass == passCount - 1) {
                TimingKey key = TimingKey.of(r);
                if (!Objects.equals(key, timedKey)) {
                    timedKey = key;
                    millisBvhOn = 0;
                    millisBvhOff = 0;
                }
                if (r.settings().bvh()) {
                    millisBvhOn = stats.millis();
                } else {
                    millisBvhOff = stats.millis();
                }
                frameDone = pending.get() == null;
            }
            if (Objects.equals(TimingKey.of(r), timedKey) && millisBvhOn > 0 && millisBvhOff > 0) {
                speedUp = millisBvhOff / millisBvhOn;
            }
            listener.accept(new RenderStatus(pass + 1, passCount, stats.millis(), stats.mraysPerSecond(),
                    r.settings().spp(), r.settings().method(), r.settings().bvh(), speedUp, prepMillis, r.tessellate()));
        }
    }

    @Override
    public void close() {
        prep.shutdownNow();
        session.close();
        try {
            prep.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
