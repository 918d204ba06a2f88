package org.beziertracer.bench.report;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Locale;

import org.beziertracer.bench.FrameScenes;
import org.beziertracer.render.RenderJob;
import org.beziertracer.render.Renderer;

/**
 * {@code FrameBench}'s frame timed by the CPU time of the whole process instead of the wall clock:
 * on a machine shared with other busy processes a frame's wall time counts the time its threads
 * wait for a core, CPU time does not (it still counts cache contention, the JIT and the GC). Each
 * frame is {@link Renderer#renderOnce} on a fresh session, as in {@code FrameBench}. For A/B
 * comparisons of two builds run alternately (e.g. {@code for r in 1 2 3; do java -cp old.jar …;
 * java -cp new.jar …; done}); JMH stays the reference on a quiet machine.
 *
 * <pre>
 * java --add-modules jdk.incubator.vector -cp bench/target/benchmarks.jar \
 *     org.beziertracer.bench.report.FrameCpu FRAMES SCENE:TESSELLATE[:THREADS] ...
 * </pre>
 * prints per case ({@code patch:0}, {@code curved:K}, {@code wavy10:0:1}; tessellate {@code K} is
 * the case's equal-accuracy K, {@link FrameScenes#equalK}; threads 2 unless given) the median and
 * best CPU ms and the median wall ms per frame over FRAMES frames, after half as many warm-up frames
 * (at least 30). The process CPU time ticks in steps of 10 ms on Linux, so it is read over blocks
 * of {@value #BLOCK} frames (the median and best are of the blocks' means). Cases take turns block
 * by block, so a change in the machine's load hits them alike.
 */
public final class FrameCpu {
    private FrameCpu() {}

    /** Frames timed together. */
    static final int BLOCK = 10;

    public static void main(String[] args) {
        int frames = Integer.parseInt(args[0]);
        int cases = args.length - 1;
        RenderJob[] jobs = new RenderJob[cases];
        for (int c = 0; c < cases; c++) {
            String[] f = args[c + 1].split(":");
            int threads = f.length > 2 ? Integer.parseInt(f[2]) : 2;
            jobs[c] = FrameScenes.job(f[0], threads, FrameScenes.tessellate(f[0], f[1]));
        }
        com.sun.management.OperatingSystemMXBean os =
                (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        int blocks = Math.max(1, frames / BLOCK);
        double[][] cpu = new double[cases][blocks], wall = new double[cases][blocks];
        int warm = Math.max(3, blocks / 2);
        long sink = 0;
        for (int r = -warm; r < blocks; r++) {
            for (int c = 0; c < cases; c++) {
                long c0 = os.getProcessCpuTime(), w0 = System.nanoTime();
                for (int f = 0; f < BLOCK; f++) {
                    sink += Renderer.renderOnce(jobs[c]).stats().totalRays();
                }
                if (r >= 0) {
                    cpu[c][r] = (os.getProcessCpuTime() - c0) / 1e6 / BLOCK;
                    wall[c][r] = (System.nanoTime() - w0) / 1e6 / BLOCK;
                }
            }
        }
        for (int c = 0; c < cases; c++) {
            double[] v = cpu[c].clone(), w = wall[c].clone();
            Arrays.sort(v);
            Arrays.sort(w);
            System.out.printf(Locale.ROOT, "%-14s CPU median %7.2f best %7.2f ms/frame; wall median %7.2f ms (%d blocks of %d frames)%n",
                    args[c + 1], v[blocks / 2], v[0], w[blocks / 2], blocks, BLOCK);
        }
        if (sink == 42) {
            System.out.println();
        }
    }
}
