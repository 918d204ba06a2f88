package org.beziertracer.geometry;

import java.util.Arrays;
import java.util.concurrent.ForkJoinTask;

import org.beziertracer.math.Bounds;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;

/**
 * Pre-splits a patch with de Casteljau into sub-patches until each is flat enough for Bézier
 * clipping to converge in few steps (or a depth cap is reached), as in the memoir's BVH over
 * sub-patches and in Tejima, Fujita and Matsuoka, "Direct ray tracing of full-featured
 * subdivision surfaces with Bézier clipping", JCGT 4(1), 2015 (pre-subdivision of patches).
 *
 * <p>Each step halves the parametric direction whose control polygon is longer. A rational patch
 * is halved through its homogeneous net ({@link RationalDeCasteljau}); a piece counts as flat
 * when its Euclidean net is flat and its weights are within {@link #WEIGHT_SPREAD} of each other
 * (the weights of a piece converge to equal values as it shrinks). A trimmed patch's pieces are
 * classified against its trim loops ({@link TrimCurves#classify}, on the piece's box in the
 * surface's parameters grown by {@link #TRIM_MARGIN} on each side, so that hits a solver reports
 * slightly outside a leaf are covered): a piece wholly outside is dropped, with all its
 * descendants; a piece wholly inside needs no trim test for its hits; a piece a trim curve crosses
 * is split on to the depth cap. A piece whose control-box diagonal is below a minimum size is not
 * halved either (the scene-relative stop that {@link SubPatchTable} sets, so that a model of many
 * small patches is not split many-fold). Run at build time only (allocates a few arrays per patch,
 * none per halving).
 */
public final class PatchSplitter {
    private PatchSplitter() {}

    /** Growth of a piece's parameter box, as a fraction of its size on each side, for trim classification. */
    static final double TRIM_MARGIN = 0.05;
    /**
     * Largest ratio between a rational piece's weights before it is split further: pieces whose
     * weights vary less have derivatives of steadier length, so the single-root test of
     * {@link HodographBounds#computeRational} succeeds as often as on polynomial pieces. (On
     * {@code FreeFormBench}'s rational tiles, 1.1–1.25 cost about the same per ray, 10–25 % less
     * than no such limit; 1.2 keeps the leaf count moderate.)
     */
    static final double WEIGHT_SPREAD = 1.2;

    public static PatchPieces split(BezierPatch patch, SplitOptions options) {
        return split(patch, options, 0);
    }

    /**
     * As {@link #split(BezierPatch, SplitOptions)}, and a piece whose control-box diagonal is below
     * {@code minSize} (model units) is not halved.
     */
    public static PatchPieces split(BezierPatch patch, SplitOptions options, double minSize) {
        return split(patch, options, patch.trim() == null ? null : TrimCurves.of(patch.trim()), minSize);
    }

    /** As {@link #split(BezierPatch, SplitOptions)}, with the patch's trim curves built by the caller (or null). */
    public static PatchPieces split(BezierPatch patch, SplitOptions options, TrimCurves trim) {
        return split(patch, options, trim, 0);
    }

    /** With the caller's trim curves (or null) and the scene-relative stop {@code minSize}. */
    public static PatchPieces split(BezierPatch patch, SplitOptions options, TrimCurves trim, double minSize) {
        return split(patch, options, trim, minSize, new Workspace());
    }

    /**
     * As {@link #split(BezierPatch, SplitOptions, TrimCurves, double)}, in the working memory
     * {@code w} of the calling thread, which a build reuses from patch to patch.
     */
    public static PatchPieces split(BezierPatch patch, SplitOptions options, TrimCurves trim, double minSize,
                                    Workspace w) {
        int n = patch.degreeU(), m = patch.degreeV();
        int dim = Patches.dim(patch);
        w.out.reset((n + 1) * (m + 1), dim == 4, trim != null);
        Recursion r = new Recursion(n, m, dim, options, minSize, w, trim, patch.domain());
        r.visit(Patches.workingNet(patch), 0, 1, 0, 1, 0, trim == null ? TrimCurves.INSIDE : TrimCurves.MIXED, null);
        return w.out.pieces(n, m);
    }

    /**
     * A kept leaf of {@link #resplit} may be this many times as far from flat (relative to its size)
     * as a fresh split allows before it is halved on: a drag that bends a leaf a little keeps the
     * leaf count, so the BVH is refitted, not rebuilt.
     */
    static final double KEPT_SLACK = 2;

    /**
     * {@code patch} (an edit of an untrimmed patch of the same degree) split along the halvings of an
     * earlier split, whose leaves' parameter boxes are {@code boxes[4·from .. 4·to)} in the order it
     * made them ({@link SubPatchTable#boxes}): each old leaf whose new net is still within
     * {@link #KEPT_SLACK} times the tolerance of flat (the depth cap and the scene's stop as in
     * {@link #split}) stays a leaf, any other is split on afresh below it. Internal nodes are halved
     * as before without a test, so a drag re-splits its patch without deciding every halving again,
     * and usually makes the same leaves (same count). Returns null for a trimmed patch or when the
     * boxes are not such a split (then {@link #split} is the way).
     */
    public static PatchPieces resplit(BezierPatch patch, SplitOptions options, double minSize, Workspace w,
                                      float[] boxes, int from, int to) {
        if (patch.trim() != null || to <= from) {
            return null;
        }
        double[] net = Patches.workingNet(patch);
        SplitGuide guide = new SplitGuide(boxes, from, to);
        if (to - from < PARALLEL_LEAVES || guide.takeLeaf(0, 1, 0, 1)) {
            return replay(patch, options, minSize, w, net, 0, 1, 0, 1, new SplitGuide(boxes, from, to));
        }
        // Many leaves (a degree-9 patch has hundreds): the two halves of the root on two threads
        boolean inU = guide.halvedInU(0, 1, 0, 1);
        int mid = inU ? guide.runEnd(0, 0.5, 0, 1) : guide.runEnd(0, 1, 0, 0.5);
        if (guide.failed() || mid == from) {
            return null;
        }
        int n = patch.degreeU(), m = patch.degreeV(), length = net.length;
        double[] a = new double[length], b = new double[length];
        int dim = Patches.dim(patch);
        if (inU) {
            DeCasteljau.splitU(net, 0, n, m, dim, 0.5, a, 0, b, 0);
        } else {
            DeCasteljau.splitV(net, 0, n, m, dim, 0.5, a, 0, b, 0);
        }
        double bu0 = inU ? 0.5 : 0, bv0 = inU ? 0 : 0.5;
        ForkJoinTask<PatchPieces> upper = ForkJoinTask.adapt(() -> replay(patch, options, minSize, new Workspace(), b,
                bu0, 1, bv0, 1, new SplitGuide(boxes, mid, to))).fork();
        PatchPieces lower = replay(patch, options, minSize, w, a, 0, inU ? 0.5 : 1, 0, inU ? 1 : 0.5,
                new SplitGuide(boxes, from, mid));
        PatchPieces higher = upper.join();
        return lower == null || higher == null ? null : PatchPieces.concat(lower, higher);
    }

    /** Old leaves from which {@link #resplit} halves the root on two threads. */
    static final int PARALLEL_LEAVES = 256;

    /** The node {@code [u0,u1]×[v0,v1]} of {@code patch}, net {@code net}, re-split along {@code guide}; null when it fails. */
    private static PatchPieces replay(BezierPatch patch, SplitOptions options, double minSize, Workspace w,
                                      double[] net, double u0, double u1, double v0, double v1, SplitGuide guide) {
        int n = patch.degreeU(), m = patch.degreeV();
        int dim = Patches.dim(patch);
        w.out.reset((n + 1) * (m + 1), dim == 4, false);
        Recursion r = new Recursion(n, m, dim, options, minSize, w, null, patch.domain());
        int depth = u1 - u0 < 1 || v1 - v0 < 1 ? 1 : 0;
        r.visit(net, u0, u1, v0, v1, depth, TrimCurves.INSIDE, guide);
        return guide.failed() || !guide.finished() ? null : w.out.pieces(n, m);
    }

    /**
     * The working memory of {@link #split}: the nets of each level of the halving and the pieces
     * made so far, kept from one patch to the next and grown when a patch needs more. One thread's.
     */
    public static final class Workspace {
        double[][] lo = new double[0][], hi = new double[0][];
        double[] euclid = new double[0], weights = new double[0];
        final Builder out = new Builder();

        /** The two nets of level {@code depth}, at least {@code length} doubles each. */
        void ensureLevel(int depth, int length) {
            if (depth >= lo.length) {
                lo = Arrays.copyOf(lo, depth + 1);
                hi = Arrays.copyOf(hi, depth + 1);
            }
            if (lo[depth] == null || lo[depth].length < length) {
                lo[depth] = new double[length];
                hi[depth] = new double[length];
            }
        }

        /** Room for the Euclidean net and weights of a rational patch of {@code points} points. */
        void ensureRational(int points) {
            if (weights.length < points) {
                euclid = new double[3 * points];
                weights = new double[points];
            }
        }
    }

    /**
     * Past the base depth cap a piece is split on only while its flatness is within this many times
     * the base tolerance. On the 10×10-point wavy grid 1 makes 292 leaves and keeps about half of
     * the frame-time gain, 2 makes 550 and 4 (or no limit) 580 with all of it; a random degree-11
     * net makes 64 pieces at the base cap, 159 with 2, 660 with 4 (degree 9..15: at most 512 with 2).
     */
    static final double PAST_CAP_FLATNESS = 2;

    /**
     * The depth-first halving in the working memory of a {@link Workspace}: level {@code d} owns
     * two nets (the halves made from level {@code d-1}), which stay intact while the lower half's
     * subtree uses deeper levels; a level's nets are made when a halving first reaches it (a
     * patch that stays whole needs none), and kept for the next patch.
     */
    private static final class Recursion {
        final int n, m, dim, points;
        final SplitOptions options;
        /** The degree-aware depth cap and tolerance ({@link SplitOptions#maxDepthFor}, {@link SplitOptions#flatnessFor}). */
        final int maxDepth;
        final double flatness;
        final double minSize;
        /** Degree at most 3: past the base cap only the fine split's tolerance ({@link SplitOptions#fine}). */
        final boolean upToBicubic;
        final Workspace w;
        final Builder out;
        final TrimCurves trim;
        final PatchDomain domain;
        final double[] box = new double[6];
        final double[] euclid, weights, trimScratch, flatnessScratch;

        Recursion(int n, int m, int dim, SplitOptions options, double minSize, Workspace w, TrimCurves trim,
                  PatchDomain domain) {
            this.n = n;
            this.m = m;
            this.dim = dim;
            this.points = (n + 1) * (m + 1);
            this.options = options;
            this.maxDepth = options.maxDepthFor(n, m);
            this.flatness = options.flatnessFor(n, m);
            this.minSize = minSize;
            this.upToBicubic = Math.max(n, m) <= 3;
            this.w = w;
            this.out = w.out;
            this.trim = trim;
            this.domain = domain;
            if (dim == 4) {
                w.ensureRational(points);
            }
            euclid = w.euclid;
            weights = w.weights;
            trimScratch = trim == null ? null : new double[TrimCurves.SCRATCH_LENGTH];
            flatnessScratch = new double[NetMeasures.flatnessScratch(n)];
        }

        /**
         * Splits the node {@code [u0,u1]×[v0,v1]} (net {@code net}) into leaves. Without a guide
         * each node is tested ({@link #done}) and halved across its longer control polygon. With
         * the {@code guide} of an old split ({@link #resplit}) the nodes are halved as it halved
         * them, down to its leaves, where a leaf is kept when {@link #done} allows it with
         * {@link #KEPT_SLACK}, else split on afresh.
         */
        void visit(double[] net, double u0, double u1, double v0, double v1, int depth, int trimState,
                   SplitGuide guide) {
            boolean inU;
            if (guide == null) {
                if (trimState == TrimCurves.MIXED) {
                    trimState = classify(u0, u1, v0, v1);
                    if (trimState == TrimCurves.OUTSIDE) {
                        return;
                    }
                }
                double[] xyz = euclidean(net);
                if (done(xyz, depth, trimState, 1)) {
                    out.add(xyz, weights, u0, u1, v0, v1, trimState == TrimCurves.MIXED);
                    return;
                }
                inU = polygonLength(xyz, n, m, true) >= polygonLength(xyz, n, m, false);
            } else {
                if (guide.failed()) {
                    return;
                }
                if (guide.takeLeaf(u0, u1, v0, v1)) {
                    double[] xyz = euclidean(net);
                    if (done(xyz, depth, TrimCurves.INSIDE, KEPT_SLACK)) {
                        out.add(xyz, weights, u0, u1, v0, v1, false);
                    } else {
                        visit(net, u0, u1, v0, v1, depth, TrimCurves.INSIDE, null);
                    }
                    return;
                }
                if (depth >= maxDepth) {
                    guide.fail(); // deeper than this split goes: not a split of these options
                    return;
                }
                inU = guide.halvedInU(u0, u1, v0, v1);
                if (guide.failed()) {
                    return;
                }
            }
            w.ensureLevel(depth + 1, points * dim);
            double[] a = w.lo[depth + 1], b = w.hi[depth + 1];
            if (inU) {
                double um = 0.5 * (u0 + u1);
                DeCasteljau.splitU(net, 0, n, m, dim, 0.5, a, 0, b, 0);
                visit(a, u0, um, v0, v1, depth + 1, trimState, guide);
                visit(b, um, u1, v0, v1, depth + 1, trimState, guide);
            } else {
                double vm = 0.5 * (v0 + v1);
                DeCasteljau.splitV(net, 0, n, m, dim, 0.5, a, 0, b, 0);
                visit(a, u0, u1, v0, vm, depth + 1, trimState, guide);
                visit(b, u0, u1, vm, v1, depth + 1, trimState, guide);
            }
        }

        /** The piece's Euclidean net: {@code net} itself, or a rational net's points (its weights in {@link #weights}). */
        private double[] euclidean(double[] net) {
            if (dim == 4) {
                RationalDeCasteljau.toEuclidean(net, 0, points, euclid, 0, weights, 0);
                return euclid;
            }
            return net;
        }

        /**
         * True when the piece is a leaf: no splitting, the depth cap, or flat — but a piece that a
         * trim curve crosses is split on to the (base) depth cap, so that most hits fall in pieces
         * wholly inside (no trim test) and the pieces that need the test are small. Up to bicubic
         * the {@link SplitOptions#fine} split lowers the tolerance and raises the cap. Above bicubic
         * the tolerance and the cap are the degree-aware ones ({@link SplitOptions#flatnessFor},
         * {@link SplitOptions#maxDepthFor}); past the base cap {@link SplitOptions#maxDepth} only a
         * piece within {@value #PAST_CAP_FLATNESS} times the base tolerance of flat is refined on,
         * so a net far from flat (a random one) stays near the base cap's piece count instead of
         * growing to {@code 2^maxDepthFor}. Below bicubic the flatness also counts the corner twist
         * ({@link NetMeasures#twist}): a degree-1 net never deviates from its own bilinear patch, so
         * a big twisted bilinear (or biquadratic) patch was kept whole, and the solvers then had no
         * single-root leaf and no good Newton start on it (CPU per wavy-grid frame, A/B: degree 2
         * 80–89 ms against 93–96; degree 1 61–69 ms in every run, where the whole-patch leaf took
         * 60–66 or, in 3 runs of 7, 127–139; at degree 3 and above the twist split the tuned leaves
         * further and cost 11–12 % on the curved and wavy10 frames, so there it is left out).
         */
        private boolean done(double[] xyz, int depth, int trimState, double slack) {
            if (!options.enabled() || depth >= maxDepth) {
                return true;
            }
            boolean pastBaseCap = depth >= options.maxDepth();
            if (trimState == TrimCurves.MIXED) {
                return pastBaseCap;
            }
            Bounds.ofPoints(xyz, 0, points, box);
            double dx = box[3] - box[0], dy = box[4] - box[1], dz = box[5] - box[2];
            double size = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (size < minSize) {
                return true;
            }
            double f = flatness(xyz, 0, n, m, flatnessScratch);
            if (pastBaseCap && !upToBicubic) {
                return f <= slack * flatness * size || f > PAST_CAP_FLATNESS * options.flatnessTolerance() * size;
            }
            if (f > slack * flatness * size) {
                return false;
            }
            if (dim == 4) {
                double wMin = Double.POSITIVE_INFINITY, wMax = 0;
                for (int k = 0; k < points; k++) {
                    wMin = Math.min(wMin, weights[k]);
                    wMax = Math.max(wMax, weights[k]);
                }
                return wMax <= WEIGHT_SPREAD * wMin; // a solver's criterion reads polynomial nets only
            }
            return options.criterion().accepts(xyz, n, m, size, depth);
        }

        /** The piece's class against the trim loops, on its box in surface parameters (grown by the margin). */
        private int classify(double u0, double u1, double v0, double v1) {
            double gu = TRIM_MARGIN * (u1 - u0), gv = TRIM_MARGIN * (v1 - v0);
            double su = domain.u1() - domain.u0(), sv = domain.v1() - domain.v0();
            return trim.classify(domain.u0() + su * (u0 - gu), domain.u0() + su * (u1 + gu),
                    domain.v0() + sv * (v0 - gv), domain.v0() + sv * (v1 + gv), trimScratch);
        }
    }

    /**
     * The split's flatness of a 3-D net: {@link NetMeasures#flatness}, plus a quarter of the
     * corner twist ({@link NetMeasures#twist}) below bicubic — then a bound on the distance to the
     * corners' plane parallelogram (see {@link #split}'s leaf rule).
     */
    static double flatness(double[] net, int off, int n, int m) {
        return flatness(net, off, n, m, new double[NetMeasures.flatnessScratch(n)]);
    }

    /** As {@link #flatness(double[], int, int, int)}, with {@link NetMeasures#flatnessScratch} doubles of scratch. */
    static double flatness(double[] net, int off, int n, int m, double[] scratch) {
        double f = NetMeasures.flatness(net, off, n, m, scratch);
        return Math.max(n, m) <= 2 ? f + 0.25 * NetMeasures.twist(net, off, n, m) : f;
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

    /** The pieces of one patch as they are made, in arrays kept for the next patch. */
    private static final class Builder {
        int points;
        boolean rational, trimmed;
        double[] nets = new double[0], weights = new double[0], boxes = new double[0];
        boolean[] trimTest = new boolean[0];
        int count;

        /** Empty, for a patch of {@code points} control points. */
        void reset(int points, boolean rational, boolean trimmed) {
            this.points = points;
            this.rational = rational;
            this.trimmed = trimmed;
            this.count = 0;
        }

        void add(double[] net, double[] w, double u0, double u1, double v0, double v1, boolean test) {
            int len = 3 * points;
            if ((count + 1) * len > nets.length) {
                nets = Arrays.copyOf(nets, Math.max(2 * nets.length, 2 * len));
            }
            if (rational && (count + 1) * points > weights.length) {
                weights = Arrays.copyOf(weights, Math.max(2 * weights.length, 2 * points));
            }
            if ((count + 1) * 4 > boxes.length) {
                boxes = Arrays.copyOf(boxes, Math.max(2 * boxes.length, 8));
                trimTest = Arrays.copyOf(trimTest, boxes.length / 4);
            }
            System.arraycopy(net, 0, nets, count * len, len);
            if (rational) {
                System.arraycopy(w, 0, weights, count * points, points);
            }
            if (trimmed) {
                trimTest[count] = test;
            }
            boxes[4 * count] = u0;
            boxes[4 * count + 1] = u1;
            boxes[4 * count + 2] = v0;
            boxes[4 * count + 3] = v1;
            count++;
        }

        PatchPieces pieces(int n, int m) {
            return new PatchPieces(n, m, count, Arrays.copyOf(nets, count * 3 * points), Arrays.copyOf(boxes, count * 4),
                    rational ? Arrays.copyOf(weights, count * points) : null,
                    trimmed ? Arrays.copyOf(trimTest, count) : null);
        }
    }
}
