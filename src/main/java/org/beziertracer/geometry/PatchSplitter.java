package org.beziertracer.geometry;

import java.util.Arrays;

import org.beziertracer.math.Bounds;
import org.beziertracer.model.BezierPatch;

/**
 * Pre-splits a patch with de Casteljau into sub-patches until each is flat enough for Bézier
 * clipping to converge in few steps (or a depth cap is reached), as in the memoir's BVH over
 * sub-patches and in Tejima, Fujita and Matsuoka, "Direct ray tracing of full-featured
 * subdivision surfaces with Bézier clipping", JCGT 4(1), 2015 (pre-subdivision of patches).
 *
 * <p>Each step halves the parametric direction whose control polygon is longer. Run at build
 * time only (allocates a few arrays per patch, none per halving).
 */
public final class PatchSplitter {
    private PatchSplitter() {}

    public static PatchPieces split(BezierPatch patch, SplitOptions options) {
        int n = patch.degreeU(), m = patch.degreeV();
        int len = (n + 1) * (m + 1) * 3;
        double[] net = patch.copyNet();
        if (!options.enabled() || options.maxDepth() == 0) {
            return new PatchPieces(n, m, 1, net, new double[] {0, 1, 0, 1});
        }
        Builder out = new Builder(len);
        new Recursion(n, m, options, out).run(net);
        return new PatchPieces(n, m, out.count, Arrays.copyOf(out.nets, out.count * len),
                Arrays.copyOf(out.boxes, out.count * 4));
    }

    /**
     * The depth-first halving with all working memory allocated once per patch: level
     * {@code d} owns two nets (the halves made from level {@code d-1}), which stay intact while
     * the lower half's subtree uses deeper levels.
     */
    private static final class Recursion {
        final int n, m, len;
        final int maxDepth;
        final double flatness;
        final Builder out;
        final double[][] lo, hi;
        final double[] box = new double[6];

        Recursion(int n, int m, SplitOptions options, Builder out) {
            this.n = n;
            this.m = m;
            this.len = (n + 1) * (m + 1) * 3;
            this.maxDepth = options.maxDepthFor(n, m);
            this.flatness = options.flatnessFor(n, m);
            this.out = out;
            int levels = maxDepth + 1;
            lo = new double[levels][len];
            hi = new double[levels][len];
        }

        void run(double[] net) {
            visit(net, 0, 1, 0, 1, 0);
        }

        private void visit(double[] net, double u0, double u1, double v0, double v1, int depth) {
            Bounds.ofPoints(net, 0, (n + 1) * (m + 1), box);
            double dx = box[3] - box[0], dy = box[4] - box[1], dz = box[5] - box[2];
            double size = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (depth >= maxDepth || NetMeasures.flatness(net, 0, n, m) <= flatness * size) {
                out.add(net, u0, u1, v0, v1);
                return;
            }
            double[] a = lo[depth + 1], b = hi[depth + 1];
            if (polygonLength(net, n, m, true) >= polygonLength(net, n, m, false)) {
                double um = 0.5 * (u0 + u1);
                DeCasteljau.splitU(net, 0, n, m, 3, 0.5, a, 0, b, 0);
                visit(a, u0, um, v0, v1, depth + 1);
                visit(b, um, u1, v0, v1, depth + 1);
            } else {
                double vm = 0.5 * (v0 + v1);
                DeCasteljau.splitV(net, 0, n, m, 3, 0.5, a, 0, b, 0);
                visit(a, u0, u1, v0, vm, depth + 1);
                visit(b, u0, u1, vm, v1, depth + 1);
            }
        }
    }

    /** Largest control-polygon length over the rows (along u) or the columns (along v). */
    static double polygonLength(double[] net, int n, int m, boolean alongU) {
        int outer = alongU ? m : n, inner = alongU ? n : m;
        double longest = 0;
        for (int a = 0; a <= outer; a++) {
            double sum = 0;
            for (int b = 0; b < inner; b++) {
                int p = alongU ? 3 * (a * (n + 1) + b) : 3 * (b * (n + 1) + a);
                int q = alongU ? p + 3 : p + 3 * (n + 1);
                double ex = net[q] - net[p], ey = net[q + 1] - net[p + 1], ez = net[q + 2] - net[p + 2];
                sum += Math.sqrt(ex * ex + ey * ey + ez * ez);
            }
            longest = Math.max(longest, sum);
        }
        return longest;
    }

    private static final class Builder {
        final int len;
        double[] nets;
        double[] boxes = new double[64];
        int count;

        Builder(int len) {
            this.len = len;
            this.nets = new double[16 * len];
        }

        void add(double[] net, double u0, double u1, double v0, double v1) {
            if ((count + 1) * len > nets.length) {
                nets = Arrays.copyOf(nets, nets.length * 2);
            }
            if ((count + 1) * 4 > boxes.length) {
                boxes = Arrays.copyOf(boxes, boxes.length * 2);
            }
            System.arraycopy(net, 0, nets, count * len, len);
            boxes[4 * count] = u0;
            boxes[4 * count + 1] = u1;
            boxes[4 * count + 2] = v0;
            boxes[4 * count + 3] = v1;
            count++;
        }
    }
}
