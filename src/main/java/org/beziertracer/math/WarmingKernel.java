package org.beziertracer.math;

import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The SIMD kernel behind a scalar stand-in until the JIT has compiled it. Until HotSpot's C2
 * compiler has turned the Vector API calls into vector instructions, they run interpreted or in
 * C1 code that boxes every vector: measured on JDK 17, the first thousand calls of
 * {@link VectorKernel#powerForm} took about 400 µs each, a thousand times the compiled cost, so a
 * one-shot 800×600 render with the SIMD kernel took twice the wall time of the scalar one.
 *
 * <p>On the first call this kernel starts one daemon thread that sleeps for a delay (a short run
 * ends before it and never pays for the warm-up: {@link Kernels} says how long), then runs both kernels on a fixed set
 * of patches (degrees 1 to 15, whole registers) and times blocks of calls, alternately; as soon as
 * the fast kernel wins three blocks in a row, every later call goes to it. The callers meanwhile
 * run the stand-in, already compiled after a few hundred calls. If the fast kernel never wins
 * within the time limit (a JVM with the JIT off, {@code -Xint}), the stand-in stays. The two
 * kernels give the same bits ({@link LaneKernel}), so which one answered a call never shows in a
 * picture: this changes speed only, like the choice in {@link Kernels}.
 *
 * <p>Adaptive warm-up by measurement follows the tiered compilation it waits for (Paleczny, Vick
 * and Click, "The Java HotSpot Server Compiler", JVM '01): the compiler's own counters decide when
 * code is compiled, so the only portable signal is the speed itself.
 */
final class WarmingKernel implements LaneKernel {

    /** Blocks in a row the fast kernel must win. */
    private static final int WINS = 3;
    private static final int CALLS_A_BLOCK = 64;

    private final LaneKernel fast;
    private final LaneKernel standIn;
    private final long delayNanos;
    private final long limitNanos;
    private final AtomicBoolean started = new AtomicBoolean();
    private final AtomicInteger threads = new AtomicInteger();
    private volatile Thread warmUp;
    private volatile boolean warm;

    /**
     * @param fast       the kernel to use once it is faster
     * @param standIn    the kernel to use until then (same bits)
     * @param delayNanos how long after the first call the warm-up waits (asleep) before it measures
     * @param limitNanos how long the warm-up may measure before it gives up and keeps the stand-in
     */
    WarmingKernel(LaneKernel fast, LaneKernel standIn, long delayNanos, long limitNanos) {
        this.fast = fast;
        this.standIn = standIn;
        this.delayNanos = delayNanos;
        this.limitNanos = limitNanos;
    }

    @Override
    public int lanes() {
        return fast.lanes();
    }

    @Override
    public String description() {
        return fast.description();
    }

    @Override
    public void powerForm(double[] a, int off, int n, int m, double[] u, double[] v, int count, double[] out,
                          int stride) {
        if (warm) {
            fast.powerForm(a, off, n, m, u, v, count, out, stride);
            return;
        }
        if (!started.get() && started.compareAndSet(false, true)) {
            Thread t = new Thread(this::warmUp, "simd-warm-up");
            t.setDaemon(true);
            t.setPriority(Thread.MIN_PRIORITY);
            threads.incrementAndGet();
            warmUp = t;
            t.start();
        }
        standIn.powerForm(a, off, n, m, u, v, count, out, stride);
    }

    /** True once calls go to the fast kernel. */
    boolean warm() {
        return warm;
    }

    /** How many warm-up threads calls have started: 0 before the first call, 1 after it. */
    int warmUpsStarted() {
        return threads.get();
    }

    /** Waits for the warm-up thread to end (won or given up); true if it has ended. */
    boolean awaitWarmUp(long timeout, TimeUnit unit) throws InterruptedException {
        Thread t = warmUp;
        if (t == null) {
            return false;
        }
        t.join(Math.max(1, unit.toMillis(timeout)));
        return !t.isAlive();
    }

    private void warmUp() {
        if (delayNanos > 0) {
            try {
                TimeUnit.NANOSECONDS.sleep(delayNanos);
            } catch (InterruptedException e) {
                return; // stays on the stand-in
            }
        }
        Workload w = new Workload(fast.lanes());
        long start = System.nanoTime();
        int wins = 0;
        while (wins < WINS && System.nanoTime() - start < limitNanos) {
            long tFast = w.time(fast), tStandIn = w.time(standIn);
            wins = tFast < tStandIn ? wins + 1 : 0;
        }
        warm = wins >= WINS;
    }

    /** Fixed patches of every degree and the lanes to evaluate them at: the calls a render makes. */
    private static final class Workload {
        private static final int MAX_DEGREE = 15;
        private final double[][] forms = new double[MAX_DEGREE][];
        private final double[] u, v, out;
        private final int count, stride;
        private double sink;

        Workload(int lanes) {
            Random rnd = new Random(32);
            for (int d = 1; d <= MAX_DEGREE; d++) {
                double[] a = new double[3 * (d + 1) * (d + 1)];
                for (int i = 0; i < a.length; i++) {
                    a[i] = rnd.nextDouble() - 0.5;
                }
                forms[d - 1] = a;
            }
            count = 2 * Math.max(1, lanes);
            stride = count;
            u = new double[count];
            v = new double[count];
            for (int i = 0; i < count; i++) {
                u[i] = rnd.nextDouble();
                v[i] = rnd.nextDouble();
            }
            out = new double[9 * stride];
        }

        /** Nanoseconds for one block of calls (mostly degree 3, then the others in turn). */
        long time(LaneKernel k) {
            long t0 = System.nanoTime();
            for (int c = 0; c < CALLS_A_BLOCK; c++) {
                int d = c % 4 == 0 ? 1 + (c / 4) % MAX_DEGREE : 3;
                k.powerForm(forms[d - 1], 0, d, d, u, v, count, out, stride);
                sink += out[0];
            }
            return System.nanoTime() - t0;
        }
    }
}
