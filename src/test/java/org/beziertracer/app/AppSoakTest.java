package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/**
 * The soak without a display: the app layer with its real threads and the real render engine, a
 * single-thread executor standing in for the event thread, and a few thousand seeded random
 * commands (see {@link SoakActions}) issued in bursts faster than frames complete, every other round
 * with the path tracer on throughout (edits, view and exposure changes while samples accumulate). Then: nothing
 * escaped on any thread and no error reached the dialogs; once idle, the picture equals a fresh
 * render of the final state pixel for pixel (path traced: through the tone map at the final exposure); the heap is within 2× of what it was after the first
 * model load. The GUI soak ({@code AppSoakGuiTest}) does the same through the window.
 */
class AppSoakTest {

    /** Checkpoints: after each round of commands the app must go idle on a fresh render of its state. */
    static final int ROUNDS = 8;
    /** Commands issued (a shorter run than the GUI soak's). */
    static final int COMMANDS = Integer.getInteger("soak.commands", 2000);
    /** The model loaded first, and again at the end before the heap is measured. */
    static final String FIRST_MODEL = "teapot-room";
    /** Picture size in device pixels. */
    static final int WIDTH = 160, HEIGHT = 120;

    /** Commands of a path-traced round issued between two waits for the picture to refine. */
    static final int PATH_CHUNK = 50;

    /**
     * What the engine reports, pass by pass (on its coordinator thread, one pass after another): the
     * passes of a path-traced picture past its first sample, and the pictures a change restarted
     * while they were there (a report of a new render's first pass after such a pass).
     */
    static final class Accumulation {
        final java.util.concurrent.atomic.AtomicInteger refiningPasses = new java.util.concurrent.atomic.AtomicInteger();
        final java.util.concurrent.atomic.AtomicInteger interrupted = new java.util.concurrent.atomic.AtomicInteger();
        private RenderStatus previous;

        void heard(RenderStatus s) {
            boolean refining = s.pathTraced() && s.samplesDone() >= 1 && s.pass() < s.passCount();
            if (refining) {
                refiningPasses.incrementAndGet();
            }
            RenderStatus p = previous;
            if (p != null && s.pass() <= p.pass() && p.pathTraced() && p.samplesDone() >= 1 && p.pass() < p.passCount()) {
                interrupted.incrementAndGet(); // a new render began while the last one refined
            }
            previous = s;
        }
    }

    /**
     * Ends the gesture in progress, brings the ray trace back ({@link SoakActions#finish}) and renders
     * the picture again, then waits (up to 10 s) until it refines past its first sample, so that the
     * next burst of commands lands on accumulating samples.
     */
    private static void refine(SoakChecks.OnUi onUi, AppModel app, SoakActions actions, Accumulation accumulation)
            throws Exception {
        int before = accumulation.refiningPasses.get();
        onUi.call(() -> {
            actions.finish();
            app.render();
            return null;
        });
        long end = System.nanoTime() + 10_000_000_000L;
        while (System.nanoTime() < end && accumulation.refiningPasses.get() == before) {
            Thread.sleep(2);
        }
    }

    @Test
    void thousandsOfRandomCommandsEndOnFreshRendersWithNoErrorAndABoundedHeap() throws Exception {
        long seed = SoakChecks.seed("AppSoakTest");
        long t0 = System.nanoTime();
        ExecutorService uiThread = Executors.newSingleThreadExecutor(r -> new Thread(r, "soak-ui"));
        SoakChecks.OnUi onUi = new SoakChecks.OnUi() {
            @Override
            public <T> T call(Callable<T> task) throws Exception {
                return uiThread.submit(task).get(60, TimeUnit.SECONDS);
            }
        };
        // Dialogs that record errors and answer "discard" to the unsaved-edits question
        FakeDialogs dialogs = new FakeDialogs();
        dialogs.discard = UserDialogs.Choice.DISCARD;
        try (SoakChecks.Uncaught uncaught = SoakChecks.Uncaught.install()) {
            RayTraceEngine engine = new RayTraceEngine();
            Accumulation accumulation = new Accumulation();
            AppModel app = onUi.call(() -> {
                AppModel a = new AppModel(engine, dialogs, AppThreads.start(uiThread), MemoryPreferences.fresh());
                engine.onStatus(s -> {
                    accumulation.heard(s);
                    a.status().report(s);
                });
                a.view().resize(WIDTH, HEIGHT, 1);
                a.files().openBuiltIn(FIRST_MODEL);
                return a;
            });
            try {
                assertTrue(SoakChecks.awaitIdle(onUi, app::busy, 30_000), "the first model loads");
                long heapAfterLoad = SoakChecks.settledHeap();
                SoakActions actions = new SoakActions(app, seed, () -> {}, true);
                Random pace = new Random(seed ^ 0x5DEECE66DL);
                SoakChecks.Final last = null;
                int refining = 0;
                for (int round = 1; round <= ROUNDS; round++) {
                    // even rounds are path traced throughout: the commands land while samples accumulate
                    boolean path = round % 2 == 0;
                    onUi.call(() -> {
                        actions.pathTraced(path);
                        return null;
                    });
                    int before = accumulation.interrupted.get();
                    if (path) {
                        // in chunks, each after the picture has refined past its first sample: the next
                        // burst's edits then land on samples that accumulate
                        for (int issued = 0; issued < COMMANDS / ROUNDS; issued += PATH_CHUNK) {
                            refine(onUi, app, actions, accumulation);
                            actions.issue(uiThread, Math.min(PATH_CHUNK, COMMANDS / ROUNDS - issued), pace);
                        }
                    } else {
                        actions.issue(uiThread, COMMANDS / ROUNDS, pace);
                    }
                    last = SoakChecks.idleState(onUi, app, actions, 40_000);
                    String where = " (round " + round + " of " + ROUNDS + (path ? ", path traced" : "") + ", seed " + seed + ")";
                    if (path) {
                        int during = accumulation.interrupted.get() - before;
                        refining += during;
                        assertTrue(last.settings().pathTraced(), "the round ends path traced" + where);
                        assertTrue(during > 0, "changes landed while a path-traced picture refined" + where);
                    }
                    assertEquals(List.of(), uncaught.seen(), "no exception escaped on any thread" + where);
                    assertEquals(List.of(), dialogs.errors(), "no error reached the dialogs (render, prep, edit, load)" + where);
                    assertNull(last.mismatch(last.freshRender()), "the picture is a fresh render of the state" + where);
                }
                long checked = System.nanoTime();
                onUi.call(() -> {
                    app.settings().replace(Settings.defaults());
                    app.files().openBuiltIn(FIRST_MODEL);
                    return null;
                });
                assertTrue(SoakChecks.awaitIdle(onUi, app::busy, 30_000), "the first model loads again");
                long heapAfterRun = SoakChecks.settledHeap();
                System.out.printf("AppSoakTest: %d commands (%s; %d path-traced pictures restarted past their first sample) and %d checkpoints "
                                + "in %.1f s; %d discards; heap %.1f MB after the first load, %.1f MB after the run; total %.1f s; "
                                + "last state %s%n",
                        actions.total(), onUi.call(actions::summary), refining, ROUNDS, (checked - t0) / 1e9, dialogs.prompts,
                        heapAfterLoad / 1e6, heapAfterRun / 1e6, (System.nanoTime() - t0) / 1e9, last.describe());
                assertTrue(heapAfterRun <= 2 * heapAfterLoad, "heap " + heapAfterRun + " after the run, "
                        + heapAfterLoad + " after the first load (seed " + seed + ")");
            } finally {
                onUi.call(() -> {
                    app.close();
                    return null;
                });
            }
        } finally {
            uiThread.shutdownNow();
        }
    }
}
