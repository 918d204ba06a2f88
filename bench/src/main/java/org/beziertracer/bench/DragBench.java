package org.beziertracer.bench;

import java.util.concurrent.TimeUnit;

import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.BezierPatch;
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
 * What a user dragging a control point waits for between full-resolution pictures: one drag step
 * ({@link SceneIntersector#withPatch}: the patch re-split, the BVH refitted or rebuilt) and then
 * the whole {@link FrameBench} frame of the new snapshot (800×600, 1 spp, Phong + shadows, 2
 * threads). The dragged point is the middle control point of the case's first patch, moved up and
 * down by 2 % of the patch size. Sample time in ms; pictures per second while dragging =
 * 1000 / median. The app renders the same snapshot progressively (a coarse pass first), so its
 * first picture after a move comes sooner; this is the time to the full-resolution one.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SampleTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
public class DragBench {

    /** The drag case, the 10×10 grid (degree 9), and the 6×6 one. */
    @Param({"wavy10", "wavy6"})
    public String scene;

    /** 0 = exact; {@code K} = the case's equal-accuracy tessellation ({@link FrameScenes#equalK}). */
    @Param({"0", "K"})
    public String tessellate;

    RenderJob job;
    BezierPatch[] drags;
    int drag;

    @Setup
    public void setup() {
        job = FrameScenes.job(scene, 2, FrameScenes.tessellate(scene, tessellate));
        drags = Fixtures.drags(job.scene().patches().get(0));
    }

    /** One drag step and the full-resolution frame that shows it. */
    @Benchmark
    public void dragFrame(Blackhole bh) {
        SceneIntersector edited = job.intersector().withPatch(0, drags[drag++ & 7]);
        RenderResult r = Renderer.renderOnce(new RenderJob(edited, job.camera(), job.settings(), job.options()));
        bh.consume(r.film());
    }
}
