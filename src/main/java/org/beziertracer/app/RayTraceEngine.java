package org.beziertracer.app;

import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.render.Failures;
import org.beziertracer.render.FrameSink;
import org.beziertracer.render.FrameStats;
import org.beziertracer.render.ShadingMode;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderSession;

/**
 * The ray-traced picture: a {@link RenderSession} fed from one "scene-prep" thread.
 *
 * <p><b>Coalescing.</b> {@link #submit} (UI thread) cancels the render in progress at once
 * (workers stop within one tile) and hands the request to the prep thread through
 * {@link Coalescing}, which always takes the <i>newest</i> request: during a drag, mouse events
 * that arrive while a snapshot is being prepared replace each other and only the latest is
 * rendered.
 *
 * <p><b>Snapshots.</b> {@link SnapshotCache}: the same {@link SceneIntersector} for a camera, light
 * or shading change (the request's lights go into the job, not the scene),
 * {@link SceneIntersector#withPatches} for a dragged point, a full build otherwise.
 *
 * <p><b>Sink.</b> Tiles of the newest generation are copied into the request's {@link Picture} on
 * the worker threads; nothing here touches a window.
 *
 * <p><b>Exposure.</b> {@link #exposure} hands the new exposure to a "picture-tone" thread (coalesced:
 * the newest value only), which has the session tone map the picture again from its film
 * ({@link RenderSession#setExposure}): the render is not restarted and the UI thread never encodes.
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
    private final ExecutorService tone = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "picture-tone");
        t.setDaemon(true);
        return t;
    });
    /** The newest exposure asked for; a retone is queued while {@link #tonePending} is set. */
    private volatile double shownExposure;
    private final java.util.concurrent.atomic.AtomicBoolean tonePending = new java.util.concurrent.atomic.AtomicBoolean();
    /** Exposure changes asked for, and the newest of them shown (busy until equal). */
    private final AtomicLong toneAsked = new AtomicLong(), toneShown = new AtomicLong();
    private final Coalescing<Numbered> requests = new Coalescing<>(prep, this::start, this::fail);
    private final SnapshotCache snapshots = new SnapshotCache();
    private volatile Consumer<RenderStatus> listener = s -> {};
    private volatile Consumer<String> errors = m -> {};
    private volatile Picture target;
    private volatile Numbered current;
    private volatile double prepMillis;
    // Requests numbered as submitted; busy until the newest one's frame is done (or failed)
    private final AtomicLong submitted = new AtomicLong();
    private final AtomicLong settled = new AtomicLong();
    // BVH speed-up measurement
    private volatile TimingKey timedKey;
    private volatile double millisBvhOn, millisBvhOff;

    public RayTraceEngine() {
        session = new RenderSession(new Sink());
    }

    @Override
    public void onStatus(Consumer<RenderStatus> l) { listener = l; }

    @Override
    public void onError(Consumer<String> l) { errors = l; }

    /** A request and its place in the order of submission. */
    private record Numbered(long number, RenderRequest request) {}

    private void fail(Throwable e) {
        errors.accept(Failures.describe(e));
    }

    /** Request {@code number} is done (its last pass shown) or failed: so are all before it. */
    private void settle(long number) {
        settled.accumulateAndGet(number, Math::max);
    }

    /** The job last started (its snapshot stays reachable while it is the newest). */
    private volatile RenderJob lastJob;

    @Override
    public RenderJob lastJob() { return lastJob; }

    @Override
    public void submit(RenderRequest request) {
        session.cancel();
        requests.submit(new Numbered(submitted.incrementAndGet(), request));
    }

    @Override
    public void exposure(double stops) {
        shownExposure = stops;
        toneAsked.incrementAndGet();
        if (tonePending.compareAndSet(false, true)) {
            tone.execute(this::retone);
        }
    }

    /** On the tone thread: the newest exposure asked for, applied to the picture shown. */
    private void retone() {
        tonePending.set(false);
        long asked = toneAsked.get();
        try {
            session.setExposure(shownExposure);
        } catch (RuntimeException | Error e) {
            fail(e);
        } finally {
            toneShown.accumulateAndGet(asked, Math::max);
        }
    }

    /**
     * True until the newest request's frame is done or has failed, or an exposure change is not shown yet. Requests are numbered, so a late
     * outcome of an older one (its last pass, or its failure, arriving after a newer one started)
     * cannot make the engine look idle.
     */
    @Override
    public boolean busy() {
        return settled.get() < submitted.get() || toneShown.get() < toneAsked.get();
    }

    private void start(Numbered n) {
        try {
            RenderRequest r = n.request();
            long t0 = System.nanoTime();
            SceneIntersector snapshot = snapshots.prepare(r.scene(), r.intersect());
            prepMillis = (System.nanoTime() - t0) / 1e6;
            RenderJob job = r.job(snapshot);
            lastJob = job;
            session.cancel();
            target = r.target();
            current = n;
            if (!requests.hasPending()) {
                session.start(job);
                session.completion().whenComplete((result, e) -> {
                    Throwable cause = e instanceof CompletionException && e.getCause() != null ? e.getCause() : e;
                    if (cause != null && !(cause instanceof CancellationException)) {
                        settle(n.number());
                        fail(cause);
                    }
                });
            }
        } catch (RuntimeException | Error e) {
            settle(n.number());
            throw e; // reported by the coalescing worker (fail)
        }
    }

    /** What must match for two frame times to be comparable: everything but the BVH switch. */
    private record TimingKey(Scene scene, java.util.List<org.beziertracer.model.PointLight> lights, CameraSpec camera,
                             RenderSettings settings, IntersectOptions intersect) {
        static TimingKey of(RenderRequest r) {
            RenderSettings s = r.settings();
            return new TimingKey(r.scene(), r.lights(), r.camera(), new RenderSettings(s.width(), s.height(), s.spp(),
                    s.sampler(), s.method(), true, s.shading(), s.checker(), s.shadows(), s.maxDepth()),
                    r.intersect().withBvh(true));
        }
    }

    private final class Sink implements FrameSink {
        @Override
        public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
            Picture p = target;
            if (generation == session.generation() && p != null) {
                p.tile(x0, y0, w, h, argb, stride);
            }
        }

        @Override
        public void passDone(int generation, int pass, int passCount, FrameStats stats) {
            Numbered n = current;
            if (generation != session.generation() || n == null) {
                return;
            }
            RenderRequest r = n.request();
            boolean bvh = r.intersect().bvh();
            if (pass == passCount - 1) {
                TimingKey key = TimingKey.of(r);
                if (!Objects.equals(key, timedKey)) {
                    timedKey = key;
                    millisBvhOn = 0;
                    millisBvhOff = 0;
                }
                if (bvh) {
                    millisBvhOn = stats.millis();
                } else {
                    millisBvhOff = stats.millis();
                }
            }
            double speedUp = Objects.equals(TimingKey.of(r), timedKey) && millisBvhOn > 0 && millisBvhOff > 0
                    ? millisBvhOff / millisBvhOn : 0;
            long pixels = (long) r.settings().width() * r.settings().height();
            int samplesDone = r.pathTraced() ? (int) (stats.primaryRays() / pixels) : -1;
            double samplesPerSecond = stats.millis() > 0 ? stats.primaryRays() / (stats.millis() / 1e3) : 0;
            listener.accept(new RenderStatus(pass + 1, passCount, stats.millis(), stats.mraysPerSecond(),
                    r.settings().spp(), r.intersect().method(), bvh, speedUp, prepMillis, r.intersect().tessellate(),
                    ShadingMode.parse(r.settings().shading()), stats.analysisLow(), stats.analysisHigh(), samplesDone,
                    samplesPerSecond));
            if (pass == passCount - 1) {
                settle(n.number()); // after the status, so a listener hears the last pass before the engine is idle
            }
        }
    }

    @Override
    public void close() {
        prep.shutdownNow();
        tone.shutdownNow();
        session.close();
        try {
            prep.awaitTermination(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
