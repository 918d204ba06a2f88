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
    /** {@code 2^exposure} of the path tracer's tone map for the tiles shown; 0 for Whitted (no tone map). */
    final double toneScale;
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
