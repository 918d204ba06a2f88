package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.render.Integrator;
import org.beziertracer.render.PathOptions;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderOptions;
import org.beziertracer.render.RenderResult;
import org.beziertracer.render.RenderSession;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.infra.Blackhole;

/**
 * The path tracer's samples a second ({@code render --integrator path}: unidirectional, next-event
 * estimation with MIS, Russian roulette, depth 16) on the {@code studio} scene (gold teapot, glass
 * teacup, rect light, sky) and on {@code docs/examples/sunflow-teapot.json} (the diffuse teapot of
 * the Sunflow comparison in docs/rendering.md), each with its own camera. One operation is one
 * camera sample (a whole path with its shadow rays): each invocation renders a frame of
 * {@value #SAMPLES} samples with the jittered sampler and the default fixed seed, on one render
 * thread of a session kept for the trial (no thread start-up in the time), in one-shot passes as
 * the CLI does. Throughput, so the score is samples per second.
 *
 * <p>{@code frame}: {@code 128x96x4} (128×96 pixels, 4 samples each) or {@code 64x48x16} — the same
 * sample count, so with {@code -prof gc} the bytes per sample of the two show what a frame costs
 * (the film, 16 bytes a pixel, and the per-render set-up) against what a path costs: a per-path
 * allocation would be the same in both, a per-frame one four times larger in the first.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
public class PathBench {

    /** Samples a frame: 128 × 96 × 4 = 64 × 48 × 16. */
    public static final int SAMPLES = 128 * 96 * 4;

    /** {@code studio} (built in) or {@code sunflow-teapot} (docs/examples). */
    @Param({"studio", "sunflow-teapot"})
    public String scene;

    /** {@code WIDTHxHEIGHTxSPP}, {@value #SAMPLES} samples either way. */
    @Param({"128x96x4", "64x48x16"})
    public String frame;

    RenderJob job;
    RenderSession session;

    @Setup
    public void setup() {
        SceneDocument doc = scene(scene);
        String[] f = frame.split("x");
        int w = Integer.parseInt(f[0]), h = Integer.parseInt(f[1]), spp = Integer.parseInt(f[2]);
        if (w * h * spp != SAMPLES) {
            throw new IllegalArgumentException("frame " + frame + " is not " + SAMPLES + " samples");
        }
        RenderSettings s = doc.settings();
        RenderSettings rs = new RenderSettings(w, h, spp, "jittered", s.method(), s.bvh(), s.shading(), s.checker(),
                s.shadows(), s.maxDepth());
        RenderOptions o = RenderOptions.defaults().withThreads(1).withProgressive(false)
                .withPath(PathOptions.defaults().withIntegrator(Integrator.PATH));
        job = RenderJob.prepare(doc.scene(), rs, o);
        session = new RenderSession(1, null);
    }

    /** A built-in scene by name, else the scene file {@code docs/examples/NAME.json} (from the repository or bench/). */
    static SceneDocument scene(String name) {
        if (org.beziertracer.model.io.BuiltIns.find(name).isPresent()) {
            return org.beziertracer.model.io.SceneFiles.load(name);
        }
        for (String dir : new String[] {"docs/examples/", "../docs/examples/"}) {
            java.nio.file.Path p = java.nio.file.Path.of(dir + name + ".json");
            if (java.nio.file.Files.isRegularFile(p)) {
                return org.beziertracer.model.io.SceneFiles.load(p.toString());
            }
        }
        throw new IllegalArgumentException("no built-in or docs/examples scene " + name + " (run from the repository)");
    }

    @TearDown
    public void close() {
        session.close();
    }

    @Benchmark
    @OperationsPerInvocation(SAMPLES)
    public void samples(Blackhole bh) throws InterruptedException {
        RenderResult r = session.render(job);
        bh.consume(r.film());
        bh.consume(r.stats().totalRays());
    }
}
