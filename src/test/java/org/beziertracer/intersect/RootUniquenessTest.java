package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link RootUniqueness}: whenever it says a piece meets the ray at most once, no search finds two
 * roots there; and it does say so often enough to be useful.
 */
class RootUniquenessTest {

    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];

    /**
     * Distinct roots of {@code F = (x, y) = 0} over {@code [0,1]²} of the ray-space net at
     * {@code net[off..]}, found by Newton from a 12×12 grid of starts (a lower bound on the true
     * count, exact for the mildly curved nets used here).
     */
    int countRoots(double[] net, int off, int n, int m, double size) {
        double[] e = new double[9], roots = new double[2 * 144];
        int count = 0;
        for (int a = 0; a < 12; a++) {
            for (int b = 0; b < 12; b++) {
                double u = (a + 0.5) / 12, v = (b + 0.5) / 12;
                boolean converged = false;
                for (int step = 0; step < 40 && !converged; step++) {
                    DeCasteljau.evaluateWithDerivatives(net, off, n, m, u, v, e, scratch);
                    if (Math.max(Math.abs(e[0]), Math.abs(e[1])) <= 1e-13 * size) {
                        converged = true;
                        break;
                    }
                    double det = e[3] * e[7] - e[6] * e[4];
                    if (det == 0) {
                        break;
                    }
                    u -= (e[0] * e[7] - e[6] * e[1]) / det;
                    v -= (e[3] * e[1] - e[0] * e[4]) / det;
                    if (!(Math.abs(u - 0.5) < 2 && Math.abs(v - 0.5) < 2)) {
                        break;
                    }
                }
                if (!converged || u < -1e-9 || u > 1 + 1e-9 || v < -1e-9 || v > 1 + 1e-9) {
                    continue;
                }
                boolean known = false;
                for (int r = 0; r < count && !known; r++) {
                    known = Math.abs(roots[2 * r] - u) + Math.abs(roots[2 * r + 1] - v) < 1e-7;
                }
                if (!known) {
                    roots[2 * count] = u;
                    roots[2 * count + 1] = v;
                    count++;
                }
            }
        }
        return count;
    }

    /**
     * A ray-space net around the ray: a slanted grid through the origin bent by random offsets of
     * up to {@code bend} of its size (small bends keep one root; large ones fold the net).
     */
    static double[] bentGrid(Random rnd, int n, int m, double bend) {
        double[] net = new double[3 * (n + 1) * (m + 1)];
        double cu = 0.2 + rnd.nextDouble(), cv = 0.2 + rnd.nextDouble(), skew = rnd.nextGaussian() * 0.5;
        double ou = -cu * rnd.nextDouble(), ov = -cv * rnd.nextDouble();
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                double s = (double) i / n, t = (double) j / m;
                net[k] = ou + cu * s + skew * t + bend * rnd.nextGaussian();
                net[k + 1] = ov + cv * t + bend * rnd.nextGaussian();
                net[k + 2] = 5 + rnd.nextDouble();
            }
        }
        return net;
    }

    @Test
    void aPieceProvenSingleRootNeverHoldsTwo() {
        Random rnd = new Random(2001);
        int provenWithRoot = 0, multiple = 0;
        for (int trial = 0; trial < 3000; trial++) {
            int n = 1 + rnd.nextInt(4), m = 1 + rnd.nextInt(4);
            double[] net = bentGrid(rnd, n, m, rnd.nextDouble() < 0.5 ? 0.05 * rnd.nextDouble() : 0.8 * rnd.nextDouble());
            boolean unique = RootUniqueness.atMostOneRoot(net, 0, n, m);
            int roots = countRoots(net, 0, n, m, 2);
            if (unique) {
                assertTrue(roots <= 1, roots + " roots in a piece proven single-root, trial " + trial);
                provenWithRoot += roots;
            }
            if (roots > 1) {
                multiple++;
                assertFalse(unique, "trial " + trial);
            }
        }
        assertTrue(provenWithRoot > 500, "single-root proofs on pieces with a root: " + provenWithRoot);
        assertTrue(multiple > 20, "pieces with several roots: " + multiple);
    }

    @Test
    void aFoldedPieceIsNotProvenSingleRoot() {
        // A quadratic curve in x bent back over the ray: x = (s - 0.5)² - 0.1 has two roots
        int n = 2, m = 1;
        double[] net = new double[3 * 3 * 2];
        double[] xs = {0.15, -0.35, 0.15};
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * 3 + i);
                net[k] = xs[i];
                net[k + 1] = j - 0.5;
                net[k + 2] = 5;
            }
        }
        assertTrue(countRoots(net, 0, n, m, 1) == 2, "the fixture has two roots");
        assertFalse(RootUniqueness.atMostOneRoot(net, 0, n, m));
    }

    @Test
    void twoCurvesCrossingTwiceAreNotProvenSingleRoot() {
        // F1 = u - 0.4 - 4(v - 0.5)², F2 = v - u: roots at u = v = 0.424 and 0.826. Both F1u and
        // F2v stay positive, so only the cross term F1v·F2u can refuse the proof
        int n = 1, m = 2;
        double[] c = {-1, 1, -1}, vs = {0, 0.5, 1};
        double[] net = new double[3 * 2 * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * 2 + i);
                net[k] = i - 0.4 + c[j];
                net[k + 1] = vs[j] - i;
                net[k + 2] = 5;
            }
        }
        assertTrue(countRoots(net, 0, n, m, 1) == 2, "the fixture has two roots");
        assertFalse(RootUniqueness.atMostOneRoot(net, 0, n, m));
    }

    /** The precomputed per-leaf test, for rays aimed at random points of random sub-patches. */
    @Test
    void aLeafProvenSingleRootForARayNeverHoldsTwo() {
        Random rnd = new Random(2005);
        int proven = 0, tested = 0;
        double[] s = new double[3], projected = new double[3 * DeCasteljau.MAX_ORDER * DeCasteljau.MAX_ORDER];
        TraceContext ctx = new TraceContext();
        for (int trial = 0; trial < 60; trial++) {
            int n = 1 + rnd.nextInt(5), m = 1 + rnd.nextInt(5);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, 4, 0.3 + rnd.nextDouble());
            SubPatchTable tab = SubPatchTable.build(List.of(patch), new SplitOptions(true, 0.2, 1 + rnd.nextInt(4)));
            for (int r = 0; r < 40; r++) {
                int leaf = rnd.nextInt(tab.count);
                int off = tab.netOffset[leaf];
                DeCasteljau.evaluate(tab.nets, off, n, m, 3, rnd.nextDouble(), rnd.nextDouble(), s, 0, scratch);
                double ox = s[0] + 2 * rnd.nextGaussian(), oy = s[1] + 2 * rnd.nextGaussian(), oz = 8 + 4 * rnd.nextDouble();
                ctx.setRay(ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz);
                tested++;
                if (!RootUniqueness.atMostOneRoot(ctx, tab, leaf)) {
                    continue;
                }
                proven++;
                ctx.project(tab.nets, off, (n + 1) * (m + 1), projected, 0);
                int roots = countRoots(projected, 0, n, m, 4);
                assertTrue(roots <= 1, roots + " roots on leaf " + leaf + " of a degree " + n + "x" + m
                        + " patch proven single-root, trial " + trial + " ray " + r);
                assertTrue(roots == 1, "the ray was aimed at the leaf, trial " + trial + " ray " + r);
            }
        }
        assertTrue(proven > 200, "proven " + proven + " of " + tested);
    }
}
