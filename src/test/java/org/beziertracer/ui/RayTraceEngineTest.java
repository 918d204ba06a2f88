package org.beziertracer.ui;

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
        SceneIntersector s0 = RayTraceEngine.update(null, a, io);
        assertSame(s0, RayTraceEngine.update(s0, a, io), "same scene: same snapshot");
        Scene b = NetEdits.movePoint(a, new PointRef(5, 1, 1), 1, 2, 3);
        SceneIntersector s1 = RayTraceEngine.update(s0, b, io);
        assertEquals(b.patches(), s1.scene().patches());
        assertSame(s1, RayTraceEngine.update(s1, b, io), "equal scene after a patch edit: reused");
        SceneIntersector s2 = RayTraceEngine.update(s1, b, io.withMethod(Method.NEWTON));
        assertNotSame(s1, s2);
        assertEquals(Method.NEWTON, s2.options().method());
    }

    @Test
    void aBurstOfEditsEndsOnThePictureOfTheNewest() throws InterruptedException {
        ToolSettings t = new ToolSettings();
        Scene scene = Models.patch();
        OrbitView view = OrbitView.fit(scene.controlBounds(), t.fovDegrees());
        java.util.concurrent.atomic.AtomicInteger finished = new java.util.concurrent.atomic.AtomicInteger();
        FrameBuffer fb = new FrameBuffer(64, 48, () -> {});
        RenderRequest last = null;
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onStatus(st -> {
                if (st.pass() == st.passCount()) {
                    finished.incrementAndGet();
                }
            });
            for (int k = 0; k < 60; k++) {
                scene = NetEdits.movePoint(scene, new PointRef(0, 1, 2), -0.5, 0.5, 0.05 * k);
                last = new RenderRequest(scene, view.camera(64 / 48.0), t.renderSettings(64, 48), 1, fb);
                engine.submit(last);
            }
            waitIdle(engine);
        }
        assertTrue(finished.get() < 60, "stale edits were coalesced or cancelled: " + finished.get() + " full frames");
        FrameBuffer alone = new FrameBuffer(64, 48, () -> {});
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.submit(new RenderRequest(last.scene(), last.camera(), last.settings(), 1, alone));
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

    @Test
    void aFailedPreparationIsReportedAsOneLineAndTheEngineGoesIdle() throws InterruptedException {
        ToolSettings t = new ToolSettings();
        FrameBuffer fb = new FrameBuffer(32, 24, () -> {});
        java.util.concurrent.BlockingQueue<String> errors = new java.util.concurrent.LinkedBlockingQueue<>();
        try (RayTraceEngine engine = new RayTraceEngine()) {
            engine.onError(errors::add);
            // a request without a camera cannot be prepared
            engine.submit(new RenderRequest(Models.patch(), null, t.renderSettings(32, 24), 1, fb));
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
