package org.beziertracer.render;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.LongAdder;

import org.beziertracer.intersect.TraceContext;

/** What the workers of one generation share: the job, its film, counters and the staleness check. */
final class RenderState {
    final int generation;
    final RenderJob job;
    final ShadingScene shading;
    /** The path tracer's data when the job asks for it ({@link Integrator#PATH}), else null. */
    final PathScene path;
    /**
     * {@code 2^exposure} of the path tracer's tone map for the tiles shown; 0 for Whitted (no tone map).
     * Changed while the render runs by {@link #retone} (the app's exposure control); read under
     * {@link #displayLock}.
     */
    volatile double toneScale;
    /**
     * Held while a tile of the film is encoded and handed to the sink, by a worker or by {@link #retone}:
     * the two never interleave on a tile, so the last tile a sink hears is the newest film data at the
     * newest exposure.
     */
    final Object displayLock = new Object();
    /**
     * The block of the pass last shown in full ({@link Film#writeArgb}: pixels without a sample yet show
     * their anchor on this grid); 1 once every pixel has a sample. Set by the coordinator between passes.
     */
    volatile int shownBlock = PassPlan.COARSEST;
    final Film film;
    final PixelSampler sampler;
    final FrameSink sink;
    final ProgressCounter progress;
    final LongAdder primaryRays = new LongAdder(), shadowRays = new LongAdder(), secondaryRays = new LongAdder();
    final LongAdder solverCalls = new LongAdder(), clipSteps = new LongAdder(), evaluations = new LongAdder(),
            laneEvaluations = new LongAdder();

    /** Adds one tracer's rays and {@code ctx}'s intersector work to the counters and zeroes {@code ctx}'s. */
    void addWork(long primary, long shadow, long secondary, TraceContext ctx) {
        primaryRays.add(primary);
        shadowRays.add(shadow);
        secondaryRays.add(secondary);
        solverCalls.add(ctx.solverCalls);
        clipSteps.add(ctx.clipIterations);
        evaluations.add(ctx.evaluations);
        laneEvaluations.add(ctx.laneEvaluations);
        ctx.solverCalls = ctx.clipIterations = ctx.evaluations = ctx.laneEvaluations = 0;
    }
    private final AtomicInteger currentGeneration;
    final long startNanos = System.nanoTime();
    volatile Throwable failure;

    RenderState(int generation, RenderJob job, FrameSink sink, AtomicInteger currentGeneration,
                ProgressCounter progress) {
        this.generation = generation;
        this.job = job;
        this.sink = sink;
        this.progress = progress;
        this.currentGeneration = currentGeneration;
        this.shading = new ShadingScene(job);
        this.path = job.options().path().integrator() == Integrator.PATH ? new PathScene(job, shading) : null;
        this.toneScale = path != null ? Math.pow(2, job.options().path().exposure()) : 0;
        this.film = new Film(job.filmWindow(),
                job.sampler() == SamplerKind.ADAPTIVE && job.settings().spp() > 1);
        this.sampler = new PixelSampler(job.sampler(), job.options().filter(), job.settings().spp(),
                job.options().seed(), path != null);
    }

    /**
     * Tone maps the whole film again with {@code scale} ({@code 2^exposure}) and hands every tile to the
     * sink, without touching the samples: the render (running or finished) goes on with the new
     * exposure. Path-traced renders only (a Whitted render has no tone map: nothing happens). Any
     * thread; tile by tile under {@link #displayLock}, so a worker's newer tile is never overwritten
     * by an older one. Allocates one tile of pixels.
     */
    void retone(double scale) {
        if (path == null || !(scale > 0) || !sink.wantsTiles()) {
            return;
        }
        toneScale = scale;
        int size = job.options().tileSize();
        int[] argb = new int[size * size];
        for (int[] t : RenderSession.tiles(job.filmWindow(), size)) {
            if (isStale()) {
                return;
            }
            synchronized (displayLock) {
                film.writeArgb(t[0], t[1], t[2], t[3], shownBlock, argb, t[2], toneScale);
                sink.tileDone(generation, t[0], t[1], t[2], t[3], argb, t[2]);
            }
        }
    }

    /** True once a newer render started or this one was cancelled (or failed). */
    boolean isStale() {
        return currentGeneration.get() != generation || failure != null;
    }

    FrameStats stats() {
        return new FrameStats(primaryRays.sum(), shadowRays.sum(), secondaryRays.sum(),
                (System.nanoTime() - startNanos) / 1e6,
                new FrameStats.Work(solverCalls.sum(), clipSteps.sum(), evaluations.sum(), laneEvaluations.sum()),
                shading.rangeLow, shading.rangeHigh);
    }
}
