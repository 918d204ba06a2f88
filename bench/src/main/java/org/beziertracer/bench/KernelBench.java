package org.beziertracer.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;

import org.beziertracer.geometry.BernsteinEval;
import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.NetMeasures;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.infra.Blackhole;

/**
 * The de Casteljau kernel on one random {@code degree×degree} 3-D net: evaluation, evaluation with
 * first derivatives (de Casteljau and the Bernstein-sum form), a split in u, sub-patch extraction and control-point bounds. Each call uses a
 * (u,v) from a small table so that the JIT cannot fold the parameters.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
public class KernelBench {

    @Param({"2", "3", "4", "6", "9", "15"})
    public int degree;

    double[] net;
    double[] lo;
    double[] hi;
    double[] sub;
    double[] out;
    double[] box;
    double[] scratch;
    double[] params;
    int next;

    @Setup
    public void setup() {
        Random rnd = new Random(42);
        int len = (degree + 1) * (degree + 1) * 3;
        net = new double[len];
        for (int k = 0; k < len; k++) {
            net[k] = rnd.nextDouble();
        }
        lo = new double[len];
        hi = new double[len];
        sub = new double[len];
        out = new double[9];
        box = new double[6];
        scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        params = new double[64];
        for (int k = 0; k < params.length; k++) {
            params[k] = 0.05 + 0.9 * rnd.nextDouble();
        }
    }

    private double nextParam() {
        next = (next + 1) & 63;
        return params[next];
    }

    @Benchmark
    public void evaluate(Blackhole bh) {
        DeCasteljau.evaluate(net, 0, degree, degree, 3, nextParam(), nextParam(), out, 0, scratch);
        bh.consume(out[0] + out[1] + out[2]);
    }

    @Benchmark
    public void evaluateWithDerivatives(Blackhole bh) {
        DeCasteljau.evaluateWithDerivatives(net, 0, degree, degree, nextParam(), nextParam(), out, scratch);
        bh.consume(out[0] + out[4] + out[8]);
    }

    /** The O(n·m) Bernstein-sum form of {@link #evaluateWithDerivatives}. */
    @Benchmark
    public void evaluateWithDerivativesBernstein(Blackhole bh) {
        BernsteinEval.evaluateWithDerivatives(net, 0, degree, degree, nextParam(), nextParam(), out, 0, scratch, 0);
        bh.consume(out[0] + out[4] + out[8]);
    }

    @Benchmark
    public void split(Blackhole bh) {
        DeCasteljau.splitU(net, 0, degree, degree, 3, nextParam(), lo, 0, hi, 0);
        bh.consume(lo[3] + hi[3]);
    }

    @Benchmark
    public void subPatch(Blackhole bh) {
        double a = 0.5 * nextParam(), c = 0.5 * nextParam();
        DeCasteljau.subPatch(net, 0, degree, degree, 3, a, a + 0.4, c, c + 0.4, sub, 0);
        bh.consume(sub[3]);
    }

    @Benchmark
    public void controlBounds(Blackhole bh) {
        net[0] = nextParam();
        NetMeasures.controlBounds(net, 0, degree, degree, box);
        bh.consume(box[0] + box[5]);
    }
}
