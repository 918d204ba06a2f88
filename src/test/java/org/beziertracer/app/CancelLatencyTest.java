package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStream;
import java.nio.charset.StandardCharsets;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.FileFormats;
import org.junit.jupiter.api.Test;

/**
 * Cancel stops a long job within a bound counted in work, not time: the bytes a load still takes
 * from its stream after Cancel. Every worker runs inline ({@link AppThreads#direct()}), so the
 * job itself presses Cancel (as the user would, from another thread) once it is well under way.
 */
class CancelLatencyTest {

    /** Most bytes a cancelled read may still take: the text buffer's refill plus one stream read. */
    static final long BYTES_AFTER_CANCEL = 2 * 16384;

    /**
     * BPT text made as it is read — {@code count} bicubic patches — that presses Cancel after
     * {@code cancelAt} bytes and counts what is read after that. Not a file channel, so an
     * interrupt does not close it: only the reader's own check can stop the read.
     */
    static final class SlowBpt extends InputStream {
        private final long cancelAt;
        private final Runnable cancel;
        private final int count;
        private byte[] chunk = new byte[0];
        private int at;
        private int patch;
        long served;
        long afterCancel = -1;

        SlowBpt(int count, long cancelAt, Runnable cancel) {
            this.count = count;
            this.cancelAt = cancelAt;
            this.cancel = cancel;
            chunk = (count + "\n").getBytes(StandardCharsets.US_ASCII);
        }

        @Override
        public int read() {
            byte[] one = new byte[1];
            return read(one, 0, 1) < 0 ? -1 : one[0] & 0xff;
        }

        @Override
        public int read(byte[] b, int off, int len) {
            if (at == chunk.length) {
                if (patch == count) {
                    return -1;
                }
                StringBuilder sb = new StringBuilder("3 3\n");
                for (int k = 0; k < 16; k++) {
                    sb.append(patch + (k % 4) / 3.0).append(' ').append(k / 4 / 3.0).append(" 0.125\n");
                }
                patch++;
                chunk = sb.toString().getBytes(StandardCharsets.US_ASCII);
                at = 0;
            }
            int n = Math.min(len, chunk.length - at);
            System.arraycopy(chunk, at, b, off, n);
            at += n;
            served += n;
            if (afterCancel >= 0) {
                afterCancel += n;
            } else if (served >= cancelAt) {
                afterCancel = 0;
                cancel.run();
            }
            return n;
        }
    }

    @Test
    void cancellingAnOpenFromAStreamStopsWithinTwoBuffersAndKeepsTheModel() {
        FakeDialogs dialogs = new FakeDialogs();
        AppModel app = new AppModel(new FakeEngine(), dialogs, AppThreads.direct(), MemoryPreferences.fresh());
        Scene before = app.document().scene();
        SlowBpt stream = new SlowBpt(100_000, 1 << 20, () -> app.status().task().cancel());
        app.files().open("endless.bpt", () -> FileFormats.BPT.read(stream, "endless.bpt", null));
        assertTrue(stream.afterCancel >= 0, "Cancel was pressed");
        assertTrue(stream.afterCancel <= BYTES_AFTER_CANCEL, "after Cancel the read took " + stream.afterCancel
                + " more bytes (of " + stream.served + " served); at most " + BYTES_AFTER_CANCEL);
        assertEquals("opening endless.bpt cancelled", app.status().message());
        assertTrue(dialogs.errors.isEmpty(), "a cancel is no error: " + dialogs.errors);
        assertSame(before, app.document().scene(), "the model stays");
        assertNull(app.status().task(), "the bar is gone");
        assertTrue(!Thread.currentThread().isInterrupted(), "no interrupt leaks out of the job");
    }

    @Test
    void cancellingTheContinuityAnalysisStopsBeforeTheNextProgressStepAndDoesNotStartAgain() {
        AppModel app = new AppModel(new FakeEngine(), new FakeDialogs(), AppThreads.direct(), MemoryPreferences.fresh());
        app.files().open("grid", () -> new SceneDocument(new Scene(BigModels.grid(10_000)), RenderSettings.defaults()));
        long[] atCancel = {-1};
        long[] mostDone = {0};
        String[] firstCount = {null};
        app.addListener(() -> {
            Task t = app.status().task();
            if (t == null || !t.label().equals("analysing continuity") || t.count().isEmpty()) {
                return;
            }
            if (firstCount[0] == null) {
                firstCount[0] = t.count();
            }
            long done = Long.parseLong(t.count().split(" ")[0].replace(",", ""));
            mostDone[0] = Math.max(mostDone[0], done);
            if (done >= ContinuityAnalysis.PROGRESS_STEP && atCancel[0] < 0) {
                atCancel[0] = done;
                t.cancel();
            }
        });
        app.settings().set(Toggle.CONTINUITY, true);
        assertEquals("0 / 19,800 borders", firstCount[0], "the bar shows the total from its first report");
        assertTrue(atCancel[0] > 0, "Cancel was pressed");
        assertTrue(mostDone[0] - atCancel[0] < ContinuityAnalysis.PROGRESS_STEP, "after Cancel at " + atCancel[0]
                + " borders the analysis went on to " + mostDone[0]);
        assertEquals("continuity analysis cancelled", app.status().message());
        assertNull(app.status().task());
        assertNull(app.continuity().current());
        assertFalse(app.continuity().busy(), "a cancelled analysis is not waited for");
        app.resetView(); // a new picture: the cancelled model is not analysed again
        assertNull(app.continuity().current());
        app.settings().set(Toggle.CONTINUITY, false);
        app.settings().set(Toggle.CONTINUITY, true);
        assertEquals(19_800, app.continuity().current().result().rows().size(), "switched on again: analysed");
    }

    @Test
    void aCancelledAnalysisStopsWhileWeldingWithinOneStepOfPatches() {
        Scene grid = new Scene(BigModels.grid(10_000));
        int[] asked = {0};
        java.util.concurrent.CancellationException e = org.junit.jupiter.api.Assertions.assertThrows(
                java.util.concurrent.CancellationException.class, () -> ContinuityAnalysis.analyze(grid,
                        ContinuityAnalysis.Tolerances.defaults(grid), (done, total) -> { }, () -> ++asked[0] >= 2));
        assertEquals(2, asked[0], "asked once a step and stopped at the first yes");
        assertTrue(java.util.Arrays.stream(e.getStackTrace()).anyMatch(f -> f.getClassName().equals(WeldIndex.class.getName())),
                "stopped while welding the points, " + WeldIndex.CANCEL_STEP + " patches after Cancel, not after all 10,000");
    }
}
