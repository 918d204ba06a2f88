package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderResult;
import org.beziertracer.render.Renderer;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.Blackhole;

/**
 * One full 800×600 frame (1 spp, Phong + shadow rays) of the two reference views
 * ({@link FrameScenes}) through {@link Renderer#renderOnce}, on 1 and 2 worker threads, exact
 * ({@code tessellate} 0) or as a K×K triangle mesh per patch through the same BVH and shading.
 * The job (intersector, BVH, camera) is built once per trial; each operation renders a frame on a
 * fresh {@code RenderSession} (thread start-up included, as the CLI does). Sample time in ms; the
 * median is the number to quote.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class FrameBench {

    @Param({"teapot", "patch"})
    public String scene;

    @Param({"1", "2"})
    public int threads;

    /**
     * 0 = exact; 15 = the smallest K whose teapot silhouette is within 0.5 px of the exact one
     * (docs/performance.md, report.SilhouetteAccuracy); 16 = the app's default K, the nearest offered choice.
     */
    @Param({"0", "15", "16"})
    public int tessellate;

    RenderJob job;

    @Setup
    public void setup() {
        job = FrameScenes.job(scene, threads, tessellate);
    }

    @Benchmark
    public void frame(Blackhole bh) {
        RenderResult r = Renderer.renderOnce(job);
        bh.consume(r.film());
        bh.consume(r.stats().totalRays());
    }
}
