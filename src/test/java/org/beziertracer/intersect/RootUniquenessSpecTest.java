package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link RootUniqueness} against its specification, computed here another way: the ball test as
 * its Javadoc states it (with {@code D0} as the triple product {@code d̂·(a×b)}), and the box test
 * as interval arithmetic over every product of the derivative ranges. {@link RootUniquenessTest}
 * checks that a proof is never wrong; this checks that the proof is the stated one.
 */
class RootUniquenessSpecTest {

    /** {@code |D0| > rb(|n1·a| + |n2·a|) + ra(|n1·b| + |n2·b|) + 2·ra·rb + margin}, D0 = d̂·(a×b). */
    static boolean ballSpec(TraceContext ctx, double[] a, double[] b, double ra, double rb, double margin) {
        double[] n1 = {ctx.n1x, ctx.n1y, ctx.n1z}, n2 = {ctx.n2x, ctx.n2y, ctx.n2z};
        double len = Math.sqrt(ctx.dx * ctx.dx + ctx.dy * ctx.dy + ctx.dz * ctx.dz);
        double[] d = {ctx.dx / len, ctx.dy / len, ctx.dz / len};
        double[] axb = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
        double d0 = dot(d, axb);
        double bound = rb * (Math.abs(dot(n1, a)) + Math.abs(dot(n2, a))) + ra * (Math.abs(dot(n1, b)) + Math.abs(dot(n2, b)))
                + 2 * ra * rb + margin;
        return Math.abs(d0) > bound;
    }

    static double dot(double[] p, double[] q) {
        return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    }

    @Test
    void theBallTestIsTheStatedInequality() {
        Random rnd = new Random(2002);
        SubPatchTable tab = SubPatchTable.build(List.of(Models.flatGrid(4, 4)), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        int proven = 0, refused = 0, checked = 0;
        for (int trial = 0; trial < 20000; trial++) {
            double[] a = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double[] b = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double scale = Math.pow(10, 4 * rnd.nextDouble() - 3);
            double ra = scale * rnd.nextDouble(), rb = scale * rnd.nextDouble();
            double margin = rnd.nextBoolean() ? 0 : 0.1 * rnd.nextDouble();
            ctx.setRay(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(),
                    rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            double[] q = tab.uniqueness; // one leaf: overwrite its ball data with this trial's
            System.arraycopy(a, 0, q, 0, 3);
            System.arraycopy(b, 0, q, 3, 3);
            q[6] = ra;
            q[7] = rb;
            q[8] = margin;
            boolean want = ballSpec(ctx, a, b, ra, rb, margin);
            boolean got = RootUniqueness.atMostOneRoot(ctx, tab, 0);
            if (want != got) { // rounding may differ only within a hair of the threshold
                ballSpecNearThreshold(ctx, a, b, ra, rb, margin, trial);
                continue;
            }
            checked++;
            if (got) proven++; else refused++;
        }
        assertTrue(proven > 3000 && refused > 3000 && checked > 19900, proven + " proven, " + refused + " refused");
    }

    private static void ballSpecNearThreshold(TraceContext ctx, double[] a, double[] b, double ra, double rb,
                                              double margin, int trial) {
        boolean up = ballSpec(ctx, a, b, ra * (1 + 1e-9), rb * (1 + 1e-9), margin * (1 + 1e-9));
        boolean down = ballSpec(ctx, a, b, ra * (1 - 1e-9), rb * (1 - 1e-9), margin * (1 - 1e-9));
        assertTrue(up != down, "disagrees with the specification away from its threshold, trial " + trial);
    }

    /**
     * A flat leaf (zero radii) is proven single-root exactly when the ray is not parallel to it:
     * D0 = d̂·(a×b) vanishes for a ray in the plane of a and b.
     */
    @Test
    void aFlatLeafIsProvenUnlessTheRayIsParallelToIt() {
        Random rnd = new Random(2003);
        SubPatchTable tab = SubPatchTable.build(List.of(Models.flatGrid(4, 4)), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        double[] q = tab.uniqueness;
        for (int trial = 0; trial < 2000; trial++) {
            double[] a = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double[] b = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            System.arraycopy(a, 0, q, 0, 3);
            System.arraycopy(b, 0, q, 3, 3);
            q[6] = 0;
            q[7] = 0;
            q[8] = 1e-9;
            double s = rnd.nextGaussian(), t = rnd.nextGaussian();
            // in the plane: d = s·a + t·b
            ctx.setRay(0, 0, 0, s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2]);
            assertFalse(RootUniqueness.atMostOneRoot(ctx, tab, 0), "ray in the leaf's plane, trial " + trial);
            // across it: d = a×b + s·a + t·b
            double[] c = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
            if (dot(c, c) < 1e-2) {
                continue;
            }
            ctx.setRay(0, 0, 0, c[0] + s * a[0] + t * b[0], c[1] + s * a[1] + t * b[1], c[2] + s * a[2] + t * b[2]);
            assertTrue(RootUniqueness.atMostOneRoot(ctx, tab, 0), "ray across the leaf's plane, trial " + trial);
        }
    }

    /** The box test's specification: [F1u]·[F2v] − [F1v]·[F2u] excludes zero by a relative 1e-12. */
    static boolean boxSpec(double[] net, int base, int n, int m) {
        double[] f1u = range(), f2u = range(), f1v = range(), f2v = range();
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int p = base + 3 * (j * (n + 1) + i);
                if (i < n) {
                    include(f1u, net[p + 3] - net[p]);
                    include(f2u, net[p + 4] - net[p + 1]);
                }
                if (j < m) {
                    int up = p + 3 * (n + 1);
                    include(f1v, net[up] - net[p]);
                    include(f2v, net[up + 1] - net[p + 1]);
                }
            }
        }
        double[] a = product(f1u, f2v), b = product(f1v, f2u);
        double margin = 1e-12 * (Math.abs(a[0]) + Math.abs(a[1]) + Math.abs(b[0]) + Math.abs(b[1]));
        return a[0] - b[1] > margin || a[1] - b[0] < -margin;
    }

    private static double[] range() {
        return new double[] {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
    }

    private static void include(double[] r, double x) {
        r[0] = Math.min(r[0], x);
        r[1] = Math.max(r[1], x);
    }

    private static double[] product(double[] x, double[] y) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (double p : x) {
            for (double q : y) {
                lo = Math.min(lo, p * q);
                hi = Math.max(hi, p * q);
            }
        }
        return new double[] {lo, hi};
    }

    @Test
    void theBoxTestIsIntervalArithmeticOnTheDerivativeRanges() {
        Random rnd = new Random(2004);
        int proven = 0, refused = 0;
        for (int trial = 0; trial < 20000; trial++) {
            int n = 1 + rnd.nextInt(5), m = 1 + rnd.nextInt(5), base = 3 * rnd.nextInt(20);
            double[] net = new double[base + 3 * (n + 1) * (m + 1) + 12];
            for (int k = 0; k < net.length; k++) {
                net[k] = rnd.nextGaussian();
            }
            // a slanted grid with bends of every size, so both answers are common
            double cu = rnd.nextGaussian(), cv = rnd.nextGaussian(), su = rnd.nextGaussian(), sv = rnd.nextGaussian();
            double bend = Math.pow(10, -3 * rnd.nextDouble());
            for (int j = 0; j <= m; j++) {
                for (int i = 0; i <= n; i++) {
                    int p = base + 3 * (j * (n + 1) + i);
                    net[p] = cu * i + su * j + bend * rnd.nextGaussian();
                    net[p + 1] = sv * i + cv * j + bend * rnd.nextGaussian();
                }
            }
            boolean want = boxSpec(net, base, n, m);
            assertEquals(want, RootUniqueness.atMostOneRoot(net, base, n, m), "trial " + trial + " degree " + n + "x" + m);
            if (want) proven++; else refused++;
        }
        assertTrue(proven > 3000 && refused > 3000, proven + " proven, " + refused + " refused");
    }

    /**
     * A degree 2×1 ray-space net with the given u-differences of F1 and F2 along both rows and
     * constant v-differences {@code (f1v, f2v)}.
     */
    static double[] net(double[] f1u, double[] f2u, double f1v, double f2v) {
        double[] net = new double[3 * 3 * 2];
        for (int j = 0; j <= 1; j++) {
            double x = j * f1v, y = j * f2v;
            for (int i = 0; i <= 2; i++) {
                int p = 3 * (3 * j + i);
                net[p] = x;
                net[p + 1] = y;
                net[p + 2] = 5;
                if (i < 2) {
                    x += f1u[i];
                    y += f2u[i];
                }
            }
        }
        return net;
    }

    /**
     * Intervals that reach zero exactly at one end are not a proof, whatever the sizes of the
     * other ends: [F1u·F2v] = [-1, 0] against [F1v·F2u] = [0, 5], and the mirrored cases.
     */
    @Test
    void anExpressionIntervalTouchingZeroIsNoProof() {
        // F1u in [-1, 0], F2u in [0, 5], F1v = F2v = 1: a = [-1, 0], b = [0, 5]
        assertFalse(RootUniqueness.atMostOneRoot(net(new double[] {-1, 0}, new double[] {0, 5}, 1, 1), 0, 2, 1));
        // F1u in [0, 5], F2u in [-1, 0]: a = [0, 5], b = [-1, 0]
        assertFalse(RootUniqueness.atMostOneRoot(net(new double[] {0, 5}, new double[] {-1, 0}, 1, 1), 0, 2, 1));
        // F1u in [0, 1], F2u in [-5, 0]: a = [0, 1], b = [-5, 0]
        assertFalse(RootUniqueness.atMostOneRoot(net(new double[] {0, 1}, new double[] {-5, 0}, 1, 1), 0, 2, 1));
        // ... while a = [1, 1] against b = [0, 0] is one
        assertTrue(RootUniqueness.atMostOneRoot(net(new double[] {1, 1}, new double[] {0, 0}, 0, 1), 0, 2, 1));
    }
}
