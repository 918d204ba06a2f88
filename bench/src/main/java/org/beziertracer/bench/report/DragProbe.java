package org.beziertracer.bench.report;

import java.util.Arrays;
import java.util.concurrent.Semaphore;
import java.util.concurrent.atomic.AtomicReference;

import org.beziertracer.app.LightPlacement;
import org.beziertracer.app.OrbitView;
import org.beziertracer.app.Picture;
import org.beziertracer.app.RayTraceEngine;
import org.beziertracer.app.RenderRequest;
import org.beziertracer.app.RenderStatus;
import org.beziertracer.app.Settings;
import org.beziertracer.bench.Fixtures;
import org.beziertracer.bench.FrameScenes;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The app's own picture engine ({@link RayTraceEngine}, the Swing-free layer the window drives)
 * during a drag: the middle control point of the case's first patch moves through
 * {@link Fixtures#drags}, one step at a time, each submitted as the window submits a mouse move,
 * and the probe waits for that step's full-resolution picture (the engine's last progressive pass)
 * before the next move. Prints the pictures per second, the median and quartiles of the time from
 * a move to its full picture, and the median snapshot time (the edit: re-split and BVH refit).
 * The app's default settings at 800×600 (its passes, samples and shading as a user gets them).
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.DragProbe [CASE [STEPS [still] [at-eye]]]
 * </pre>
 * {@code CASE} as in {@link FrameScenes} (default {@code wavy10}), {@code STEPS} timed moves
 * (default 120, after 40 untimed ones); {@code still}: the same requests without the edit (the
 * snapshot reused), for the cost of the picture alone; {@code at-eye}: the light at the eye (as in
 * {@link FrameScenes}' wavy cases) instead of the app's default above left of the eye.
 */
public final class DragProbe {
    private DragProbe() {}

    public static void main(String[] args) {
        String name = args.length > 0 ? args[0] : "wavy10";
        int steps = args.length > 1 ? Integer.parseInt(args[1]) : 120;
        java.util.List<String> flags = Arrays.asList(args).subList(Math.min(2, args.length), args.length);
        Scene scene = FrameScenes.scene(name);
        Settings settings = flags.contains("at-eye") ? Settings.defaults().with(LightPlacement.AT_EYE) : Settings.defaults();
        OrbitView view = OrbitView.fit(scene.controlBounds(), settings.fovDegrees());
        Picture picture = new Picture(FrameScenes.WIDTH, FrameScenes.HEIGHT, () -> {});
        BezierPatch[] drags = Fixtures.drags(scene.patches().get(0));
        boolean still = flags.contains("still");
        AtomicReference<RenderStatus> last = new AtomicReference<>();
        java.util.concurrent.atomic.AtomicLong firstPass = new java.util.concurrent.atomic.AtomicLong();
        double[] millis = new double[steps], prep = new double[steps], first = new double[steps];
        try (RayTraceEngine engine = new RayTraceEngine()) {
            // The last pass's status releases the waiting probe: a blocking wait, as the window's
            // (which is told by callbacks), so the probe takes no processor time from the two render
            // threads (polling every 50 µs, as it did, cost them about 10 % on two cores)
            Semaphore pictureDone = new Semaphore(0);
            engine.onStatus(st -> {
                if (st.pass() == 1) {
                    firstPass.set(System.nanoTime());
                }
                last.set(st);
                if (st.pass() == st.passCount()) {
                    pictureDone.release();
                }
            });
            engine.onError(m -> { throw new IllegalStateException(m); });
            long start = 0;
            for (int k = -40; k < steps; k++) {
                if (k == 0) {
                    start = System.nanoTime();
                }
                scene = scene.withPatch(0, still ? scene.patches().get(0) : drags[Math.floorMod(k, drags.length)]);
                long t0 = System.nanoTime();
                engine.submit(RenderRequest.of(scene, view.camera(picture.width() / (double) picture.height()),
                        view.framing(), settings, picture));
                pictureDone.acquireUninterruptibly();
                while (engine.busy()) { // settled just after the last status
                    Thread.onSpinWait();
                }
                if (k >= 0) {
                    millis[k] = (System.nanoTime() - t0) / 1e6;
                    prep[k] = last.get().prepMillis();
                    first[k] = (firstPass.get() - t0) / 1e6;
                }
            }
            double seconds = (System.nanoTime() - start) / 1e9;
            Arrays.sort(millis);
            Arrays.sort(prep);
            Arrays.sort(first);
            RenderStatus s = last.get();
            System.out.printf("%s: %d moves, %.1f full pictures a second; move to full picture %.1f ms median"
                    + " (quartiles %.1f / %.1f); first (coarse) picture %.1f ms median; snapshot (edit) %.2f ms"
                    + " median; %d passes a picture, %d spp; light %s%s%n",
                    name, steps, steps / seconds, millis[steps / 2], millis[steps / 4], millis[3 * steps / 4],
                    first[steps / 2], prep[steps / 2], s.passCount(), s.spp(), settings.light(), still ? " (no edit: the same scene again)" : "");
        }
    }
}
