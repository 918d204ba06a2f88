package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;
import org.beziertracer.model.RenderSettings;
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

    /** The threads of a closed session leave their workers as they end, just after close() returns. */
    private static void waitForSpares() throws InterruptedException {
        for (int i = 0; i < 200 && SpareWorkers.count() == 0; i++) {
            Thread.sleep(5);
        }
        assertTrue(SpareWorkers.count() > 0, "a closed session's threads left their workers");
    }
}
