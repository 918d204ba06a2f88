package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.Environment;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.beziertracer.render.Integrator;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.RenderResult;
import org.beziertracer.render.RenderSession;
import org.beziertracer.render.ToneMap;
import org.junit.jupiter.api.Test;

/**
 * Render → Path Traced without a window: the engine accumulates one sample a pixel a pass up to the
 * target, ends on the bytes of a one-shot render ({@code render --integrator path --sampler jittered
 * --spp N}), restarts on an edit, stops at a time budget, and previews while a gesture moves.
 */
class PathTracedPictureTest {

    private static final int W = 40, H = 30, SPP = 6;

    /** The teapot under a constant sky: something for the paths to find. */
    private static Scene scene() {
        return Models.teapot().toBuilder().environment(Environment.color(0.8, 0.85, 1.0)).build();
    }

    private static Settings pathTraced(int spp) {
        return Settings.defaults().with(Toggle.PATH_TRACED, true).with(Level.PATH_SAMPLES, spp);
    }

    private static RenderRequest request(Scene scene, Settings s, Picture p) {
        OrbitView view = OrbitView.fit(scene.controlBounds(), s.fovDegrees());
        return RenderRequest.of(scene, view.camera((double) W / H), view.framing(), s, p);
    }

    /** The one-shot render of the request's job, as the command line renders it, tone mapped as its PNG. */
    private static int[] oneShot(RenderRequest r) throws InterruptedException {
        return oneShot(r, 0);
    }

    /**
     * As {@link #oneShot(RenderRequest)} with {@code exposure} stops: {@code render --exposure E} writes
     * {@code ToneMap.argb(film, window, E)} (RenderCommand), this function.
     */
    private static int[] oneShot(RenderRequest r, double exposure) throws InterruptedException {
        RenderJob job = r.job(SceneIntersector.build(r.scene(), r.intersect()));
        job = job.withOptions(job.options().withProgressive(false).withThreads(1));
        try (RenderSession session = new RenderSession(1, null)) {
            RenderResult result = session.render(job);
            return ToneMap.argb(result.film(), exposure);
        }
    }

    private static void waitIdle(PictureEngine engine) throws InterruptedException {
        long end = System.nanoTime() + 60_000_000_000L;
        while (engine.busy()) {
            assertTrue(System.nanoTime() < end, "engine did not finish");
            Thread.sleep(5);
        }
    }

    private static void assertSamePicture(int[] expected, Picture p, String what) {
        int differ = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                if ((expected[y * W + x] & 0xFFFFFF) != p.rgb(x, y)) {
                    differ++;
                }
            }
        }
        assertEquals(0, differ, what + ": pixels that differ from the one-shot render");
    }

    @Test
    void theRequestPathTracesAtTheTargetSamplesWithTheJitteredSampler() {
        RenderRequest r = request(scene(), pathTraced(64), new Picture(W, H, () -> {}));
        assertEquals(Integrator.PATH, r.options().path().integrator());
        assertEquals(64, r.settings().spp());
        assertEquals("jittered", r.settings().sampler());
        RenderRequest whitted = request(scene(), Settings.defaults(), new Picture(W, H, () -> {}));
        assertEquals(Integrator.WHITTED, whitted.options().path().integrator(), "Whitted stays the default");
        RenderRequest zebra = request(scene(), pathTraced(64).withAnalysis(org.beziertracer.render.ShadingMode.ZEBRA),
                new Picture(W, H, () -> {}));
        assertEquals(Integrator.WHITTED, zebra.options().path().integrator(), "an analysis view wins");
    }

    @Test
    void samplesAccumulateOneAPassAndEndOnTheBytesOfTheOneShotRender() throws InterruptedException {
        Picture p = new Picture(W, H, () -> {});
        List<RenderStatus> seen = new CopyOnWriteArrayList<>();
        RenderRequest r = request(scene(), pathTraced(SPP), p);
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(seen::add);
            engine.submit(r);
            waitIdle(engine);
        }
        // 8-, 4-, 2- and 1-pixel grids of the first sample, then one pass a further sample
        RenderStatus last = seen.get(seen.size() - 1);
        assertEquals(4 + SPP - 1, last.passCount(), "passes");
        assertEquals(last.passCount(), last.pass(), "it ran to the end");
        assertEquals(SPP, last.samplesDone(), "samples a pixel at the end");
        assertTrue(last.samplesPerSecond() > 0, "samples/s " + last.samplesPerSecond());
        int[] spp = seen.stream().mapToInt(RenderStatus::samplesDone).toArray();
        for (int k = 1; k < spp.length; k++) {
            assertTrue(spp[k] >= spp[k - 1], "samples never go down: " + java.util.Arrays.toString(spp));
        }
        assertEquals(List.of(1, 2, 3, 4, 5, 6), seen.stream().map(RenderStatus::samplesDone).filter(n -> n > 0)
                .toList(), "one sample a pixel a pass after the first");
        assertTrue(last.samplesText().startsWith(SPP + " of " + SPP + " spp, "), last.samplesText());
        assertSamePicture(oneShot(r), p, "after " + SPP + " passes");
    }

    @Test
    void aNewExposureTonesTheFinishedFilmAgainWithoutRenderingAndGivesTheCommandLinesBytes() throws InterruptedException {
        Picture p = new Picture(W, H, () -> {});
        List<RenderStatus> seen = new CopyOnWriteArrayList<>();
        RenderRequest r = request(scene(), pathTraced(SPP), p);
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(seen::add);
            engine.submit(r);
            waitIdle(engine);
            int passes = seen.size();
            int[] atZero = p.pixels().clone();
            engine.exposure(1.5);
            waitIdle(engine);
            assertEquals(passes, seen.size(), "no pass rendered again: the film was tone mapped, not restarted");
            assertSamePicture(oneShot(r, 1.5), p, "+1.5 EV, as render --exposure 1.5");
            int brighter = 0;
            for (int k = 0; k < atZero.length; k++) {
                brighter += (atZero[k] & 0xFF) < (p.pixels()[k] & 0xFF) ? 1 : 0;
            }
            assertTrue(brighter > atZero.length / 2, "brighter: " + brighter + " of " + atZero.length + " pixels");
            engine.exposure(-3);
            engine.exposure(0);
            waitIdle(engine);
            assertEquals(passes, seen.size(), "still no pass rendered again");
            assertSamePicture(oneShot(r, 0), p, "back at 0 EV");
        }
    }

    @Test
    void aNewExposureWhileTheSamplesAccumulateKeepsThemAndEndsOnTheCommandLinesBytes() throws InterruptedException {
        int spp = 48;
        Picture p = new Picture(W, H, () -> {});
        List<RenderStatus> seen = new CopyOnWriteArrayList<>();
        RenderRequest r = request(scene(), pathTraced(spp), p);
        int changedAt;
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(seen::add);
            engine.submit(r);
            long end = System.nanoTime() + 60_000_000_000L;
            while (seen.isEmpty() || seen.get(seen.size() - 1).samplesDone() < 2) {
                assertTrue(System.nanoTime() < end, "the picture refines");
                Thread.sleep(1);
            }
            changedAt = seen.get(seen.size() - 1).samplesDone();
            engine.exposure(-1.2);
            waitIdle(engine);
        }
        int[] spps = seen.stream().mapToInt(RenderStatus::samplesDone).toArray();
        for (int k = 1; k < spps.length; k++) {
            assertTrue(spps[k] >= spps[k - 1], "the samples never start again: " + java.util.Arrays.toString(spps));
        }
        assertTrue(changedAt < spp, "changed while refining (at " + changedAt + " spp)");
        assertEquals(spp, seen.get(seen.size() - 1).samplesDone(), "it refined on to the target");
        assertEquals(4 + spp - 1, seen.size(), "every pass once: nothing rendered twice");
        assertSamePicture(oneShot(r, -1.2), p, "-1.2 EV, as render --exposure -1.2");
    }

    @Test
    void anExposureChangeAloneIsNoNewRequestAndIsRemembered() {
        FakeEngine engine = new FakeEngine();
        AppPreferences prefs = MemoryPreferences.fresh();
        AppModel app = new AppModel(engine, new FakeDialogs(), AppThreads.direct(), prefs);
        app.view().resize(W, H, 1);
        app.settings().replace(pathTraced(64));
        int requests = engine.requests.size();
        assertEquals(0, last(engine).options().path().exposure(), "0 EV at first");
        app.settings().step(Level.EXPOSURE, Level.EXPOSURE_STEP);
        app.settings().step(Level.EXPOSURE, Level.EXPOSURE_STEP);
        app.settings().step(Level.EXPOSURE, 5);
        assertEquals(requests, engine.requests.size(), "no new render: the picture is tone mapped again");
        assertEquals(List.of(0.5, 1.0, 1.5), engine.exposures, "the engine hears each exposure");
        assertEquals(15, prefs.exposureTenths(), "remembered");
        app.settings().toggle(Toggle.SHADOWS);
        assertEquals(requests + 1, engine.requests.size(), "another change renders again");
        assertEquals(1.5, last(engine).options().path().exposure(), "with the exposure");
        app.settings().step(Level.EXPOSURE, 100);
        assertEquals(5.0, app.settings().current().exposure(), "at most +5 stops");
        app.settings().set(Level.EXPOSURE, 0);
        assertEquals(requests + 1, engine.requests.size());
        app.settings().set(Level.EXPOSURE, -35);
        app.close();

        FakeEngine next = new FakeEngine();
        AppModel again = new AppModel(next, new FakeDialogs(), AppThreads.direct(), prefs);
        again.view().resize(W, H, 1);
        again.settings().set(Toggle.PATH_TRACED, true);
        assertEquals(-3.5, again.settings().current().exposure(), "the next run starts at the exposure last chosen");
        assertEquals(-3.5, last(next).options().path().exposure(), "and renders with it");
        again.close();
    }

    @Test
    void anEditRestartsTheAccumulationAndEndsOnTheEditedScene() throws InterruptedException {
        Picture p = new Picture(W, H, () -> {});
        List<RenderStatus> seen = new CopyOnWriteArrayList<>();
        Scene before = scene();
        Scene after = before.withPatch(0, before.patches().get(0).withPoint(1, 1, 0, 0, 0));
        RenderRequest edited = request(after, pathTraced(SPP), p);
        int restartedAt;
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(seen::add);
            engine.submit(request(before, pathTraced(1024), p));
            long end = System.nanoTime() + 60_000_000_000L;
            while (seen.isEmpty() || seen.get(seen.size() - 1).samplesDone() < 2) {
                assertTrue(System.nanoTime() < end, "the first picture refines");
                Thread.sleep(2);
            }
            restartedAt = seen.size();
            engine.submit(edited);
            waitIdle(engine);
        }
        List<RenderStatus> later = seen.subList(restartedAt, seen.size());
        RenderStatus last = seen.get(seen.size() - 1);
        assertEquals(SPP, last.spp(), "the newest request ran to its end");
        assertEquals(SPP, last.samplesDone());
        assertTrue(later.stream().anyMatch(s -> s.spp() == SPP && s.samplesDone() == 0),
                "the edited picture started again from its first sample");
        assertFalse(later.stream().anyMatch(s -> s.spp() == 1024 && s.samplesDone() >= 1024), "the old one was cancelled");
        assertSamePicture(oneShot(edited), p, "the edited scene");
    }

    @Test
    void aTimeBudgetStopsTheRefinementEarlyAndTheEngineGoesIdle() throws InterruptedException {
        Picture p = new Picture(W, H, () -> {});
        List<RenderStatus> seen = new CopyOnWriteArrayList<>();
        RenderRequest r = request(scene(), pathTraced(1024).with(Level.PATH_SECONDS, 1), p);
        assertEquals(1000, r.options().path().budgetMillis());
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(seen::add);
            engine.submit(r);
            waitIdle(engine);
        }
        RenderStatus last = seen.get(seen.size() - 1);
        assertEquals(last.passCount(), last.pass(), "the pass that spent the budget is reported as the last");
        assertTrue(last.samplesDone() >= 1 && last.samplesDone() < 1024, "stopped early at " + last.samplesDone() + " spp");
        assertTrue(last.millis() >= 1000, "not before the budget: " + last.millis() + " ms");
    }

    @Test
    void aTurnOfTheViewPreviewsOneSampleAndRefinesAgainWhenReleased() {
        FakeEngine engine = new FakeEngine();
        AppModel app = pathTracedApp(engine, 64);
        assertEquals(64, last(engine).settings().spp(), "refining to the target");
        int before = engine.requests.size();
        app.pointer().pressed(5, 5);
        assertEquals(before, engine.requests.size(), "a press alone changes nothing");
        app.pointer().dragged(15, 8);
        assertEquals(1, last(engine).settings().spp(), "one sample a pixel while turning");
        assertTrue(last(engine).pathTraced(), "still path traced");
        app.pointer().dragged(25, 9);
        assertEquals(1, last(engine).settings().spp());
        int moved = engine.requests.size();
        app.pointer().released(25, 9);
        assertEquals(moved + 1, engine.requests.size(), "released: one request");
        assertEquals(64, last(engine).settings().spp(), "refining again");
        app.pointer().pressed(5, 5);
        app.pointer().released(5, 5);
        assertEquals(moved + 1, engine.requests.size(), "a click without motion does not restart the picture");
        app.close();
    }

    @Test
    void theStudioOpensLitByItsOwnAreaLightAndSky() {
        FakeEngine engine = new FakeEngine();
        AppModel app = pathTracedApp(engine, 16);
        app.files().openBuiltIn("studio");
        assertEquals(58, app.document().scene().patchCount(), "teapot and teacup");
        assertEquals(LightPlacement.SCENE, app.settings().current().light(), "its own light, no placed point light");
        RenderRequest r = last(engine);
        assertEquals(58, r.scene().patchCount());
        assertEquals(null, r.lights(), "the scene's lights: one rect light and the sky");
        assertTrue(r.pathTraced(), "still path traced");
        app.files().openBuiltIn("teapot");
        assertEquals(1, last(engine).lights().size(), "a model without lights gets the placed light again");
        app.close();
    }

    /** The app without a window (direct threads, {@code engine} recording), path traced to {@code spp}. */
    private static AppModel pathTracedApp(FakeEngine engine, int spp) {
        AppModel app = new AppModel(engine, new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());
        app.view().resize(W, H, 1);
        app.settings().replace(pathTraced(spp));
        return app;
    }

    private static RenderRequest last(FakeEngine e) {
        return e.requests.get(e.requests.size() - 1);
    }
}
