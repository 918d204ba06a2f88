package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;
import org.junit.jupiter.api.Test;

/**
 * A one-shot render on a fresh session takes the scratch its threads need from the sessions closed
 * before it ({@link SpareWorkers}) instead of allocating it again, and renders exactly what a new
 * worker renders: the same floats and the same counted work.
 */
class SpareWorkersTest {

    private static RenderJob job(LaneKernel kernel) {
        RenderSettings s = new RenderSettings(48, 36, 1, "regular", "clipping", true, "phong", 0, true, 5);
        return RenderJob.prepare(TestScenes.shadows(), s, RenderOptions.defaults().withThreads(2)
                .withProgressive(false).withTileSize(16).withKernel(kernel));
    }

    @Test
    void aFreshSessionReusesTheWorkersOfClosedOnesAndRendersTheSame() throws InterruptedException {
        RenderJob job = job(Kernels.best());
        RenderResult first = Renderer.renderOnce(job);
        waitForSpares();
        int before = SpareWorkers.reuses();
        RenderResult second = Renderer.renderOnce(job);
        assertTrue(SpareWorkers.reuses() > before, "the second session's threads took spare workers");
        assertArrayEquals(first.film().linearRgb(), second.film().linearRgb(), "the same picture from a reused worker");
        assertEquals(first.stats().work(), second.stats().work(), "the same work counted, none carried over");
        assertEquals(first.stats().shadowRays(), second.stats().shadowRays());
        assertTrue(SpareWorkers.count() <= SpareWorkers.LIMIT, "at most LIMIT spares: " + SpareWorkers.count());
    }

    @Test
    void aWorkerServesOnlyJobsOfItsOwnKernel() {
        LaneKernel scalar = Kernels.scalar(), simd = Kernels.named("simd");
        RenderWorker w = new RenderWorker(job(scalar).intersector());
        assertTrue(w.fits(job(scalar)));
        assertFalse(w.fits(job(simd)), "a scalar worker must not serve a SIMD job");
    }

    /**
     * A one-thread render on a reused worker counts the work a new worker counts, also after the
     * worker served renders of other scenes and of the same one (their shadow rays fill OriginLeaf's
     * per-thread memory of failed proofs, which changes later work, never answers).
     */
    @Test
    void aReusedWorkerCountsTheWorkOfANewOne() throws InterruptedException {
        RenderJob job = teapotWithShadows();
        for (String other : new String[] {"curved", "wavy10", "teapot-room"}) {
            Renderer.renderOnce(RenderJob.prepare(SceneFiles.load(other).scene(), job.settings(), job.options()));
        }
        Renderer.renderOnce(job);
        waitForSpares();
        int before = SpareWorkers.reuses();
        FrameStats reused = Renderer.renderOnce(job).stats();
        assertTrue(SpareWorkers.reuses() > before, "the render's thread took a spare worker");
        assertEquals(freshWorker(job).work(), reused.work(), "the work of a new worker");
        assertTrue(reused.shadowRays() > 1000, "shadow rays: " + reused.shadowRays());
    }

    private static RenderJob teapotWithShadows() {
        SceneDocument doc = SceneFiles.load("teapot");
        Scene scene = doc.scene().toBuilder().lights(List.of(new PointLight(new Vec3(-200, -350, 450)))).build();
        RenderSettings s = doc.settings();
        RenderSettings settings = new RenderSettings(160, 120, 1, s.sampler(), s.method(), s.bvh(), "phong",
                s.checker(), true, s.maxDepth());
        return RenderJob.prepare(scene, settings, RenderOptions.defaults().withThreads(1).withProgressive(false))
                .withCamera(Camera.lookAt(new Vec3(-150, -420, 260), new Vec3(10, 0, 55), new Vec3(0, 0, 1), 40));
    }

    /** The frame's stats rendered tile by tile by a new {@link RenderWorker}, as the session's thread renders it. */
    private static FrameStats freshWorker(RenderJob job) {
        List<int[]> tiles = RenderSession.tiles(job.width(), job.height(), job.options().tileSize());
        List<PassPlan.Pass> passes = PassPlan.of(false, job.sampler(), 1);
        RenderState st = new RenderState(0, job, FrameSink.NONE, new AtomicInteger(0),
                new ProgressCounter(RenderProgress.NONE, 0, passes, tiles));
        RenderWorker worker = new RenderWorker(job.intersector());
        for (PassPlan.Pass pass : passes) {
            for (int[] t : tiles) {
                assertTrue(worker.renderTile(st, pass, t[0], t[1], t[2], t[3], false));
            }
        }
        return st.stats();
    }

    /** The threads of a closed session leave their workers as they end, just after close() returns. */
    private static void waitForSpares() throws InterruptedException {
        for (int i = 0; i < 200 && SpareWorkers.count() == 0; i++) {
            Thread.sleep(5);
        }
        assertTrue(SpareWorkers.count() > 0, "a closed session's threads left their workers");
    }
}
