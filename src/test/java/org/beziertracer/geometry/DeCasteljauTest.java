package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.beziertracer.geometry.TestNets.degrees;
import static org.beziertracer.geometry.TestNets.eval;
import static org.beziertracer.geometry.TestNets.maxDiff;
import static org.beziertracer.geometry.TestNets.randomDegree;
import static org.beziertracer.geometry.TestNets.randomNet;
import static org.beziertracer.geometry.TestNets.size;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.Random;

import org.junit.jupiter.api.Test;

class DeCasteljauTest {

    /** de Casteljau against the independent Bernstein sum (the sum itself loses a few digits). */
    private static final double BERNSTEIN_REL = 1e-11;
    /**
     * Central differences with step {@link #FD_STEP}: truncation ≤ h²/6·|S'''| and
     * |S'''| ≤ 8·deg³·size (third differences of the net), so h²·8/6 ≈ 1.4e-10 per deg³;
     * rounding adds about ulp(size)/h ≈ 1e-11. Relative to net size.
     */
    private static final double FD_REL = 2e-10;
    private static final double FD_ROUNDING_REL = 1e-9;
    private static final double FD_STEP = 1e-5;
    private static final int TRIALS = 200;
    private static final int SAMPLES = 10;
    private static final int[] DIMS = {1, 2, 3};

    @Test
    void evaluationMatchesTheBernsteinSum() {
        Random rnd = new Random(1);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), dim = DIMS[trial % 3];
            double[] net = randomNet(rnd, n, m, dim, 10);
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            double err = maxDiff(eval(net, 0, n, m, dim, u, v), TestNets.bernstein(net, n, m, dim, u, v));
            assertTrue(err <= BERNSTEIN_REL * size(net, 0, net.length),
                    () -> degrees(n, m, dim) + " at (" + u + "," + v + "): error " + err);
        }
    }

    @Test
    void evaluationAtTheCornersReturnsTheCornerControlPoints() {
        Random rnd = new Random(2);
        int n = 4, m = 7, dim = 3;
        double[] net = randomNet(rnd, n, m, dim, 5);
        int[][] corners = {{0, 0}, {n, 0}, {0, m}, {n, m}};
        for (int[] c : corners) {
            int k = (c[1] * (n + 1) + c[0]) * dim;
            assertArrayEquals(Arrays.copyOfRange(net, k, k + dim),
                    eval(net, 0, n, m, dim, (double) c[0] / n, (double) c[1] / m), 0, "corner " + Arrays.toString(c));
        }
    }

    @Test
    void evaluationHonoursOffsetsAndLeavesTheNetUnchanged() {
        Random rnd = new Random(3);
        int n = 3, m = 5, dim = 2, pad = 7;
        double[] net = randomNet(rnd, n, m, dim, 1);
        double[] padded = new double[net.length + 2 * pad];
        System.arraycopy(net, 0, padded, pad, net.length);
        double[] before = padded.clone();
        double[] out = new double[dim + 4];
        DeCasteljau.evaluate(padded, pad, n, m, dim, 0.3, 0.8, out, 4, new double[DeCasteljau.SCRATCH_LENGTH]);
        assertArrayEquals(before, padded, 0, "net modified");
        assertArrayEquals(eval(net, 0, n, m, dim, 0.3, 0.8), Arrays.copyOfRange(out, 4, 4 + dim), 0);
    }

    @Test
    void splitHalvesReproduceTheParentSurfaceAtMappedParameters() {
        Random rnd = new Random(4);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), dim = DIMS[trial % 3];
            boolean inU = trial % 2 == 0;
            double[] net = randomNet(rnd, n, m, dim, 100);
            double t = rnd.nextDouble();
            double[] lo = new double[net.length], hi = new double[net.length];
            if (inU) {
                DeCasteljau.splitU(net, 0, n, m, dim, t, lo, 0, hi, 0);
            } else {
                DeCasteljau.splitV(net, 0, n, m, dim, t, lo, 0, hi, 0);
            }
            double tol = ROUNDING * size(net, 0, net.length);
            for (int s = 0; s < SAMPLES; s++) {
                double a = rnd.nextDouble(), b = rnd.nextDouble();
                double[] pLo = inU ? eval(net, 0, n, m, dim, a * t, b) : eval(net, 0, n, m, dim, b, a * t);
                double[] pHi = inU ? eval(net, 0, n, m, dim, t + a * (1 - t), b)
                        : eval(net, 0, n, m, dim, b, t + a * (1 - t));
                double errLo = maxDiff(pLo, inU ? eval(lo, 0, n, m, dim, a, b) : eval(lo, 0, n, m, dim, b, a));
                double errHi = maxDiff(pHi, inU ? eval(hi, 0, n, m, dim, a, b) : eval(hi, 0, n, m, dim, b, a));
                String what = (inU ? "splitU " : "splitV ") + degrees(n, m, dim) + " at t=" + t + ", local (" + a + "," + b + ")";
                assertTrue(errLo <= tol, () -> what + ": low half error " + errLo);
                assertTrue(errHi <= tol, () -> what + ": high half error " + errHi);
            }
        }
    }

    @Test
    void splitInPlaceGivesTheSameHalvesAsSplitIntoSeparateArrays() {
        Random rnd = new Random(5);
        for (int trial = 0; trial < 40; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), dim = DIMS[trial % 3];
            boolean inU = trial % 2 == 0;
            double[] net = randomNet(rnd, n, m, dim, 1);
            double t = rnd.nextDouble();
            double[] lo = new double[net.length], hi = new double[net.length];
            split(inU, net, n, m, dim, t, lo, hi);
            String what = (inU ? "splitU " : "splitV ") + degrees(n, m, dim) + " t=" + t;
            // Low half written over the source, high half elsewhere
            double[] a = net.clone(), aHi = new double[net.length];
            split(inU, a, n, m, dim, t, a, aHi);
            assertArrayEquals(lo, a, 0, what + ": lo == src");
            assertArrayEquals(hi, aHi, 0, what + ": lo == src, hi");
            // High half written over the source, low half elsewhere
            double[] b = net.clone(), bLo = new double[net.length];
            split(inU, b, n, m, dim, t, bLo, b);
            assertArrayEquals(hi, b, 0, what + ": hi == src");
            assertArrayEquals(lo, bLo, 0, what + ": hi == src, lo");
            // One half only
            double[] c = net.clone();
            split(inU, c, n, m, dim, t, null, c);
            assertArrayEquals(hi, c, 0, what + ": hi only, in place");
            double[] d = net.clone();
            split(inU, d, n, m, dim, t, d, null);
            assertArrayEquals(lo, d, 0, what + ": lo only, in place");
        }
    }

    @Test
    void splitAndSubPatchHonourOutputsInOtherRegionsOfTheSourceArray() {
        Random rnd = new Random(55);
        for (int trial = 0; trial < 24; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6), dim = DIMS[trial % 3], len = (n + 1) * (m + 1) * dim;
            boolean inU = trial % 2 == 0;
            double[] net = randomNet(rnd, n, m, dim, 1);
            double t = rnd.nextDouble();
            double[] lo = new double[len], hi = new double[len];
            split(inU, net, n, m, dim, t, lo, hi);
            String what = (inU ? "splitU " : "splitV ") + degrees(n, m, dim) + " t=" + t;
            // One array: the source at 0, lo at len, hi at 2 len; each output alone, then both
            for (int outputs = 1; outputs <= 3; outputs++) {
                double[] all = new double[3 * len];
                System.arraycopy(net, 0, all, 0, len);
                double[] loArr = (outputs & 1) != 0 ? all : null, hiArr = (outputs & 2) != 0 ? all : null;
                if (inU) {
                    DeCasteljau.splitU(all, 0, n, m, dim, t, loArr, len, hiArr, 2 * len);
                } else {
                    DeCasteljau.splitV(all, 0, n, m, dim, t, loArr, len, hiArr, 2 * len);
                }
                assertArrayEquals(net, Arrays.copyOfRange(all, 0, len), 0, what + ": source kept, outputs " + outputs);
                if (loArr != null) {
                    assertArrayEquals(lo, Arrays.copyOfRange(all, len, 2 * len), 0, what + ": lo, outputs " + outputs);
                }
                if (hiArr != null) {
                    assertArrayEquals(hi, Arrays.copyOfRange(all, 2 * len, 3 * len), 0, what + ": hi, outputs " + outputs);
                }
            }
            // A separate array at the source's offset, the other half in place or skipped
            double[] sepLo = new double[len], inPlaceHi = net.clone();
            split(inU, inPlaceHi, n, m, dim, t, sepLo, inPlaceHi);
            assertArrayEquals(lo, sepLo, 0, what + ": separate lo, hi in place");
            double[] onlyLo = new double[len], onlyHi = new double[len];
            split(inU, net.clone(), n, m, dim, t, onlyLo, null);
            split(inU, net.clone(), n, m, dim, t, null, onlyHi);
            assertArrayEquals(lo, onlyLo, 0, what + ": separate lo only");
            assertArrayEquals(hi, onlyHi, 0, what + ": separate hi only");
            // subPatch into another region of the same array, and into another array at the same offset
            double[] box = {0.2 * t, 0.5 + 0.5 * t, 0.1, 0.9}, expected = net.clone();
            DeCasteljau.subPatch(expected, 0, n, m, dim, box[0], box[1], box[2], box[3], expected, 0);
            double[] shared = new double[2 * len], other = new double[len];
            System.arraycopy(net, 0, shared, 0, len);
            DeCasteljau.subPatch(shared, 0, n, m, dim, box[0], box[1], box[2], box[3], shared, len);
            DeCasteljau.subPatch(net, 0, n, m, dim, box[0], box[1], box[2], box[3], other, 0);
            assertArrayEquals(expected, Arrays.copyOfRange(shared, len, 2 * len), 0, what + ": subPatch, same array");
            assertArrayEquals(expected, other, 0, what + ": subPatch, other array");
        }
    }

    private static void split(boolean inU, double[] src, int n, int m, int dim, double t, double[] lo, double[] hi) {
        if (inU) {
            DeCasteljau.splitU(src, 0, n, m, dim, t, lo, 0, hi, 0);
        } else {
            DeCasteljau.splitV(src, 0, n, m, dim, t, lo, 0, hi, 0);
        }
    }

    @Test
    void theUnrolledThreeDimensionalSplitGivesTheGenericSplitsNumbersToTheLastBit() {
        // The same net with a fourth coordinate goes through the generic loop; x, y, z must agree
        Random rnd = new Random(88);
        for (int trial = 0; trial < 200; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), points = (n + 1) * (m + 1);
            double[] net3 = randomNet(rnd, n, m, 3, 1 + 100 * rnd.nextDouble());
            double[] net4 = new double[4 * points];
            for (int k = 0; k < points; k++) {
                System.arraycopy(net3, 3 * k, net4, 4 * k, 3);
                net4[4 * k + 3] = rnd.nextDouble();
            }
            double t = trial % 2 == 0 ? 0.5 : rnd.nextDouble();
            boolean alongU = rnd.nextBoolean();
            double[] lo3 = new double[3 * points], hi3 = new double[3 * points];
            double[] lo4 = new double[4 * points], hi4 = new double[4 * points];
            if (alongU) {
                DeCasteljau.splitU(net3, 0, n, m, 3, t, lo3, 0, hi3, 0);
                DeCasteljau.splitU(net4, 0, n, m, 4, t, lo4, 0, hi4, 0);
            } else {
                DeCasteljau.splitV(net3, 0, n, m, 3, t, lo3, 0, hi3, 0);
                DeCasteljau.splitV(net4, 0, n, m, 4, t, lo4, 0, hi4, 0);
            }
            for (int k = 0; k < points; k++) {
                for (int c = 0; c < 3; c++) {
                    String in = "trial " + trial + " point " + k + " coordinate " + c;
                    org.junit.jupiter.api.Assertions.assertEquals(lo4[4 * k + c], lo3[3 * k + c], 0, in + " (low half)");
                    org.junit.jupiter.api.Assertions.assertEquals(hi4[4 * k + c], hi3[3 * k + c], 0, in + " (high half)");
                }
            }
        }
    }

    @Test
    void restrictionMatchesTheParentAtMappedParameters() {
        Random rnd = new Random(6);
        double[][] special = {{0, 1}, {0, 1e-9}, {1 - 1e-9, 1}, {0.3, 0.3}, {0, 0}, {1, 1}, {0.25, 0.75}};
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), dim = DIMS[trial % 3];
            boolean inU = trial % 2 == 0;
            double[] net = randomNet(rnd, n, m, dim, 100);
            double a, b;
            if (trial < special.length * 2) {
                a = special[trial / 2][0];
                b = special[trial / 2][1];
            } else {
                double x = rnd.nextDouble(), y = rnd.nextDouble();
                a = Math.min(x, y);
                b = Math.max(x, y);
            }
            double[] r = net.clone();
            if (inU) {
                DeCasteljau.restrictU(r, 0, n, m, dim, a, b);
            } else {
                DeCasteljau.restrictV(r, 0, n, m, dim, a, b);
            }
            double tol = ROUNDING * size(net, 0, net.length);
            for (int s = 0; s < SAMPLES; s++) {
                double p = rnd.nextDouble(), q = rnd.nextDouble(), mapped = a + p * (b - a);
                double[] expected = inU ? eval(net, 0, n, m, dim, mapped, q) : eval(net, 0, n, m, dim, q, mapped);
                double[] actual = inU ? eval(r, 0, n, m, dim, p, q) : eval(r, 0, n, m, dim, q, p);
                double err = maxDiff(expected, actual);
                String what = (inU ? "restrictU " : "restrictV ") + degrees(n, m, dim) + " to [" + a + "," + b
                        + "], local (" + p + "," + q + ")";
                assertTrue(err <= tol, () -> what + ": error " + err);
            }
        }
    }

    @Test
    void subPatchMatchesTheParentAtMappedParameters() {
        Random rnd = new Random(7);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), dim = DIMS[trial % 3];
            double[] net = randomNet(rnd, n, m, dim, 100);
            double[] box = new double[4];
            for (int k = 0; k < 4; k += 2) {
                double x = rnd.nextDouble(), y = rnd.nextDouble();
                box[k] = Math.min(x, y);
                box[k + 1] = Math.max(x, y);
            }
            int pad = 5;
            double[] dest = new double[net.length + pad];
            DeCasteljau.subPatch(net, 0, n, m, dim, box[0], box[1], box[2], box[3], dest, pad);
            double[] inPlace = net.clone();
            DeCasteljau.subPatch(inPlace, 0, n, m, dim, box[0], box[1], box[2], box[3], inPlace, 0);
            assertArrayEquals(Arrays.copyOfRange(dest, pad, dest.length), inPlace, 0, "in place differs");
            double tol = ROUNDING * size(net, 0, net.length);
            for (int s = 0; s < SAMPLES; s++) {
                double p = rnd.nextDouble(), q = rnd.nextDouble();
                double[] expected = eval(net, 0, n, m, dim, box[0] + p * (box[1] - box[0]), box[2] + q * (box[3] - box[2]));
                double err = maxDiff(expected, eval(dest, pad, n, m, dim, p, q));
                assertTrue(err <= tol, () -> "subPatch " + degrees(n, m, dim) + " box " + Arrays.toString(box)
                        + " local (" + p + "," + q + "): error " + err);
            }
        }
    }

    @Test
    void derivativesMatchCentralFiniteDifferences() {
        Random rnd = new Random(8);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = randomDegree(rnd), m = randomDegree(rnd), dim = DIMS[trial % 3];
            double[] net = randomNet(rnd, n, m, dim, 1);
            double u = FD_STEP + rnd.nextDouble() * (1 - 2 * FD_STEP), v = FD_STEP + rnd.nextDouble() * (1 - 2 * FD_STEP);
            double[] d = new double[3 * dim];
            DeCasteljau.evaluateWithDerivatives(net, 0, n, m, dim, u, v, d, 0, scratch, 0);
            double[] s = eval(net, 0, n, m, dim, u, v);
            double[] su = sub(eval(net, 0, n, m, dim, u + FD_STEP, v), eval(net, 0, n, m, dim, u - FD_STEP, v));
            double[] sv = sub(eval(net, 0, n, m, dim, u, v + FD_STEP), eval(net, 0, n, m, dim, u, v - FD_STEP));
            // Higher degrees have larger third derivatives (~deg³): scale the tolerance
            double tol = (FD_REL * Math.pow(Math.max(n, m), 3) + FD_ROUNDING_REL) * size(net, 0, net.length);
            String what = degrees(n, m, dim) + " at (" + u + "," + v + ")";
            assertTrue(maxDiff(s, Arrays.copyOfRange(d, 0, dim)) <= ROUNDING, what + ": position");
            double eu = maxDiff(su, Arrays.copyOfRange(d, dim, 2 * dim));
            double ev = maxDiff(sv, Arrays.copyOfRange(d, 2 * dim, 3 * dim));
            assertTrue(eu <= tol, () -> what + ": dS/du error " + eu);
            assertTrue(ev <= tol, () -> what + ": dS/dv error " + ev);
        }
    }

    private static double[] sub(double[] plus, double[] minus) {
        double[] out = new double[plus.length];
        for (int c = 0; c < out.length; c++) {
            out[c] = (plus[c] - minus[c]) / (2 * FD_STEP);
        }
        return out;
    }

    @Test
    void theThreeDimensionalDerivativeFormAgreesWithTheGenericOne() {
        Random rnd = new Random(9);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int n = 3, m = 6;
        double[] net = randomNet(rnd, n, m, 3, 2);
        double[] a = new double[9], b = new double[9];
        DeCasteljau.evaluateWithDerivatives(net, 0, n, m, 0.2, 0.9, a, scratch);
        DeCasteljau.evaluateWithDerivatives(net, 0, n, m, 3, 0.2, 0.9, b, 0, scratch, 0);
        assertArrayEquals(b, a, 0);
    }

    @Test
    void curveEvaluationMatchesTheBernsteinSum() {
        Random rnd = new Random(10);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < 50; trial++) {
            int deg = randomDegree(rnd), dim = DIMS[trial % 3];
            double[] pts = randomNet(rnd, deg, 0, dim, 3);
            double t = rnd.nextDouble();
            double[] out = new double[dim];
            DeCasteljau.evaluateCurve(pts, 0, dim, deg, dim, t, out, 0, scratch);
            double[] expected = TestNets.bernstein(pts, deg, 0, dim, t, 0);
            assertTrue(maxDiff(expected, out) <= BERNSTEIN_REL * 3, "degree " + deg + " dim " + dim + " t " + t);
        }
    }

    @Test
    void hotMethodsAllocateNothing() {
        var bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        Random rnd = new Random(11);
        int n = 15, m = 15, dim = 3, calls = 2000;
        double[] net = randomNet(rnd, n, m, dim, 1), work = net.clone(), lo = net.clone(), hi = net.clone();
        double[] out = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        Runnable body = () -> {
            for (int k = 0; k < calls; k++) {
                double t = (k + 0.5) / calls;
                DeCasteljau.evaluate(net, 0, n, m, dim, t, 1 - t, out, 0, scratch);
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, t, 1 - t, out, scratch);
                DeCasteljau.splitU(net, 0, n, m, dim, t, lo, 0, hi, 0);
                DeCasteljau.splitV(net, 0, n, m, dim, t, lo, 0, hi, 0);
                DeCasteljau.subPatch(net, 0, n, m, dim, 0.1, t, 0.2, 0.9, work, 0);
                PatchNormals.unitNormal(net, 0, n, m, t, 0, out, 0, scratch);
                NetMeasures.flatness(net, 0, n, m);
            }
        };
        body.run(); // warm up (class loading, JIT)
        long tid = Thread.currentThread().getId();
        long before = bean.getThreadAllocatedBytes(tid);
        body.run();
        long allocated = bean.getThreadAllocatedBytes(tid) - before;
        // The probe itself must see a known allocation
        long probeBefore = bean.getThreadAllocatedBytes(tid);
        double[] probe = new double[1000];
        long probed = bean.getThreadAllocatedBytes(tid) - probeBefore;
        assertTrue(probed >= 8000 && probe.length == 1000, "allocation probe saw only " + probed + " bytes");
        // A single array per call would be ≥ 16 bytes × 7 methods × calls; allow measurement noise
        assertTrue(allocated < 4096, "allocated " + allocated + " bytes in " + calls + " rounds");
    }
}
