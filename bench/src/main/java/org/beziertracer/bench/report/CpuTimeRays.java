package org.beziertracer.bench.report;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Locale;

import org.beziertracer.bench.MethodBench;
import org.openjdk.jmh.infra.Blackhole;

/**
 * {@link MethodBench}'s ray loops timed by the thread's CPU time instead of the wall clock: on a
 * machine shared with other busy processes the wall clock counts the time the thread waits for a
 * core, CPU time does not (it still counts cache and memory contention). For A/B comparisons
 * between two builds run alternately; JMH stays the reference on a quiet machine.
 *
 * <pre>
 * java -cp bench/target/benchmarks.jar org.beziertracer.bench.report.CpuTimeRays ROUNDS METHOD:SCENE ...
 * </pre>
 * prints, per {@code METHOD:SCENE} (e.g. {@code NEWTON:teapot}, {@code CLIPPING:6}), the best and
 * the median over ROUNDS rounds of CPU nanoseconds per ray (each round traces the benchmark's
 * 1,024 rays 20 times, after 20 warm-up rounds).
 */
public final class CpuTimeRays {
    private CpuTimeRays() {}

    public static void main(String[] args) {
        int rounds = Integer.parseInt(args[0]);
        int configs = args.length - 1;
        MethodBench[] benches = new MethodBench[configs];
        for (int c = 0; c < configs; c++) {
            String[] f = args[c + 1].split(":");
            benches[c] = new MethodBench();
            benches[c].method = org.beziertracer.intersect.Method.valueOf(f[0]);
            benches[c].scene = f[1];
            benches[c].setup();
        }
        Blackhole bh = new Blackhole("Today's password is swordfish. I understand instantiating Blackholes directly is dangerous.");
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        double[][] ns = new double[configs][rounds];
        for (int r = -20; r < rounds; r++) {
            for (int c = 0; c < configs; c++) {
                long t0 = mx.getCurrentThreadCpuTime();
                for (int k = 0; k < 20; k++) {
                    benches[c].closestHit(bh);
                }
                double perRay = (mx.getCurrentThreadCpuTime() - t0) / (20.0 * org.beziertracer.bench.Fixtures.RAYS);
                if (r >= 0) {
                    ns[c][r] = perRay;
                }
            }
        }
        for (int c = 0; c < configs; c++) {
            double[] v = ns[c].clone();
            java.util.Arrays.sort(v);
            System.out.printf(Locale.ROOT, "%-20s best %8.1f  median %8.1f ns/ray (CPU time, %d rounds)%n", args[c + 1], v[0],
                    v[v.length / 2], rounds);
        }
    }
}
