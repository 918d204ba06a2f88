package org.beziertracer.geometry;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;

/**
 * Shared fixtures for the geometry tests: random nets, an independent Bernstein-sum reference
 * evaluator, and a tiny local reader for the bundled teapot (the real BPT reader lives in
 * {@code model.io} and is written in parallel).
 */
final class TestNets {

    private TestNets() {}

    /** Random net of {@code (n+1)(m+1)*dim} coordinates in {@code [-scale, scale]}. */
    static double[] randomNet(Random rnd, int n, int m, int dim, double scale) {
        double[] net = new double[(n + 1) * (m + 1) * dim];
        for (int k = 0; k < net.length; k++) {
            net[k] = scale * (2 * rnd.nextDouble() - 1);
        }
        return net;
    }

    /** Random degree 1..15. */
    static int randomDegree(Random rnd) {
        return 1 + rnd.nextInt(BezierPatch.MAX_DEGREE);
    }

    /** Largest absolute coordinate: the "net size" that tolerances are relative to. */
    static double size(double[] net, int off, int len) {
        double s = 0;
        for (int k = off; k < off + len; k++) {
            s = Math.max(s, Math.abs(net[k]));
        }
        return s;
    }

    /** Reference: {@code S(u,v) = Σ Σ B_i^n(u) B_j^m(v) P_ij} computed term by term. */
    static double[] bernstein(double[] net, int n, int m, int dim, double u, double v) {
        double[] out = new double[dim];
        for (int j = 0; j <= m; j++) {
            double bj = basis(m, j, v);
            for (int i = 0; i <= n; i++) {
                double w = basis(n, i, u) * bj;
                for (int c = 0; c < dim; c++) {
                    out[c] += w * net[(j * (n + 1) + i) * dim + c];
                }
            }
        }
        return out;
    }

    static double basis(int n, int i, double t) {
        double binom = 1;
        for (int k = 1; k <= i; k++) {
            binom = binom * (n - i + k) / k;
        }
        return binom * Math.pow(t, i) * Math.pow(1 - t, n - i);
    }

    static double[] eval(double[] net, int off, int n, int m, int dim, double u, double v) {
        double[] out = new double[dim];
        DeCasteljau.evaluate(net, off, n, m, dim, u, v, out, 0, new double[DeCasteljau.SCRATCH_LENGTH]);
        return out;
    }

    static double maxDiff(double[] a, double[] b) {
        double d = 0;
        for (int k = 0; k < a.length; k++) {
            d = Math.max(d, Math.abs(a[k] - b[k]));
        }
        return d;
    }

    static String degrees(int n, int m, int dim) {
        return "degree " + n + "x" + m + ", dim " + dim;
    }

    /** The 32 patches of the bundled teapot, parsed with a whitespace tokeniser. */
    static List<BezierPatch> teapot() {
        String text;
        try (InputStream in = TestNets.class.getResourceAsStream("/org/beziertracer/models/teapot.bpt")) {
            if (in == null) {
                throw new IllegalStateException("teapot.bpt not on the class path");
            }
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
        String[] tok = text.trim().split("\\s+");
        int pos = 0;
        int count = Integer.parseInt(tok[pos++]);
        List<BezierPatch> patches = new ArrayList<>();
        for (int p = 0; p < count; p++) {
            int n = Integer.parseInt(tok[pos++]), m = Integer.parseInt(tok[pos++]);
            double[] net = new double[(n + 1) * (m + 1) * 3];
            for (int k = 0; k < net.length; k++) {
                net[k] = Double.parseDouble(tok[pos++]);
            }
            patches.add(new BezierPatch(n, m, net));
        }
        return patches;
    }
}
