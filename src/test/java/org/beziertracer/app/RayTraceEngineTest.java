package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.UserMessages;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

class RayTraceEngineTest {

    @Test
    void snapshotsAreReusedPatchedOrRebuilt() {
        IntersectOptions io = IntersectOptions.defaults();
        Scene a = Models.teapot();
        SceneIntersector s0 = SnapshotCache.update(null, a, io);
        assertSame(s0, SnapshotCache.update(s0, a, io), "same scene: same snapshot");
        Scene b = a.withPatch(5, a.patches().get(5).withPoint(1, 1, 1, 2, 3));
        SceneIntersector s1 = SnapshotCache.update(s0, b, io);
        assertEquals(b.patches(), s1.scene().patches());
        assertSame(s1, SnapshotCache.update(s1, b, io), "equal scene after a patch edit: reused");
        SceneIntersector s2 = SnapshotCache.update(s1, b, io.withMethod(Method.NEWTON));
        assertNotSame(s1, s2);
        assertEquals(Method.NEWTON, s2.options().method());
    }

    @Test
    void aPointSharedByFourPatchesPatchesTheSnapshotOnceAndMatchesARebuild() {
        IntersectOptions io = IntersectOptions.defaults();
        Scene a = Models.teapot();
        SceneIntersector s0 = SnapshotCache.update(null, a, io);
        Topology t = Topology.of(a, false);
        Selection corner = Selection.ofHandles(java.util.List.of(t.handle(new PointRef(0, 0, 0), a)));
        assertTrue(corner.size() >= 2, "a corner of the body is welded: " + corner);
        Scene b = SelectionMove.apply(a, corner, new double[] {3, -2, 5}, t, false);
        SceneIntersector s1 = SnapshotCache.update(s0, b, io);
        assertSame(b, s1.scene());
        SceneIntersector rebuilt = SceneIntersector.build(b, io);
        org.beziertracer.intersect.TraceContext c1 = s1.newContext(), c2 = rebuilt.newContext();
        org.beziertracer.intersect.Hit h1 = new org.beziertracer.intersect.Hit(), h2 = new org.beziertracer.intersect.Hit();
        java.util.Random rnd = new java.util.Random(3);
        for (int r = 0; r < 300; r++) {
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian() - 1;
            boolean x = s1.closestHit(c1, 0, 0, 200, dx, dy, dz, 0, Double.POSITIVE_INFINITY, h1);
            boolean y = rebuilt.closestHit(c2, 0, 0, 200, dx, dy, dz, 0, Double.POSITIVE_INFINITY, h2);
            assertEquals(y, x, "ray " + r);
            if (x) {
                assertEquals(h2.t, h1.t, 1e-9 * h2.t, "ray " + r);
            }
        }
    }


    @Test
    void aBurstOfEditsEndsOnThePictureOfTheNewest() throws InterruptedException {
        Settings t = Settings.defaults();
        Scene scene = Models.patch();
        OrbitView view = OrbitView.fit(scene.controlBounds(), t.fovDegrees());
        java.util.concurrent.atomic.AtomicInteger finished = new java.util.concurrent.atomic.AtomicInteger();
        Picture fb = new Picture(64, 48, () -> {});
        RenderRequest last = null;
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(st -> {
                if (st.pass() == st.passCount()) {
                    finished.incrementAndGet();
                }
            });
            for (int k = 0; k < 60; k++) {
                var p = scene.patches().get(0);
                scene = scene.withPatch(0, p.withPoint(1, 2, -0.5, 0.5, 0.05 * k));
                last = RenderRequest.of(scene, view.camera(64 / 48.0), view.framing(), t, fb);
                engine.submit(last);
            }
            waitIdle(engine);
        }
        assertTrue(finished.get() < 60, "stale edits were coalesced or cancelled: " + finished.get() + " full frames");
        Picture alone = new Picture(64, 48, () -> {});
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.submit(RenderRequest.of(last.scene(), last.camera(), view.framing(), t, alone));
            waitIdle(engine);
        }
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                assertEquals(alone.rgb(x, y), fb.rgb(x, y), "pixel " + x + "," + y + " shows the newest edit");
            }
        }
    }

    private static void waitIdle(RayTraceEngine engine) throws InterruptedException {
        long end = System.nanoTime() + 30_000_000_000L;
        while (engine.busy()) {
            assertTrue(System.nanoTime() < end, "engine did not finish");
            Thread.sleep(5);
        }
    }

    /**
     * Found while building the app soak: a render that failed after a newer request had started
     * marked the engine's frame as done, so {@code busy()} said idle while the newer frame was
     * still rendering (and the tests that wait for idle compared a half-rendered picture).
     */
    @Test
    void aFailedRenderLeavesTheEngineBusyUntilTheNewerFrameIsDone() throws InterruptedException {
        Scene scene = Models.teapot();
        Settings slow = Settings.defaults().with(Toggle.SUPER_SAMPLING, true).with(Level.SAMPLES_PER_PIXEL, 16);
        var camera = OrbitView.fit(scene.controlBounds(), slow.fovDegrees()).camera(4 / 3.0);
        java.util.concurrent.BlockingQueue<String> errors = new java.util.concurrent.LinkedBlockingQueue<>();
        java.util.concurrent.atomic.AtomicBoolean newerDone = new java.util.concurrent.atomic.AtomicBoolean();
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onError(errors::add);
            engine.onStatus(st -> newerDone.compareAndSet(false, st.pass() == st.passCount() && st.spp() == 16));
            RenderRequest newer = RenderRequest.of(scene, camera, Framing.of(scene.controlBounds()), slow, new Picture(160, 120, () -> {}));
            java.util.concurrent.atomic.AtomicBoolean once = new java.util.concurrent.atomic.AtomicBoolean();
            // The first tile of the failing render asks for a repaint: the newer request comes, then the render fails
            Picture failing = new Picture(64, 48, () -> {
                if (once.compareAndSet(false, true)) {
                    engine.submit(newer);
                    throw new IllegalStateException("repaint failed");
                }
            });
            engine.submit(RenderRequest.of(scene, camera, Framing.of(scene.controlBounds()), Settings.defaults(), failing));
            assertTrue(errors.poll(30, java.util.concurrent.TimeUnit.SECONDS) != null, "the failure is reported");
            long end = System.nanoTime() + 60_000_000_000L;
            while (!newerDone.get()) {
                boolean busy = engine.busy();
                assertTrue(busy || newerDone.get(), "busy while the newer frame renders");
                assertTrue(System.nanoTime() < end, "the newer frame finishes");
                Thread.sleep(1);
            }
            waitIdle(engine);
        }
    }

    @Test
    void aFailedPreparationIsReportedAsOneLineAndTheEngineGoesIdle() throws InterruptedException {
        Picture fb = new Picture(32, 24, () -> {});
        java.util.concurrent.BlockingQueue<String> errors = new java.util.concurrent.LinkedBlockingQueue<>();
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onError(errors::add);
            // a request without a camera cannot be prepared
            Settings t = Settings.defaults().with(LightPlacement.SCENE);
            engine.submit(RenderRequest.of(Models.patch(), null, null, t, fb));
            String msg = errors.poll(20, java.util.concurrent.TimeUnit.SECONDS);
            assertTrue(msg != null, "an error line");
            UserMessages.check(msg);
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (engine.busy() && System.nanoTime() < deadline) {
                Thread.sleep(10);
            }
            assertTrue(!engine.busy(), "the engine is idle after a failure");
        }
    }
}
