package org.beziertracer.render;

import static org.beziertracer.Tolerances.FLOAT;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.ref.WeakReference;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class RenderSessionTest {

    private static RenderJob mirrorJob(int w, int h, int spp, String sampler, boolean progressive) {
        RenderSettings s = new RenderSettings(w, h, spp, sampler, "clipping", true, "phong", 0, true, 5);
        return TestScenes.job(TestScenes.reflection(), s)
                .withOptions(RenderOptions.defaults().withThreads(2).withProgressive(progressive).withTileSize(16));
    }

    /** Found with the app's path-traced mode: a job file's seed turned its path tracer back into Whitted. */
    @Test
    void aNewSeedKeepsThePathTracersOptions() {
        PathOptions p = PathOptions.defaults().withIntegrator(Integrator.PATH).withClamp(4).withBudgetMillis(500);
        RenderOptions o = RenderOptions.defaults().withPath(p).withSeed(7);
        assertEquals(p, o.path());
        assertEquals(7, o.seed());
    }

    /** Path traced and progressive: one sample a pass after the first, every pass shown tone mapped, a budget ends it early. */
    @Test
    void aProgressivePathTracedRenderRefinesOneSampleAPassAndStopsAtItsBudget() throws InterruptedException {
        Scene scene = TestScenes.reflection();
        RenderSettings rs = new RenderSettings(32, 24, 5, "jittered", "clipping", true, "phong", 0, true, 5);
        PathOptions path = PathOptions.defaults().withIntegrator(Integrator.PATH).withExposure(1);
        RenderJob job = RenderJob.prepare(scene, rs, RenderOptions.defaults().withThreads(2).withPath(path)
                .withPassesPerFrame(4));
        java.util.List<Integer> passCounts = new java.util.concurrent.CopyOnWriteArrayList<>();
        int[] shown = new int[32 * 24];
        FrameSink sink = new FrameSink() {
            @Override
            public synchronized void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
                for (int j = 0; j < h; j++) {
                    System.arraycopy(argb, j * stride, shown, (y0 + j) * 32 + x0, w);
                }
            }

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {
                passCounts.add(passCount);
            }
        };
        RenderResult r;
        try (RenderSession session = new RenderSession(2, sink)) {
            r = session.render(job);
        }
        assertEquals(4 + 4, passCounts.size(), "four first-sample passes, then one a further sample");
        assertArrayEquals(ToneMap.argb(r.film(), 1), shown, "every pass shown (interactivity ignored), tone mapped at 1 EV");
        RenderJob slow = job.withOptions(job.options().withPath(path.withBudgetMillis(1)));
        passCounts.clear();
        try (RenderSession session = new RenderSession(2, sink)) {
            r = session.render(slow);
        }
        assertEquals(5, passCounts.size(), "stopped after the first extra pass: " + passCounts);
        assertEquals(5, passCounts.get(4), "which says it is the last");
        assertEquals(2, r.film().sampleCount(0, 0), "two samples a pixel");
    }

    @Test
    void progressivePassesEndOnExactlyTheOneShotImage() {
        for (String sampler : new String[] {"regular", "jittered", "adaptive"}) {
            RenderResult once = Renderer.renderOnce(mirrorJob(72, 56, 4, sampler, false));
            List<Integer> passes = Collections.synchronizedList(new ArrayList<>());
            AtomicInteger tiles = new AtomicInteger();
            FrameSink sink = new FrameSink() {
                @Override
                public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
                    tiles.incrementAndGet();
                }

                @Override
                public void passDone(int generation, int pass, int passCount, FrameStats stats) {
                    passes.add(pass);
                }
            };
            RenderResult progressive = Renderer.renderOnce(mirrorJob(72, 56, 4, sampler, true), sink);
            assertArrayEquals(once.film().linearRgb(), progressive.film().linearRgb(), sampler);
            assertArrayEquals(once.argb(), progressive.argb(), sampler);
            assertEquals(once.stats().primaryRays(), progressive.stats().primaryRays(),
                    "each first sample is traced once: " + sampler);
            int expectedPasses = 4 + (sampler.equals("adaptive") ? 1 : 2); // 8,4,2,1 + extra samples
            assertEquals(expectedPasses, passes.size(), sampler);
            assertEquals(expectedPasses * 5 * 4, tiles.get(), "every pass shows every 16-pixel tile");
        }
    }

    @Test
    void aCoarsePassFillsEachBlockWithItsAnchorPixel() {
        RenderJob job = mirrorJob(64, 48, 1, "regular", true).withOptions(RenderOptions.defaults().withThreads(1)
                .withTileSize(64));
        int[][] first = new int[1][];
        try (RenderSession session = new RenderSession(1, new FrameSink() {
            @Override
            public synchronized void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
                if (first[0] == null) {
                    first[0] = argb.clone();
                }
            }

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {}
        })) {
            RenderResult r = session.render(job);
            assertEquals(64 * 48, r.stats().primaryRays());
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                assertEquals(first[0][(y - y % 8) * 64 + x - x % 8], first[0][y * 64 + x], "pixel " + x + "," + y);
            }
        }
    }

    @Test
    void aSinkThatWantsNoTilesGetsNoneAndTheSameImage() {
        AtomicInteger tiles = new AtomicInteger();
        FrameSink quiet = new FrameSink() {
            @Override
            public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
                tiles.incrementAndGet();
            }

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {}

            @Override
            public boolean wantsTiles() { return false; }
        };
        RenderResult skipped = Renderer.renderOnce(mirrorJob(48, 32, 2, "regular", true), quiet);
        assertEquals(0, tiles.get(), "no tile is encoded for a sink that wants none");
        assertFalse(FrameSink.NONE.wantsTiles(), "the benchmark and command-line sink wants no tiles");
        RenderResult shown = Renderer.renderOnce(mirrorJob(48, 32, 2, "regular", true), new FrameSink() {
            @Override
            public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {}

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {}
        });
        assertArrayEquals(shown.argb(), skipped.argb());
    }

    @Test
    void onlyAnAdaptiveRenderKeepsTheFirstSamplesApart() {
        for (String sampler : new String[] {"regular", "jittered", "adaptive"}) {
            for (int spp : new int[] {1, 4}) {
                RenderResult r = Renderer.renderOnce(mirrorJob(24, 16, spp, sampler, false));
                boolean kept = r.film().first != null;
                assertEquals(sampler.equals("adaptive") && spp > 1, kept, sampler + " spp " + spp);
            }
        }
        Film film = new Film(2, 1, false);
        film.addSample(0, 0, 0.25, 0.5, 0.75);
        film.addSample(0, 0, 0.75, 0.5, 0.25);
        float[] px = new float[3];
        film.pixel(0, 0, px);
        assertArrayEquals(new float[] {0.5f, 0.5f, 0.5f}, px, "averages without the first-sample copy");
        assertEquals(2, film.sampleCount(0, 0));
    }

    @Test
    void jitteredRendersRepeatExactly() {
        RenderResult a = Renderer.renderOnce(mirrorJob(40, 30, 4, "jittered", false));
        RenderResult b = Renderer.renderOnce(mirrorJob(40, 30, 4, "jittered", true).withOptions(
                RenderOptions.defaults().withThreads(1).withProgressive(false)));
        assertArrayEquals(a.film().linearRgb(), b.film().linearRgb());
    }

    @Test
    void adaptiveSamplingAddsSamplesOnlyWhereNeighboursDiffer() {
        RenderSettings s = new RenderSettings(64, 48, 9, "adaptive", "clipping", true, "phong", 0, true, 5);
        RenderResult r = Renderer.renderOnce(TestScenes.job(TestScenes.shadows(), s));
        long pixels = 64 * 48;
        long primary = r.stats().primaryRays();
        assertTrue(primary > pixels && primary < 9 * pixels / 2, "primary rays " + primary);
        assertEquals(1, r.film().sampleCount(0, 0), "flat background corner keeps one sample");
    }

    @Test
    void cancellingMidFrameLeavesNoWorkerRunning() throws Exception {
        RenderSettings s = new RenderSettings(640, 480, 16, "jittered", "clipping", true, "phong", 0, true, 5);
        RenderJob job = RenderJob.prepare(Models.teapot(), s, RenderOptions.defaults().withThreads(2));
        CountDownLatch firstTile = new CountDownLatch(1);
        AtomicInteger lastPass = new AtomicInteger(-1);
        try (RenderSession session = new RenderSession(2, new FrameSink() {
            @Override
            public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {
                firstTile.countDown();
            }

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {
                lastPass.set(pass);
            }
        })) {
            int gen = session.start(job);
            assertTrue(firstTile.await(30, TimeUnit.SECONDS), "no tile within 30 s");
            session.cancel();
            assertTrue(session.generation() > gen);
            assertTrue(session.awaitIdle(5, TimeUnit.SECONDS), "workers still running after cancel");
            assertEquals(0, session.activeWorkers());
            assertThrows(CancellationException.class, session::await);
            assertTrue(lastPass.get() < PassPlan.of(true, SamplerKind.JITTERED, 16).size() - 1, "it did not finish");
        }
    }

    @Test
    void aNewStartSupersedesTheRenderInProgress() throws Exception {
        RenderSettings big = new RenderSettings(640, 480, 16, "jittered", "clipping", true, "phong", 0, true, 5);
        RenderJob slow = RenderJob.prepare(Models.teapot(), big, RenderOptions.defaults().withThreads(2));
        RenderJob quick = mirrorJob(32, 24, 1, "regular", false);
        List<Integer> finished = Collections.synchronizedList(new ArrayList<>());
        try (RenderSession session = new RenderSession(2, new FrameSink() {
            @Override
            public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {}

            @Override
            public void passDone(int generation, int pass, int passCount, FrameStats stats) {
                if (pass == passCount - 1) {
                    finished.add(generation);
                }
            }
        })) {
            int g1 = session.start(slow);
            int g2 = session.start(quick);
            RenderResult r = session.await();
            assertEquals(32, r.film().width());
            assertTrue(session.awaitIdle(5, TimeUnit.SECONDS));
            assertEquals(List.of(g2), finished, "only the newest generation " + g2 + " finishes, not " + g1);
        }
    }

    /**
     * Found by the app soak: after a big model, a small picture rendered by fewer workers than the
     * pool holds left the idle workers bound to the big model's snapshot, so it stayed in the heap.
     */
    @Test
    void idleWorkersLetGoOfAFinishedRendersScene() throws InterruptedException {
        RenderSettings s = new RenderSettings(128, 96, 1, "regular", "clipping", true, "phong", 0, true, 5);
        RenderJob first = TestScenes.job(TestScenes.teapot(), s)
                .withOptions(RenderOptions.defaults().withThreads(4).withTileSize(16));
        WeakReference<SceneIntersector> firstSnapshot = new WeakReference<>(first.intersector());
        try (RenderSession session = new RenderSession(4, FrameSink.NONE)) {
            session.render(first);
            first = null;
            session.render(mirrorJob(8, 8, 1, "regular", false)); // one tile: one worker renders it
            for (int k = 0; k < 50 && firstSnapshot.get() != null; k++) {
                System.gc();
                Thread.sleep(20);
            }
            assertNull(firstSnapshot.get(), "the first render's snapshot is unreachable once the second is done");
        }
    }

    @Test
    void theTeapotHasNoNanPixels() {
        for (String shading : new String[] {"phong", "normals"}) {
            RenderSettings s = new RenderSettings(96, 72, 1, "regular", "clipping", true, shading, 0, true, 5);
            RenderJob job = RenderJob.prepare(Models.teapot(), s, RenderOptions.defaults().withThreads(2));
            for (Camera c : new Camera[] {job.camera(), job.camera().orbit(0, 60), job.camera().orbit(140, -30)}) {
                float[] film = Renderer.renderOnce(job.withCamera(c)).film().linearRgb();
                for (int k = 0; k < film.length; k++) {
                    assertTrue(Float.isFinite(film[k]), shading + " " + c + ": NaN at pixel " + k / 3);
                }
            }
        }
    }

    @Test
    void pixelProbeReturnsTheRenderedPixel() {
        RenderJob job = mirrorJob(48, 36, 4, "jittered", false);
        RenderResult r = Renderer.renderOnce(job);
        List<String> lines = new ArrayList<>();
        double[] rgb = PixelProbe.trace(job, 30, 20, lines::add);
        float[] px = new float[3];
        r.film().pixel(30, 20, px);
        for (int c = 0; c < 3; c++) {
            assertEquals(px[c], rgb[c], FLOAT);
        }
        assertTrue(lines.stream().anyMatch(l -> l.contains("hit ")), String.join("\n", lines));
    }
}
