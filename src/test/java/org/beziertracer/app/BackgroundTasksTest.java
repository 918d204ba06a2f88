package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.RenderSettings;
import org.junit.jupiter.api.Test;

/** Work off the UI thread, with a real worker thread and a UI queue the test drains. */
class BackgroundTasksTest {

    private final BlockingQueue<Runnable> uiQueue = new LinkedBlockingQueue<>();

    /** Runs UI jobs until {@code done} holds (or fails after 20 s). */
    private void runUiUntil(java.util.function.BooleanSupplier done) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!done.getAsBoolean()) {
            Runnable r = uiQueue.poll(50, TimeUnit.MILLISECONDS);
            if (r != null) {
                r.run();
            }
            assertTrue(System.nanoTime() < end, "timed out");
        }
    }

    @Test
    void cancellingInterruptsTheWorkAndReportsCancellationOnTheUiThread() throws Exception {
        ExecutorService worker = Executors.newSingleThreadExecutor();
        try {
            BackgroundTasks tasks = new BackgroundTasks(worker, uiQueue::add);
            CountDownLatch started = new CountDownLatch(1);
            Throwable[] outcome = new Throwable[1];
            Task t = tasks.submit("sleeping", () -> {
                started.countDown();
                Thread.sleep(60_000);
                return "woke";
            }, r -> outcome[0] = new AssertionError("done with " + r), e -> outcome[0] = e);
            assertTrue(started.await(10, TimeUnit.SECONDS));
            assertTrue(tasks.busy());
            t.cancel();
            runUiUntil(() -> outcome[0] != null);
            assertTrue(outcome[0] instanceof CancellationException, String.valueOf(outcome[0]));
            assertFalse(tasks.busy());
            // The worker is not left interrupted: the next task runs normally
            String[] next = new String[1];
            tasks.submit("next", () -> {
                Thread.sleep(1);
                return "ok";
            }, r -> next[0] = r, e -> next[0] = e.toString());
            runUiUntil(() -> next[0] != null);
            assertEquals("ok", next[0]);
        } finally {
            worker.shutdownNow();
        }
    }

    @Test
    void aCancelledOpenKeepsTheCurrentModelAndClearsTheProgress() throws Exception {
        ExecutorService io = Executors.newSingleThreadExecutor();
        try {
            AppThreads threads = new AppThreads(uiQueue::add, Runnable::run, io, Runnable::run, Runnable::run, Runnable::run);
            AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), threads, MemoryPreferences.fresh());
            Scene before = app.document().scene();
            CountDownLatch started = new CountDownLatch(1);
            app.files().open("big", () -> {
                started.countDown();
                Thread.sleep(60_000);
                return new SceneDocument(Models.teapot(), RenderSettings.defaults());
            });
            Task task = app.status().task();
            assertNotNull(task, "the status bar shows the load");
            assertEquals("opening big", task.label());
            assertTrue(started.await(10, TimeUnit.SECONDS));
            task.cancel();
            runUiUntil(() -> app.status().task() == null);
            assertSame(before, app.document().scene(), "the current model stays");
            assertEquals("opening big cancelled", app.status().message());
            // A second open completes, replacing the model
            app.files().open("teapot", () -> new SceneDocument(Models.teapot(), RenderSettings.defaults()));
            runUiUntil(() -> app.document().scene().patchCount() == 32);
            assertEquals("teapot — Bézier Tracer", app.document().title());
        } finally {
            io.shutdownNow();
        }
    }

    @Test
    void coalescingHandlesTheNewestOfABurst() throws Exception {
        ExecutorService worker = Executors.newSingleThreadExecutor();
        try {
            CountDownLatch gate = new CountDownLatch(1);
            AtomicInteger handled = new AtomicInteger();
            int[] last = {-1};
            Coalescing<Integer> c = new Coalescing<>(worker, i -> {
                try {
                    gate.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                handled.incrementAndGet();
                last[0] = i;
            }, e -> { });
            for (int i = 0; i < 100; i++) {
                c.submit(i);
            }
            gate.countDown();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (c.busy()) {
                assertTrue(System.nanoTime() < end);
                Thread.sleep(5);
            }
            assertEquals(99, last[0], "the newest item is handled last");
            assertTrue(handled.get() <= 2, "the burst was coalesced: " + handled.get() + " handled");
        } finally {
            worker.shutdownNow();
        }
    }
}
