package org.beziertracer.app;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.BooleanSupplier;

import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Scene;
import org.beziertracer.render.Renderer;

/**
 * What the soak tests check after a run, shared by the app-layer and the GUI soak: no exception
 * escaped on any thread, the app's picture equals a fresh render of its final state, the heap
 * stayed bounded. Also the seed (printed, replayed with {@code -Dsoak.seed=N}).
 */
public final class SoakChecks {
    private SoakChecks() {}

    /** System property that replays a run: {@code -Dsoak.seed=N}. */
    public static final String SEED = "soak.seed";

    /** The seed of this run: {@value #SEED} when set, else a new one; printed either way. */
    public static long seed(String test) {
        String given = System.getProperty(SEED);
        long seed = given != null ? Long.parseLong(given.trim()) : System.nanoTime() & 0xFFFFFFFFL;
        System.out.println(test + ": seed " + seed + " (replay with -D" + SEED + "=" + seed + ")");
        return seed;
    }

    /** Records every exception no one caught, on any thread, while installed as the default handler. */
    public static final class Uncaught implements Thread.UncaughtExceptionHandler, AutoCloseable {
        private final List<String> seen = Collections.synchronizedList(new ArrayList<>());
        private final Thread.UncaughtExceptionHandler previous = Thread.getDefaultUncaughtExceptionHandler();

        private Uncaught() {}

        /** Makes a recorder the default handler (until {@link #close}). */
        public static Uncaught install() {
            Uncaught u = new Uncaught();
            Thread.setDefaultUncaughtExceptionHandler(u);
            return u;
        }

        @Override
        public void uncaughtException(Thread t, Throwable e) {
            System.err.println("soak: uncaught on " + t.getName() + ":");
            e.printStackTrace();
            seen.add(t.getName() + ": " + e);
        }

        /** What was recorded (a copy). */
        public List<String> seen() {
            synchronized (seen) {
                return List.copyOf(seen);
            }
        }

        @Override
        public void close() {
            Thread.setDefaultUncaughtExceptionHandler(previous);
        }
    }

    /** The final state as the UI thread sees it: what to render afresh, and the picture the app shows. */
    public record Final(Scene scene, CameraSpec camera, Framing framing, Settings settings, int width, int height, int[] shown) {

        /** Read on the UI thread, once the app is idle. */
        public static Final of(AppModel app) {
            Picture p = app.view().picture();
            return new Final(app.document().scene(), app.view().camera(), app.view().view().framing(), app.settings().current(),
                    p.width(), p.height(),
                    p.pixels().clone());
        }

        /** The same request rendered from scratch: a new snapshot, a new session, the same render pipeline. */
        public int[] freshRender() {
            RenderRequest r = RenderRequest.of(scene, camera, framing, settings, new Picture(width, height, () -> {}));
            SceneIntersector snapshot = SceneIntersector.build(r.scene(), r.intersect());
            org.beziertracer.render.RenderResult result = Renderer.renderOnce(r.job(snapshot));
            // a path-traced picture is shown through the tone map, as its PNG is written
            return r.pathTraced() ? org.beziertracer.render.ToneMap.argb(result.film(), r.options().path().exposure())
                    : result.argb();
        }

        /** Null when every pixel of the shown picture equals {@code fresh}; else how many differ and where the first is. */
        public String mismatch(int[] fresh) {
            int count = 0, first = -1;
            for (int k = 0; k < shown.length; k++) {
                if ((shown[k] & 0xFFFFFF) != (fresh[k] & 0xFFFFFF)) {
                    count++;
                    first = first < 0 ? k : first;
                }
            }
            return count == 0 ? null : count + " of " + shown.length + " pixels differ from a fresh render, the first at ("
                    + first % width + ", " + first / width + "): shown " + Integer.toHexString(shown[first] & 0xFFFFFF)
                    + ", fresh " + Integer.toHexString(fresh[first] & 0xFFFFFF) + "; state " + describe();
        }

        /** The final state in one line (for a failure message). */
        public String describe() {
            return scene.patchCount() + " patches, " + settings + ", " + width + "×" + height;
        }
    }

    /**
     * A checkpoint: ends the open gesture and brings the ray trace back ({@link SoakActions#finish}),
     * waits (up to {@code timeoutMillis}) until the app is idle, and returns its final state with
     * the picture it shows.
     */
    public static Final idleState(OnUi onUi, AppModel app, SoakActions actions, long timeoutMillis) throws Exception {
        onUi.call(() -> {
            actions.finish();
            return null;
        });
        if (!awaitIdle(onUi, app::busy, timeoutMillis)) {
            printThreads();
            throw new AssertionError("the app did not go idle within " + timeoutMillis + " ms (busy: "
                    + onUi.call(app::busyParts) + "); state " + onUi.call(() -> Final.of(app)).describe());
        }
        return onUi.call(() -> Final.of(app));
    }

    /**
     * Waits until {@code busy} (asked on the UI thread through {@code onUi}) has been false for
     * three checks in a row, 30 ms apart; false after {@code timeoutMillis}.
     */
    public static boolean awaitIdle(OnUi onUi, BooleanSupplier busy, long timeoutMillis) throws Exception {
        long end = System.nanoTime() + timeoutMillis * 1_000_000;
        int quiet = 0;
        while (quiet < 3) {
            if (System.nanoTime() > end) {
                return false;
            }
            quiet = onUi.call(busy::getAsBoolean) ? 0 : quiet + 1;
            Thread.sleep(30);
        }
        return true;
    }

    /** Runs a call on the UI thread and waits for its result. */
    @FunctionalInterface
    public interface OnUi {
        <T> T call(Callable<T> task) throws Exception;
    }

    /** Every thread's stack, to standard output (when the app did not go idle). */
    public static void printThreads() {
        Thread.getAllStackTraces().forEach((t, stack) -> {
            System.out.println("soak: thread " + t.getName() + " " + t.getState());
            for (StackTraceElement e : stack) {
                System.out.println("    " + e);
            }
        });
    }

    /** Used heap after full collections, in bytes. */
    public static long settledHeap() throws InterruptedException {
        long used = Long.MAX_VALUE;
        for (int k = 0; k < 3; k++) {
            System.gc();
            Thread.sleep(50);
            used = Math.min(used, ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed());
        }
        return used;
    }
}
