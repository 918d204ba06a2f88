package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;

import org.beziertracer.model.RenderSettings;
import org.junit.jupiter.api.Test;

class RenderProgressTest {

    /** Records every call; fails the test if two calls overlap or a generation changes midway. */
    private static final class Recorder implements RenderProgress {
        final List<long[]> calls = new ArrayList<>();
        final AtomicBoolean inside = new AtomicBoolean();
        volatile boolean overlapped;
        RenderSession toCancel;

        @Override
        public void progress(int generation, long done, long total) {
            if (!inside.compareAndSet(false, true)) {
                overlapped = true;
            }
            calls.add(new long[] {generation, done, total});
            Thread.onSpinWait();
            if (toCancel != null) {
                toCancel.cancel();
            }
            inside.set(false);
        }
    }

    private static RenderJob job(int w, int h, int spp, String sampler, boolean progressive, int threads) {
        RenderSettings s = new RenderSettings(w, h, spp, sampler, "clipping", true, "phong", 0, true, 5);
        return TestScenes.job(TestScenes.shadows(), s).withOptions(RenderOptions.defaults().withThreads(threads)
                .withProgressive(progressive).withTileSize(16));
    }

    @Test
    void progressRisesStrictlyAndEndsAtTheTotalOfAllPlannedSamples() throws InterruptedException {
        for (String sampler : new String[] {"regular", "jittered", "adaptive"}) {
            for (boolean progressive : new boolean[] {false, true}) {
                String what = sampler + (progressive ? " progressive" : " one-shot");
                Recorder rec = new Recorder();
                try (RenderSession session = new RenderSession(2, FrameSink.NONE, rec)) {
                    session.render(job(72, 56, 5, sampler, progressive, 2));
                }
                assertFalse(rec.overlapped, "calls are serialised: " + what);
                assertFalse(rec.calls.isEmpty(), what);
                long total = rec.calls.get(0)[2];
                assertEquals(72L * 56 * 5, total, "every sample of every pixel is planned: " + what);
                long last = 0;
                for (long[] c : rec.calls) {
                    assertEquals(total, c[2], what);
                    assertTrue(c[1] > last, "done rises strictly: " + last + " then " + c[1] + ", " + what);
                    last = c[1];
                }
                assertEquals(total, last, "a finished render reports 100 %: " + what);
            }
        }
    }

    @Test
    void eachRenderOfASessionReportsItsOwnGeneration() throws InterruptedException {
        Recorder rec = new Recorder();
        int first, second;
        try (RenderSession session = new RenderSession(2, FrameSink.NONE, rec)) {
            first = session.start(job(40, 30, 1, "regular", false, 2));
            session.await();
            second = session.start(job(40, 30, 1, "regular", false, 2));
            session.await();
        }
        assertTrue(second > first);
        long[] lastOfFirst = null;
        for (long[] c : rec.calls) {
            if (c[0] == first) {
                lastOfFirst = c;
            }
        }
        long[] end = rec.calls.get(rec.calls.size() - 1);
        assertEquals(1200, lastOfFirst[1], "first render complete");
        assertEquals(second, end[0]);
        assertEquals(1200, end[1], "second render complete, counted from zero");
    }

    @Test
    void aCancelledRenderStopsShortOfTheTotal() throws InterruptedException {
        Recorder rec = new Recorder();
        try (RenderSession session = new RenderSession(1, FrameSink.NONE, rec)) {
            rec.toCancel = session;
            session.start(job(160, 120, 1, "regular", false, 1));
            assertThrows(CancellationException.class, session::await);
        }
        assertEquals(1, rec.calls.size(), "one worker stops after the tile that cancelled");
        assertTrue(rec.calls.get(0)[1] < rec.calls.get(0)[2]);
    }

    @Test
    void plannedSamplesCountEdgeTilesAndSkippedGrids() {
        PassPlan.Pass fourGrid = new PassPlan.Pass(4, 8, 0, 1, false);
        // x in 30..37: 32, 36 on the 4-grid; 32 also on the 8-grid. y in 0..2: 0 on both.
        assertEquals(2 * 1 - 1, ProgressCounter.samples(fourGrid, new int[] {30, 0, 8, 3}));
        PassPlan.Pass extra = new PassPlan.Pass(1, 0, 2, 4, false);
        assertEquals(8 * 3 * 2, ProgressCounter.samples(extra, new int[] {30, 0, 8, 3}));
        assertEquals(0, ProgressCounter.samples(new PassPlan.Pass(8, 0, 0, 1, false), new int[] {33, 9, 5, 5}),
                "no pixel of the 8-grid in 33..37 x 9..13");
    }
}
