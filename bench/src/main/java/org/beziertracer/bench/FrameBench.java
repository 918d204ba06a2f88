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
 * One full 800×600 frame (1 spp, Phong + shadow rays) of a reference view ({@link FrameScenes})
 * through {@link Renderer#renderOnce}, exact ({@code tessellate} 0) or as a K×K triangle mesh per
 * patch through the same BVH and shading ({@code K}: the case's equal-accuracy K,
 * {@link FrameScenes#equalK}; or a number). The job (intersector, BVH, camera) is built once per
 * trial; each operation renders a frame on a fresh {@code RenderSession} (thread start-up
 * included, as the CLI does). Sample time in ms; the median is the number to quote, and exact
 * against tessellated is compared as a ratio within one run.
 *
 * <p>{@code DegreeSweep} runs the same frame over the wavy grids of degree 1..15.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class FrameBench {

    /** The cases: the 10×10 and 6×6 wavy grids, the curved bicubic, the default patch, the teapot. */
    @Param({"wavy10", "wavy6", "curved", "patch", "teapot"})
    public String scene;

    @Param({"2"})
    public int threads;

    /** 0 = exact; {@code K} = the case's equal-accuracy K ({@link FrameScenes#equalK}); or a number. */
    @Param({"0", "K"})
    public String tessellate;

    RenderJob job;

    @Setup
    public void setup() {
        job = FrameScenes.job(scene, threads, FrameScenes.tessellate(scene, tessellate));
    }

    @Benchmark
    public void frame(Blackhole bh) {
        RenderResult r = Renderer.renderOnce(job);
        bh.consume(r.film());
        bh.consume(r.stats().totalRays());
    }
}
