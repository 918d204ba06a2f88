package org.beziertracer.math;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/**
 * {@link WarmingKernel} answers with its stand-in until its warm-up thread has measured the fast
 * kernel winning, then with the fast kernel; it starts that thread on the first call only, lets it
 * measure only after its delay (a short run never pays for the warm-up), keeps
 * the stand-in when the fast kernel never wins, and gives the same bits either way. The two fake
 * kernels differ in cost by orders of magnitude (a busy wait against none), so which one wins does
 * not depend on the machine's load.
 */
class WarmingKernelTest {

    /** Counts its calls; costs {@code spinNanos} of busy waiting a call; computes the scalar kernel's lanes. */
    private static final class Counting implements LaneKernel {
        final AtomicInteger calls = new AtomicInteger();
        private final long spinNanos;

        Counting(long spinNanos) {
            this.spinNanos = spinNanos;
        }

        @Override
        public int lanes() {
            return 4;
        }

        @Override
        public String description() {
            return "counting, " + spinNanos + " ns a call";
        }

        @Override
        public void powerForm(double[] a, int off, int n, int m, double[] u, double[] v, int count, double[] out,
                              int stride) {
            calls.incrementAndGet();
            long end = System.nanoTime() + spinNanos;
            while (System.nanoTime() < end) {
                Thread.onSpinWait();
            }
            Kernels.scalar().powerForm(a, off, n, m, u, v, count, out, stride);
        }
    }

    private static final double[] A = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1}; // degree 1x1
    private static final double[] U = {0.25, 0.5}, V = {0.75, 0.5};

    @Test
    void theFirstCallStartsTheWarmUpAndTheFasterKernelTakesOver() throws InterruptedException {
        Counting fast = new Counting(0), slow = new Counting(200_000);
        WarmingKernel k = new WarmingKernel(fast, slow, 0, TimeUnit.SECONDS.toNanos(60));
        assertEquals(0, k.warmUpsStarted(), "nothing runs before the first call");
        double[] out = new double[18];
        k.powerForm(A, 0, 1, 1, U, V, 2, out, 2);
        assertEquals(1, k.warmUpsStarted());
        assertTrue(k.awaitWarmUp(60, TimeUnit.SECONDS), "the warm-up ends");
        assertTrue(k.warm(), "a kernel with no busy wait wins against 200 µs a call");
        int fastBefore = fast.calls.get(), slowBefore = slow.calls.get();
        for (int i = 0; i < 10; i++) {
            k.powerForm(A, 0, 1, 1, U, V, 2, out, 2);
        }
        assertEquals(fastBefore + 10, fast.calls.get(), "calls go to the fast kernel once it is warm");
        assertEquals(slowBefore, slow.calls.get(), "and no longer to the stand-in");
        assertEquals(fast.description(), k.description());
        assertEquals(fast.lanes(), k.lanes());
    }

    @Test
    void theWarmUpWaitsForItsDelayBeforeItRunsTheFastKernel() throws InterruptedException {
        Counting fast = new Counting(0), slow = new Counting(200_000);
        WarmingKernel k = new WarmingKernel(fast, slow, TimeUnit.SECONDS.toNanos(60), TimeUnit.SECONDS.toNanos(60));
        double[] out = new double[18];
        k.powerForm(A, 0, 1, 1, U, V, 2, out, 2);
        assertEquals(1, k.warmUpsStarted(), "the first call starts the (sleeping) warm-up thread");
        assertFalse(k.awaitWarmUp(300, TimeUnit.MILLISECONDS), "the warm-up is still waiting");
        assertEquals(0, fast.calls.get(), "a run shorter than the delay never calls the fast kernel");
        assertEquals(1, slow.calls.get(), "only the caller's call ran, on the stand-in");
        assertFalse(k.warm());
    }

    @Test
    void afterItsDelayTheWarmUpMeasuresAndHandsOver() throws InterruptedException {
        Counting fast = new Counting(0), slow = new Counting(200_000);
        long delay = TimeUnit.MILLISECONDS.toNanos(200);
        WarmingKernel k = new WarmingKernel(fast, slow, delay, TimeUnit.SECONDS.toNanos(60));
        long t0 = System.nanoTime();
        k.powerForm(A, 0, 1, 1, U, V, 2, new double[18], 2);
        assertTrue(k.awaitWarmUp(60, TimeUnit.SECONDS));
        assertTrue(System.nanoTime() - t0 >= delay, "the warm-up did not end before its delay");
        assertTrue(k.warm(), "and then the fast kernel takes over");
        assertTrue(fast.calls.get() > 0);
    }

    @Test
    void aFastKernelThatNeverWinsLeavesTheStandIn() throws InterruptedException {
        Counting neverFaster = new Counting(200_000), standIn = new Counting(0);
        WarmingKernel k = new WarmingKernel(neverFaster, standIn, 0, TimeUnit.MILLISECONDS.toNanos(300));
        double[] out = new double[18];
        k.powerForm(A, 0, 1, 1, U, V, 2, out, 2);
        assertTrue(k.awaitWarmUp(60, TimeUnit.SECONDS), "the warm-up gives up at its limit");
        assertFalse(k.warm());
        int before = standIn.calls.get();
        k.powerForm(A, 0, 1, 1, U, V, 2, out, 2);
        assertEquals(before + 1, standIn.calls.get(), "the stand-in keeps answering");
    }

    @Test
    void concurrentFirstCallsStartOneWarmUpThreadThatEnds() throws InterruptedException {
        Counting fast = new Counting(0), slow = new Counting(200_000);
        WarmingKernel k = new WarmingKernel(fast, slow, 0, TimeUnit.SECONDS.toNanos(60));
        Thread[] callers = new Thread[4];
        for (int t = 0; t < callers.length; t++) {
            callers[t] = new Thread(() -> k.powerForm(A, 0, 1, 1, U, V, 2, new double[18], 2));
            callers[t].start();
        }
        for (Thread t : callers) {
            t.join();
        }
        assertEquals(1, k.warmUpsStarted(), "one warm-up for any number of racing first calls");
        assertTrue(k.awaitWarmUp(60, TimeUnit.SECONDS), "the warm-up thread ends once it has decided");
        assertTrue(k.warm());
    }

    @Test
    void theSimdKernelBehindItsWarmUpGivesTheScalarBitsBeforeAndAfter() throws InterruptedException {
        LaneKernel simd = Kernels.named("simd"), scalar = Kernels.scalar();
        WarmingKernel k = new WarmingKernel(simd, scalar, 0, TimeUnit.SECONDS.toNanos(60));
        Random rnd = new Random(9);
        int stride = 16;
        for (int round = 0; round < 2; round++) {
            for (int n = 1; n <= 9; n++) {
                double[] a = new double[3 * (n + 1) * (n + 1)];
                for (int i = 0; i < a.length; i++) {
                    a[i] = rnd.nextGaussian();
                }
                double[] u = new double[stride], v = new double[stride];
                for (int i = 0; i < stride; i++) {
                    u[i] = rnd.nextDouble();
                    v[i] = rnd.nextDouble();
                }
                double[] expected = new double[9 * stride], actual = new double[9 * stride];
                scalar.powerForm(a, 0, n, n, u, v, stride, expected, stride);
                k.powerForm(a, 0, n, n, u, v, stride, actual, stride);
                assertArrayEquals(expected, actual, "round " + round + ", degree " + n + ", warm " + k.warm());
            }
            assertTrue(k.awaitWarmUp(60, TimeUnit.SECONDS));
        }
    }
}
