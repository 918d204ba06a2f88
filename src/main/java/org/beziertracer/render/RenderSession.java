package org.beziertracer.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The renderer for an interactive app: a fixed pool of worker threads, one render at a time,
 * identified by a generation number.
 *
 * <p>{@link #start} returns at once (call it from any thread, e.g. the Swing event thread). A
 * coordinator thread runs the passes of {@link PassPlan}; in each pass the workers take 32-pixel
 * tiles from a shared counter, and after the pass the sink hears {@link FrameSink#passDone}.
 * Starting a new render or {@link #cancel()} bumps the generation; workers check it between tiles
 * and every {@value RenderWorker#PACKET} rows of its grid, so a stale render stops within one tile's time.
 *
 * <p>The sink and the {@link RenderProgress} listener are called from worker threads.
 * {@link #close()} stops everything.
 */
public final class RenderSession implements AutoCloseable {
    private final int poolSize;
    private final ThreadPoolExecutor pool;
    private final ExecutorService coordinator;
    private final FrameSink sink;
    private final RenderProgress progress;
    private final AtomicInteger generation = new AtomicInteger();
    private final AtomicInteger activeWorkers = new AtomicInteger();
    private final AtomicInteger runningRenders = new AtomicInteger();
    private volatile CompletableFuture<RenderResult> current = CompletableFuture.completedFuture(null);
    /** The state of the render started last (running or finished), for {@link #setExposure}; null before the first. */
    private volatile RenderState latest;
    /** The exposure {@link #setExposure} chose, in stops, or NaN: each job's own. */
    private volatile double shownExposure = Double.NaN;

    /** A session with {@code threads} workers (1..{@value RenderOptions#MAX_THREADS}) sending output to {@code sink}. */
    public RenderSession(int threads, FrameSink sink) {
        this(threads, sink, RenderProgress.NONE);
    }

    /** As {@link #RenderSession(int, FrameSink)}, also telling {@code progress} as tiles finish. */
    public RenderSession(int threads, FrameSink sink, RenderProgress progress) {
        if (threads < 1 || threads > RenderOptions.MAX_THREADS) {
            throw new IllegalArgumentException("threads must be 1.." + RenderOptions.MAX_THREADS + ", got " + threads);
        }
        this.poolSize = threads;
        this.sink = sink == null ? FrameSink.NONE : sink;
        this.progress = progress == null ? RenderProgress.NONE : progress;
        AtomicInteger n = new AtomicInteger();
        pool = new ThreadPoolExecutor(threads, threads, 0, TimeUnit.MILLISECONDS, new LinkedBlockingQueue<>(), r -> {
            Thread t = new WorkerThread(r, "render-worker-" + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        coordinator = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "render-coordinator");
            t.setDaemon(true);
            return t;
        });
    }

    /** A session with one worker per available processor. */
    public RenderSession(FrameSink sink) {
        this(Runtime.getRuntime().availableProcessors(), sink);
    }

    /**
     * Starts rendering {@code job}, cancelling any render in progress, and returns the new
     * generation number. Non-blocking. At most {@code min(job threads, pool size)} workers run.
     */
    public int start(RenderJob job) {
        int gen = generation.incrementAndGet();
        CompletableFuture<RenderResult> done = new CompletableFuture<>();
        current = done;
        runningRenders.incrementAndGet();
        try {
            coordinator.execute(() -> {
                try {
                    run(gen, job, done);
                } catch (Throwable e) {
                    done.completeExceptionally(e);
                } finally {
                    runningRenders.decrementAndGet();
                }
            });
        } catch (RuntimeException e) {
            runningRenders.decrementAndGet();
            throw e;
        }
        return gen;
    }

    /**
     * Renders {@code job} and waits for it (the sink still hears every tile and pass).
     *
     * @throws CancellationException when another start or a cancel superseded it
     */
    public RenderResult render(RenderJob job) throws InterruptedException {
        start(job);
        return await();
    }

    /** Waits for the newest render to finish and returns it. */
    public RenderResult await() throws InterruptedException {
        try {
            return current.get();
        } catch (ExecutionException e) {
            Throwable c = e.getCause();
            if (c instanceof RuntimeException re) {
                throw re;
            }
            if (c instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(c);
        }
    }

    /** Makes the current render stale; its workers stop within one tile. Non-blocking. */
    public void cancel() {
        generation.incrementAndGet();
    }

    /**
     * The exposure, in stops, of the path-traced tiles this session shows from now on, in place of the
     * jobs' {@link PathOptions#exposure}: the render started last — running or finished — is tone
     * mapped again from its film at once (its samples are kept and it goes on refining), and later
     * renders show it too. Blocks while the film is encoded again (about one frame's tone map);
     * call it off the UI thread. The film, and so a PNG or a {@code .pfm} made from it, does not
     * change. A Whitted render has no tone map and is left alone.
     *
     * @throws IllegalArgumentException one line, for an exposure that is not finite or beyond ±64 stops
     */
    public void setExposure(double stops) {
        if (!(Math.abs(stops) <= PathOptions.MAX_EXPOSURE)) {
            throw new IllegalArgumentException("exposure must be -64..64 stops, got " + stops);
        }
        shownExposure = stops;
        // run() publishes its state before it reads shownExposure: either it sees the new value, or we see its state
        RenderState st = latest;
        if (st != null) {
            st.retone(Math.pow(2, stops));
        }
    }

    /** The newest generation number handed out (or bumped by {@link #cancel()}). */
    public int generation() { return generation.get(); }

    /**
     * Completes when the render last started finishes: normally with its result, exceptionally
     * with a {@link CancellationException} when superseded or with the worker's failure.
     */
    public java.util.concurrent.CompletionStage<RenderResult> completion() { return current; }

    /** Worker tasks running right now. */
    public int activeWorkers() { return activeWorkers.get(); }

    /** Waits until no render and no worker is running; false on timeout. */
    public boolean awaitIdle(long timeout, TimeUnit unit) throws InterruptedException {
        long end = System.nanoTime() + unit.toNanos(timeout);
        while (runningRenders.get() > 0 || activeWorkers.get() > 0 || pool.getActiveCount() > 0) {
            if (System.nanoTime() > end) {
                return false;
            }
            Thread.sleep(1);
        }
        return true;
    }

    public int poolSize() { return poolSize; }

    /** Cancels the current render and stops the threads. */
    @Override
    public void close() {
        cancel();
        coordinator.shutdownNow();
        pool.shutdownNow();
        try {
            coordinator.awaitTermination(10, TimeUnit.SECONDS);
            pool.awaitTermination(10, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void run(int gen, RenderJob job, CompletableFuture<RenderResult> done) throws InterruptedException {
        if (generation.get() != gen) {
            done.completeExceptionally(new CancellationException("superseded"));
            return;
        }
        // A window (a crop or tile of the image) is tiled from its own corner and rendered in one-shot
        // passes: its pixels take the same samples in the same order as in the whole image
        PixelWindow region = job.filmWindow();
        List<int[]> tiles = tiles(region, job.options().tileSize());
        boolean progressive = job.options().progressive() && job.window().isWhole(job.width(), job.height());
        PathOptions path = job.options().path();
        // A progressive path-traced render refines one sample a pass and shows every pass; one with a
        // time budget also takes one sample a pass, so it can stop close to the budget
        List<PassPlan.Pass> passes = PassPlan.of(progressive, job.sampler(), job.settings().spp(),
                onePerPass(job.options().progressive(), path));
        RenderState st = new RenderState(gen, job, sink, generation, new ProgressCounter(progress, gen, passes, tiles));
        latest = st;
        double shown = shownExposure;
        if (!Double.isNaN(shown) && st.path != null) {
            st.toneScale = Math.pow(2, shown);
        }
        int workers = Math.min(job.options().threads(), poolSize);
        int perFrame = path.traced() ? 1 : job.options().passesPerFrame();
        for (int p = 0; p < passes.size(); p++) {
            PassPlan.Pass pass = passes.get(p);
            boolean display = (p + 1) % perFrame == 0 || p == passes.size() - 1;
            AtomicInteger next = new AtomicInteger();
            CountDownLatch latch = new CountDownLatch(workers);
            for (int k = 0; k < workers; k++) {
                pool.execute(() -> work(st, pass, tiles, next, display, latch));
            }
            latch.await();
            if (st.failure != null) {
                done.completeExceptionally(st.failure);
                return;
            }
            if (st.isStale()) {
                done.completeExceptionally(new CancellationException("superseded"));
                return;
            }
            st.shownBlock = pass.firstSample() ? pass.block() : 1;
            if (overBudget(path, st, pass) && p < passes.size() - 1) {
                // The time budget is spent: this pass is the last one
                sink.passDone(gen, p, p + 1, st.stats());
                break;
            }
            sink.passDone(gen, p, passes.size(), st.stats());
        }
        done.complete(new RenderResult(st.film, st.stats(), job.window()));
    }

    private void work(RenderState st, PassPlan.Pass pass, List<int[]> tiles, AtomicInteger next, boolean display,
                      CountDownLatch latch) {
        activeWorkers.incrementAndGet();
        RenderWorker w = null;
        try {
            w = ((WorkerThread) Thread.currentThread()).worker(st.job);
            for (int t = next.getAndIncrement(); t < tiles.size() && !st.isStale(); t = next.getAndIncrement()) {
                int[] tile = tiles.get(t);
                if (!w.renderTile(st, pass, tile[0], tile[1], tile[2], tile[3], display)) {
                    break;
                }
                st.progress.tileDone(pass, tile);
            }
        } catch (Throwable e) {
            st.failure = e;
        } finally {
            if (w != null) {
                w.release();
            }
            activeWorkers.decrementAndGet();
            latch.countDown();
        }
    }

    /** True when the extra samples come one a pass: a path-traced render that is progressive or has a time budget. */
    static boolean onePerPass(boolean progressive, PathOptions path) {
        return path.traced() && (progressive || path.budgetMillis() > 0);
    }

    /** True when a path-traced render with a time budget has spent it by the end of {@code pass} (an extra-sample pass). */
    private static boolean overBudget(PathOptions path, RenderState st, PassPlan.Pass pass) {
        return path.traced() && path.budgetMillis() > 0 && !pass.firstSample()
                && System.nanoTime() - st.startNanos >= path.budgetMillis() * 1_000_000L;
    }

    /** Tiles {@code {x0, y0, w, h}} covering the image, row by row. */
    static List<int[]> tiles(int width, int height, int size) {
        return tiles(PixelWindow.whole(width, height), size);
    }

    /** Tiles {@code {x0, y0, w, h}} (image coordinates) covering {@code window}, row by row from its corner. */
    static List<int[]> tiles(PixelWindow window, int size) {
        List<int[]> out = new ArrayList<>();
        for (int y = window.y0(); y < window.y1(); y += size) {
            for (int x = window.x0(); x < window.x1(); x += size) {
                out.add(new int[] {x, y, Math.min(size, window.x1() - x), Math.min(size, window.y1() - y)});
            }
        }
        return out;
    }

    /**
     * A pool thread that keeps its {@link RenderWorker} scratch, taken from the {@linkplain
     * SpareWorkers spares} of closed sessions when one fits, and left there when the thread ends.
     */
    private static final class WorkerThread extends Thread {
        private RenderWorker worker;

        WorkerThread(Runnable r, String name) {
            super(r, name);
        }

        RenderWorker worker(RenderJob job) {
            if (worker == null) {
                worker = SpareWorkers.take(job);
            }
            return worker;
        }

        @Override
        public void run() {
            try {
                super.run();
            } finally {
                if (worker != null) {
                    SpareWorkers.leave(worker);
                    worker = null;
                }
            }
        }
    }
}
