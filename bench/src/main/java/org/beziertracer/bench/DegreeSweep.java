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
 * Cost versus degree: the {@link FrameBench} frame of the wavy grid of degree 1..15
 * ({@code wavy2} … {@code wavy16}: fit camera, light at the eye, 800×600, 1 spp, Phong), exact
 * ({@code tessellate} 0) and tessellated at the degree's equal-accuracy K ({@code K},
 * {@link FrameScenes#equalK}). Sample time in ms per frame; quote the median.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class DegreeSweep {

    @Param({"1", "2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12", "13", "14", "15"})
    public int degree;

    @Param({"2"})
    public int threads;

    @Param({"0", "K"})
    public String tessellate;

    RenderJob job;

    @Setup
    public void setup() {
        String name = "wavy" + (degree + 1);
        job = FrameScenes.job(name, threads, FrameScenes.tessellate(name, tessellate));
    }

    @Benchmark
    public void frame(Blackhole bh) {
        RenderResult r = Renderer.renderOnce(job);
        bh.consume(r.film());
        bh.consume(r.stats().totalRays());
    }
}
