package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.math.Bounds;
import org.beziertracer.geometry.SubPatchTable;

/**
 * Ray–patch intersection by Bézier clipping.
 *
 * <p>Nishita, Sederberg, Kakimoto, "Ray tracing trimmed rational surface patches", SIGGRAPH 1990.
 * The sub-patch's control net is projected once into ray space ({@link TraceContext}); a root is
 * where both plane distances vanish. Each step clips in u, then in v: the distances of the
 * control points to a line through the ray, parallel to the other parametric direction, form a
 * scalar Bézier function; the convex hull of its control points meets zero only inside
 * {@code [a,b]}, and the net is restricted to that range with de Casteljau. When a step
 * removes less than 20 % in both directions, the net is split in half and the half nearer the
 * ray origin is visited first. When the remaining piece is tiny, a few Newton steps on the parent
 * patch give the root to full double precision.
 *
 * <p>Shortcut: when a clipped piece provably holds at most one root ({@link RootUniqueness}),
 * Newton on the parent patch, confined to the piece's parameter box, finds that root directly
 * and the piece is settled (its only root is known, so nothing nearer can hide in it); a failed
 * attempt falls back to clipping. Before anything else, the leaf's record
 * ({@link NewtonLeafRecords}, when the leaves keep them) rejects a ray that misses the leaf's
 * enclosure, a parallelogram grown by the leaf's largest deviation from it (K. Qin, M. Gong,
 * G. Tong, "Fast ray tracing NURBS surfaces", 1996), with no evaluation at all; then a
 * precomputed test per leaf ({@link RootUniqueness#atMostOneRoot(TraceContext, SubPatchTable, int)}:
 * four dot products) often proves the whole leaf single-root for this ray; Newton then starts
 * where the ray meets that parallelogram (without records: the parallelogram of the leaf's
 * corners; on a leaf above bicubic, where the ray meets the leaf's quadratic model,
 * {@link LeafQuadratics}) and, when it converges inside the leaf, no net is projected or clipped at all; its
 * last step is usually taken without evaluating the patch again ({@link RayPatchNewton#extrapolate}).
 * When Newton fails on such a leaf, the ray usually passes beside it: the winding of the image of
 * the leaf's border around the ray then proves it empty ({@link BoundaryWinding}). A leaf above
 * bicubic that the precomputed test cannot prove single-root is tried quarter by quarter
 * ({@link LeafQuarters}: each quarter's own record proves a miss or a single root that Newton in
 * the quarter finds). Otherwise, on a leaf's first visit both clips run on the unrestricted net, so a leaf with a
 * unique root needs no de Casteljau restriction. An any-hit query (a shadow ray) ends the search
 * at the leaf's first root, and on a leaf that may hold several roots first runs Newton from the
 * leaf's start, confined to the leaf: whatever root it converges to within the ray's interval
 * answers the query (any root does), and only when it finds none does the clipping search run.
 *
 * <p>Robustness, after Efremov, Havran and Seidel, "Robust and numerically stable Bézier
 * clipping method for ray tracing NURBS surfaces", SCCG 2005: clipped intervals are widened by a
 * small margin, the work per leaf is capped, every candidate in {@code (tMin, tMax)} is kept and
 * the nearest returned, and pieces are pruned by their ray-space bounds (the third coordinate
 * bounds t, so a piece beyond the best hit so far is dropped).
 *
 * <p>A rational leaf is clipped on its weighted distances {@code w·d} (the zero set of
 * {@code Σ w_ij·d_ij·B_i(u)·B_j(v)}, Nishita et al.), its weights carried along in the context's
 * weight arena ({@link RationalNets}); everything else is the same.
 *
 * <p>Allocation-free: all nets live in the context's arena, a stack of at most
 * {@link TraceContext#MAX_ENTRIES} entries.
 */
final class BezierClipper {
    private BezierClipper() {}

    /** A clip must shrink the parameter range below this fraction, or the piece is split. */
    static final double SPLIT_THRESHOLD = 0.8;
    /** Margin added on both sides of a clipped interval (local parameters). */
    static final double WIDEN = 1e-10;
    /** Cap on clip steps per leaf. */
    static final int MAX_STEPS = 400;
    /** Newton attempts per leaf on pieces proven to hold at most one root ({@link RootUniqueness}). */
    static final int MAX_NEWTON_TRIES = 2;
    /** Iteration cap of such an attempt; a failed attempt falls back to clipping. */
    static final int NEWTON_STEPS = 8;
    /** A piece whose ray-space extent is below this fraction of the leaf size is a root candidate. */
    static final double CONVERGED_EXTENT = 1e-7;
    /** ... or whose parameter box (local to the leaf) is this narrow in both directions. */
    static final double CONVERGED_WIDTH = 1e-12;

    /** {@link #clipWholeLeaf} found the leaf's only root: the search is over. */
    private static final int SOLVED = -1;

    /**
     * Nearest root of sub-patch {@code s} with {@code tMin < t < tMax}; on success stores it in
     * {@code ctx.rootT/rootU/rootV} (parent-patch parameters) and returns true.
     *
     * @param records the table's {@link NewtonLeafRecords}, or null: with them a ray that misses
     *                a leaf's enclosure (its parallelogram grown by R, {@link NewtonSolver#start})
     *                is rejected before anything else, and Newton starts where the ray crosses
     *                that parallelogram; without them it starts at the parallelogram of the leaf's
     *                corners
     */
    static boolean intersect(TraceContext ctx, SubPatchTable tab, float[] records, int s, double tMin, double tMax,
                             double tolerance) {
        return intersect(ctx, tab, records, null, s, tMin, tMax, tolerance);
    }

    /**
     * As {@link #intersect(TraceContext, SubPatchTable, float[], int, double, double, double)};
     * with {@code quadratics} (the leaves' {@link LeafQuadratics}, or null) Newton on a leaf proven
     * single-root starts where the ray meets the leaf's quadratic model, when that lies in the leaf.
     */
    static boolean intersect(TraceContext ctx, SubPatchTable tab, float[] records, float[] quadratics, int s,
                             double tMin, double tMax, double tolerance) {
        return intersect(ctx, tab, records, quadratics, null, null, s, tMin, tMax, tolerance);
    }

    /**
     * As {@link #intersect(TraceContext, SubPatchTable, float[], float[], int, double, double, double)};
     * with {@code quarters} (or null) a leaf its record cannot prove single-root is first tried
     * quarter by quarter ({@link LeafQuarters}) before it is clipped; with {@code slabs} (the
     * leaves' {@link LeafSlabs}, or null) a leaf whose record the ray meets is rejected when the
     * ray misses its slabs.
     */
    static boolean intersect(TraceContext ctx, SubPatchTable tab, float[] records, float[] quadratics,
                             LeafQuarters quarters, float[] slabs, int s, double tMin, double tMax, double tolerance) {
        int stage = begin(ctx, tab, records, quadratics, quarters, slabs, s, tMin, tMax, tolerance);
        if (stage != NEWTON) {
            return stage == HIT;
        }
        return afterNewton(ctx, tab, slabs, s, tMin, tMax, tolerance,
                newtonFrom(ctx, tab, s, ctx.pendingSu, ctx.pendingSv, tolerance));
    }

    /** Outcomes of {@link #begin}: the leaf is settled (a miss, or a hit in {@code ctx.root*}), or Newton is next. */
    static final int MISS = 0, HIT = 1, NEWTON = 2;

    /**
     * {@link #intersect} up to the Newton solve on a leaf proven single-root: returns {@link #MISS}
     * or {@link #HIT} when the leaf is settled before it (the root in {@code ctx.root*}), or
     * {@link #NEWTON} when {@link #newtonFrom} is next, from {@code (ctx.pendingSu, ctx.pendingSv)},
     * its outcome then handed to {@link #afterNewton}. Split there so that a batch of rays can run
     * the Newton solves of the lanes that reach the same leaf together ({@link NewtonLanes}).
     */
    static int begin(TraceContext ctx, SubPatchTable tab, float[] records, float[] quadratics,
                     LeafQuarters quarters, float[] slabs, int s, double tMin, double tMax, double tolerance) {
        int kind = NewtonSolver.MAYBE_SEVERAL;
        boolean besideFirst = false;
        // The leaf a shadow ray leaves, proven single-root by the table's own test: its one root is
        // the origin's point, behind the ray, and no record is read (nor any evaluation made)
        boolean own = s == ctx.originLeaf, originSingle = own && RootUniqueness.atMostOneRoot(ctx, tab, s);
        if (originSingle && OriginRoot.behind(ctx, tab, s, tMin, tolerance)) {
            ctx.originBehind++;
            return MISS;
        }
        if (records == null) {
            cornerStart(ctx, tab, s);
        } else if ((kind = NewtonSolver.start(ctx, records, NewtonLeafRecords.STRIDE * s, tMin, tMax, tolerance))
                == NewtonSolver.MISS) {
            ctx.recordMisses++;
            return MISS; // the leaf lies in its enclosure, which the ray misses in (tMin, tMax)
        }
        // The record's balls bound a polynomial leaf's derivatives (not a rational one's): when
        // they prove a single root, the table's own test need not run
        boolean polynomial = tab.patchDim[tab.parent[s]] == 3;
        // (on the ray's own leaf the table's test has run above)
        boolean unique = originSingle || kind == NewtonSolver.SINGLE_ROOT && polynomial
                || !own && RootUniqueness.atMostOneRoot(ctx, tab, s);
        if (unique) {
            ctx.singleRootLeaves++;
        }
        if (unique && own) {
            if (!originSingle && OriginRoot.behind(ctx, tab, s, tMin, tolerance)) {
                ctx.originBehind++;
                return MISS; // its one root is the origin's point, behind the ray: proven unevaluated
            }
            OriginLeaf.startAtOrigin(ctx, tab, s); // a shadow ray's own leaf: its one root is the origin's point
            ctx.originStarts++;
        } else if (unique && quadratics != null) {
            // A nearer start, when the model's lies in the leaf. When it lies outside, the ray
            // nearly always passes beside the leaf (wavy10: 14,400 of 14,750 such leaves a frame),
            // and the winding test, which settles a single-root leaf either way, goes before Newton
            boolean modelStart = LeafQuadratics.start(ctx, quadratics, s);
            if (modelStart) {
                ctx.quadraticStarts++;
            }
            besideFirst = !modelStart && LeafQuadratics.has(quadratics, s);
        }
        double su = ctx.clip[0], sv = ctx.clip[1]; // (the quarters' own starts overwrite ctx.clip)
        // The leaf's slabs are tried where the ray would cost more than their test: before any
        // search of a leaf that may hold several roots, and on a single-root one once Newton failed
        // or its start lies outside (a leaf a ray hits pays nothing for them)
        if (!unique && beside(ctx, slabs, own, s, tMin, tMax, tolerance)) {
            return MISS;
        }
        if (!unique && quarters != null) {
            int settled = quarters.solve(ctx, tab, s, tMin, tMax, tolerance);
            if (settled != LeafQuarters.UNDECIDED) {
                ctx.quarterLeaves++;
                return settled == LeafQuarters.ROOT ? HIT : MISS;
            }
        }
        boolean windingFirst = besideFirst && polynomial;
        if (windingFirst && (beside(ctx, slabs, own, s, tMin, tMax, tolerance) || holdsNoRoot(ctx, tab, s, tolerance))) {
            ctx.besideFirst++;
            return MISS;
        }
        if (unique) {
            ctx.pendingSu = su;
            ctx.pendingSv = sv;
            ctx.pendingOwn = own;
            ctx.pendingWindingFirst = windingFirst;
            ctx.pendingPolynomial = polynomial;
            return NEWTON;
        }
        // An any-hit query needs a root, not the nearest: one that Newton finds in the leaf (its
        // iterates confined to it) answers it, without the clipping search. Not on the leaf the
        // ray leaves from a start near the ray's origin: Newton there converges to the origin's
        // own point, behind the ray
        boolean anyByNewton = !unique && ctx.anyHit && tab.trimTest == null;
        if (anyByNewton && s == ctx.originLeaf && !OriginLeaf.awayFromOrigin(ctx, tab, s, su, sv)) {
            ctx.nearOriginStarts++;
            anyByNewton = false;
        }
        if (anyByNewton && newtonFrom(ctx, tab, s, su, sv, tolerance) && ctx.rootT > tMin && ctx.rootT < tMax) {
            ctx.anyRootsByNewton++;
            return HIT;
        }
        return clipLeaf(ctx, tab, s, false, tMin, tMax, tolerance) ? HIT : MISS;
    }

    /**
     * The rest of {@link #intersect} once the Newton solve that {@link #begin} asked for has run
     * ({@code converged}: its root in {@code ctx.root*}): the root when it lies in
     * {@code (tMin, tMax)}; when Newton failed, the slabs and the winding test prove the ray passes
     * beside the leaf, or clipping searches it.
     */
    static boolean afterNewton(TraceContext ctx, SubPatchTable tab, float[] slabs, int s, double tMin, double tMax,
                               double tolerance, boolean converged) {
        if (converged) {
            // The whole leaf holds at most one root and Newton found it: no clipping at all
            return ctx.rootT > tMin && ctx.rootT < tMax;
        }
        if (!ctx.pendingWindingFirst && (beside(ctx, slabs, ctx.pendingOwn, s, tMin, tMax, tolerance)
                || ctx.pendingPolynomial && holdsNoRoot(ctx, tab, s, tolerance))) {
            // Newton failed because there is nothing to find: the ray passes beside the leaf
            return false;
        }
        return clipLeaf(ctx, tab, s, true, tMin, tMax, tolerance);
    }


    /**
     * The ray misses leaf {@code s}'s {@link LeafSlabs} (when there are slabs; never on the leaf a
     * shadow ray leaves, whose slabs hold its origin) within {@code (tMin, tMax)}.
     */
    private static boolean beside(TraceContext ctx, float[] slabs, boolean own, int s, double tMin, double tMax,
                                  double tolerance) {
        if (slabs != null && !own && LeafSlabs.misses(ctx, slabs, s, tMin, tMax, windingMargin(ctx, tolerance))) {
            ctx.slabMisses++;
            return true;
        }
        return false;
    }

    /**
     * The winding of the border's image around the ray proves the single-root polynomial leaf
     * {@code s} holds no root ({@link BoundaryWinding}).
     */
    private static boolean holdsNoRoot(TraceContext ctx, SubPatchTable tab, int s, double tolerance) {
        if (BoundaryWinding.holdsNoRoot(ctx, tab, s, windingMargin(ctx, tolerance))) {
            ctx.windingMisses++;
            return true;
        }
        return false;
    }

    /** The winding test's margin: the tolerance and the rounding of the projection about the ray's origin. */
    static double windingMargin(TraceContext ctx, double tolerance) {
        return tolerance + 1e-13 * (Math.abs(ctx.ox) + Math.abs(ctx.oy) + Math.abs(ctx.oz));
    }

    /** {@link #intersect} without records: every leaf is searched, Newton starting at its corners' parallelogram. */
    static boolean intersect(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tMax, double tolerance) {
        return intersect(ctx, tab, null, s, tMin, tMax, tolerance);
    }

    /**
     * The clipping search over leaf {@code s}: its projected net and then its pieces on the
     * context's stack (top = next), the nearest candidate so far in {@code ctx.pieceBest*}.
     * {@code unique}: the precomputed test proved the leaf single-root for this ray.
     */
    private static boolean clipLeaf(TraceContext ctx, SubPatchTable tab, int s, boolean unique, double tMin,
                                    double tMax, double tolerance) {
        int n = tab.degreeU[s], m = tab.degreeV[s];
        int points = (n + 1) * (m + 1), len = 3 * points;
        double extentEps = CONVERGED_EXTENT * leafSize(tab, s);
        double[] boxes = ctx.entryBoxes;
        ctx.project(tab.nets, tab.netOffset[s], points, ctx.arena, 0);
        ctx.leafRational = RationalNets.rational(tab, s);
        if (ctx.leafRational) {
            RationalNets.weigh(ctx, tab, s, points);
        }
        boxes[0] = 0; boxes[1] = 1; boxes[2] = 0; boxes[3] = 1;
        ctx.pieceBestT = tMax;
        ctx.pieceFound = false;
        ctx.clipNewtonTries = 0;
        int sp = 1, steps = 0;
        // an any-hit query is answered by the first root (not with trims: a root the trim rejects
        // is searched past, TrimmedLeaves, and a nearer one left on the stack would be lost)
        boolean anyRoot = ctx.anyHit && tab.trimTest == null;
        while (sp > 0 && !(anyRoot && ctx.pieceFound)) {
            int w = sp - 1, base = w * len, b4 = 4 * w;
            if (++steps > MAX_STEPS) {
                break;
            }
            if (missesRay(ctx, base, points, tolerance, tMin)) {
                sp--;
                continue;
            }
            double[] rb = ctx.rayBounds;
            if (Math.max(rb[3] - rb[0], rb[4] - rb[1]) <= extentEps
                    || (boxes[b4 + 1] - boxes[b4] <= CONVERGED_WIDTH && boxes[b4 + 3] - boxes[b4 + 2] <= CONVERGED_WIDTH)) {
                polishCandidate(ctx, tab, s, b4, tMin, tolerance);
                sp--;
                continue;
            }
            ctx.clipIterations++;
            if (steps == 1) {
                sp = clipWholeLeaf(ctx, tab, s, unique, tolerance);
                if (sp == SOLVED) {
                    return ctx.rootT > tMin && ctx.rootT < tMax;
                }
            } else {
                sp = clipPiece(ctx, tab, s, sp, tMin, tolerance);
            }
        }
        if (ctx.pieceFound) {
            ctx.rootT = ctx.pieceBestT;
            ctx.rootU = ctx.pieceBestU;
            ctx.rootV = ctx.pieceBestV;
        }
        return ctx.pieceFound;
    }

    /**
     * Ray-space bounds of the piece at {@code ctx.arena[base..]} into {@code ctx.rayBounds}; true
     * when the ray cannot pass through it within {@code (tMin, ctx.pieceBestT)}.
     */
    private static boolean missesRay(TraceContext ctx, int base, int points, double slack, double tMin) {
        double[] rb = ctx.rayBounds;
        if (ctx.leafRational) {
            RationalNets.rayBounds(ctx, base / (3 * points), points, rb);
        } else {
            Bounds.ofPoints(ctx.arena, base, points, rb);
        }
        double invLength = ctx.invLength;
        return rb[0] > slack || rb[3] < -slack || rb[1] > slack || rb[4] < -slack
                || rb[2] * invLength >= ctx.pieceBestT || rb[5] * invLength <= tMin;
    }

    /** Keeps {@code ctx.root*} as the search's best when it is nearer than the best so far. */
    private static void offerRoot(TraceContext ctx, double tMin) {
        if (ctx.rootT > tMin && ctx.rootT < ctx.pieceBestT) {
            ctx.pieceBestT = ctx.rootT;
            ctx.pieceBestU = ctx.rootU;
            ctx.pieceBestV = ctx.rootV;
            ctx.pieceFound = true;
        }
    }

    /** A piece small enough to be a root candidate (box {@code ctx.entryBoxes[b4..]}): polish on the parent patch. */
    private static void polishCandidate(TraceContext ctx, SubPatchTable tab, int s, int b4, double tMin,
                                        double tolerance) {
        double[] boxes = ctx.entryBoxes;
        double u0 = boxes[b4], u1 = boxes[b4 + 1], v0 = boxes[b4 + 2], v1 = boxes[b4 + 3];
        double leafU0 = tab.boxes[4 * s], leafDu = tab.boxes[4 * s + 1] - leafU0;
        double leafV0 = tab.boxes[4 * s + 2], leafDv = tab.boxes[4 * s + 3] - leafV0;
        double uc = leafU0 + leafDu * 0.5 * (u0 + u1);
        double vc = leafV0 + leafDv * 0.5 * (v0 + v1);
        if (polish(ctx, tab, tab.parent[s], uc, vc, leafDu * (u1 - u0), leafDv * (v1 - v0), tolerance)) {
            offerRoot(ctx, tMin);
        }
    }

    /**
     * The leaf's first visit (stack slot 0): clips both directions on the unrestricted net (both
     * intervals hold every root of the leaf); when the leaf holds at most one root, Newton in
     * the clipped box settles it ({@link #SOLVED}), no restriction needed. Otherwise restricts
     * the net to the clipped box. Returns the new stack size (0: no root in the leaf).
     */
    private static int clipWholeLeaf(TraceContext ctx, SubPatchTable tab, int s, boolean unique, double slack) {
        int n = tab.degreeU[s], m = tab.degreeV[s];
        double[] arena = ctx.arena, boxes = ctx.entryBoxes;
        if (!clipInterval(ctx, arena, 0, n, m, true, slack)) {
            return 0;
        }
        double a = ctx.clip[0], b = ctx.clip[1];
        if (!clipInterval(ctx, arena, 0, n, m, false, slack)) {
            return 0;
        }
        double c = ctx.clip[0], d = ctx.clip[1];
        // (the precomputed test of the leaf, else the box test on its projected net)
        if (unique || RootUniqueness.atMostOneRoot(arena, 0, n, m)) {
            // At most one root in the leaf, and it lies in [a,b]×[c,d]: Newton there
            ctx.clipNewtonTries++;
            if (newtonInLeafPiece(ctx, tab, s, a, b, c, d, slack)) {
                return SOLVED;
            }
        }
        if (b - a < 1) {
            restrict(ctx, 0, 0, n, m, true, a, b);
        }
        if (d - c < 1) {
            restrict(ctx, 0, 0, n, m, false, c, d);
        }
        boxes[0] = a; boxes[1] = b; boxes[2] = c; boxes[3] = d;
        return 1;
    }

    /**
     * Restricts the piece in stack slot {@code w} (its net at {@code ctx.arena[base..]}) to
     * {@code [a,b]} in u ({@code inU}) or v, and its weights with it when the leaf is rational.
     */
    private static void restrict(TraceContext ctx, int base, int w, int n, int m, boolean inU, double a, double b) {
        if (inU) {
            DeCasteljau.restrictU(ctx.arena, base, n, m, 3, a, b);
        } else {
            DeCasteljau.restrictV(ctx.arena, base, n, m, 3, a, b);
        }
        if (ctx.leafRational) {
            if (inU) {
                RationalNets.restrictU(ctx, w, n, m, a, b);
            } else {
                RationalNets.restrictV(ctx, w, n, m, a, b);
            }
        }
    }

    /**
     * One clipping step on the piece on top of the stack (size {@code sp}): clip in u, then in
     * v; a piece proven single-root is settled by Newton; a piece that shrank by less than
     * {@link #SPLIT_THRESHOLD} in both directions is split, nearer half on top. Returns the new
     * stack size.
     */
    private static int clipPiece(TraceContext ctx, SubPatchTable tab, int s, int sp, double tMin, double slack) {
        int n = tab.degreeU[s], m = tab.degreeV[s];
        int len = 3 * (n + 1) * (m + 1), w = sp - 1, base = w * len, b4 = 4 * w;
        double keptU = clipAndRestrict(ctx, base, n, m, true, b4, slack);
        if (keptU < 0) {
            return sp - 1;
        }
        double keptV = clipAndRestrict(ctx, base, n, m, false, b4, slack);
        if (keptV < 0) {
            return sp - 1;
        }
        double[] arena = ctx.arena, boxes = ctx.entryBoxes;
        double u0 = boxes[b4], u1 = boxes[b4 + 1], v0 = boxes[b4 + 2], v1 = boxes[b4 + 3];
        boolean stalled = keptU > SPLIT_THRESHOLD && keptV > SPLIT_THRESHOLD;
        if (!stalled && ctx.clipNewtonTries < MAX_NEWTON_TRIES && RootUniqueness.atMostOneRoot(arena, base, n, m)) {
            // At most one root in this piece: Newton on the parent, confined to the piece, finds it
            ctx.clipNewtonTries++;
            if (newtonInLeafPiece(ctx, tab, s, u0, u1, v0, v1, slack)) {
                offerRoot(ctx, tMin);
                return sp - 1; // the piece's only root is known, whatever its t
            }
        }
        if (!stalled) {
            return sp;
        }
        if (sp == TraceContext.MAX_ENTRIES) {
            return sp - 1; // stack full: drop this piece (bounded work)
        }
        boolean inU = u1 - u0 >= v1 - v0;
        boolean swapped = split(ctx, arena, base, len, n, m, boxes, b4, inU);
        if (ctx.leafRational) {
            RationalNets.split(ctx, w, n, m, inU, swapped);
        }
        return sp + 1;
    }

    /**
     * Clips the piece at {@code ctx.arena[base..]} in u ({@code alongU}) or v, restricts its net to
     * the kept interval and maps its parameter box {@code ctx.entryBoxes[b4..]} to match; returns
     * the kept fraction of the interval, or -1 when the hull misses zero (no root in the piece).
     */
    private static double clipAndRestrict(TraceContext ctx, int base, int n, int m, boolean alongU, int b4,
                                          double slack) {
        double[] arena = ctx.arena, boxes = ctx.entryBoxes;
        if (!clipInterval(ctx, arena, base, n, m, alongU, slack)) {
            return -1;
        }
        double a = ctx.clip[0], b = ctx.clip[1];
        double kept = b - a;
        if (kept < 1) {
            restrict(ctx, base, base / (3 * (n + 1) * (m + 1)), n, m, alongU, a, b);
            int lo = alongU ? b4 : b4 + 2;
            double w0 = boxes[lo], width = boxes[lo + 1] - w0;
            boxes[lo + 1] = w0 + width * b;
            boxes[lo] = w0 + width * a;
        }
        return kept;
    }

    /**
     * {@link #newtonInPiece} on the piece {@code [a,b]×[c,d]} of leaf {@code s}, in the leaf's own
     * parameters (mapped to the parent patch's).
     */
    private static boolean newtonInLeafPiece(TraceContext ctx, SubPatchTable tab, int s, double a, double b, double c,
                                             double d, double tolerance) {
        double leafU0 = tab.boxes[4 * s], leafDu = tab.boxes[4 * s + 1] - leafU0;
        double leafV0 = tab.boxes[4 * s + 2], leafDv = tab.boxes[4 * s + 3] - leafV0;
        return newtonInPiece(ctx, tab, tab.parent[s], leafU0 + leafDu * a, leafU0 + leafDu * b,
                leafV0 + leafDv * c, leafV0 + leafDv * d, tolerance);
    }

    /**
     * Newton on parent patch {@code k} from the centre of the piece's parameter box
     * {@code [u0,u1]×[v0,v1]}, every iterate confined to that box; true when it converged (the
     * root is then in {@code ctx.root*} and lies in the piece), refined by one more step so it is
     * as exact as the polish of a fully clipped piece.
     */
    static boolean newtonInPiece(TraceContext ctx, SubPatchTable tab, int k, double u0, double u1,
                                 double v0, double v1, double tolerance) {
        if (RayPatchNewton.solve(ctx, tab, k, 0.5 * (u0 + u1), 0.5 * (v0 + v1), NEWTON_STEPS,
                u0, u1, v0, v1, tolerance) != RayPatchNewton.CONVERGED) {
            return false;
        }
        RayPatchNewton.refine(ctx, tab, k, u0, u1, v0, v1, tolerance);
        return true;
    }

    /**
     * Newton on leaf {@code s}'s parent patch from the leaf's point {@code (su, sv)} (leaf
     * parameters), iterates confined to the leaf's parameter box, then {@link RayPatchNewton#refine};
     * true when it converged (the root in {@code ctx.root*}).
     */
    static boolean newtonFrom(TraceContext ctx, SubPatchTable tab, int s, double su, double sv, double tolerance) {
        float[] bx = tab.boxes;
        return newtonIn(ctx, tab, tab.parent[s], bx[4 * s], bx[4 * s + 1], bx[4 * s + 2], bx[4 * s + 3], su, sv, tolerance);
    }

    /**
     * Newton on patch {@code k} from the point {@code (su, sv)} of the parameter box
     * {@code [u0,u1]×[v0,v1]} (in the box's own parameters), iterates confined to the box, then
     * {@link RayPatchNewton#refine}; true when it converged (the root in {@code ctx.root*}).
     */
    static boolean newtonIn(TraceContext ctx, SubPatchTable tab, int k, double u0, double u1, double v0, double v1,
                            double su, double sv, double tolerance) {
        if (RayPatchNewton.solve(ctx, tab, k, u0 + (u1 - u0) * su, v0 + (v1 - v0) * sv, NEWTON_STEPS,
                u0, u1, v0, v1, tolerance) != RayPatchNewton.CONVERGED) {
            return false;
        }
        RayPatchNewton.refine(ctx, tab, k, u0, u1, v0, v1, tolerance);
        return true;
    }

    /**
     * The start of a leaf without records, in leaf parameters into {@code ctx.clip[0..1]}: where the
     * ray crosses the parallelogram of the leaf's four corners (clamped to the leaf), or its centre
     * when the ray sees that parallelogram edge-on.
     */
    static void cornerStart(TraceContext ctx, SubPatchTable tab, int s) {
        int n = tab.degreeU[s], m = tab.degreeV[s];
        double[] c = ctx.corners;
        ctx.projectCorners(tab.nets, tab.netOffset[s], n, m, c);
        double ex = 0.5 * ((c[2] - c[0]) + (c[6] - c[4])), ey = 0.5 * ((c[3] - c[1]) + (c[7] - c[5]));
        double fx = 0.5 * ((c[4] - c[0]) + (c[6] - c[2])), fy = 0.5 * ((c[5] - c[1]) + (c[7] - c[3]));
        double cx = 0.25 * (c[0] + c[2] + c[4] + c[6]), cy = 0.25 * (c[1] + c[3] + c[5] + c[7]);
        double det = ex * fy - ey * fx;
        double u = 0.5, v = 0.5;
        if (Math.abs(det) > 0) {
            u = Math.min(1, Math.max(0, u + (fx * cy - fy * cx) / det));
            v = Math.min(1, Math.max(0, v + (ey * cx - ex * cy) / det));
        }
        ctx.clip[0] = u;
        ctx.clip[1] = v;
    }

    /** Diagonal of the leaf's control box. */
    static double leafSize(SubPatchTable tab, int s) {
        return tab.diagonal[s];
    }

    /**
     * Newton polish from a clipping candidate; accepts the root when it converges near the
     * candidate's box, else falls back to the candidate itself.
     */
    static boolean polish(TraceContext ctx, SubPatchTable tab, int k, double u, double v,
                          double boxDu, double boxDv, double tolerance) {
        double mu = 1e-6 + 4 * boxDu, mv = 1e-6 + 4 * boxDv;
        int r = RayPatchNewton.solve(ctx, tab, k, u, v, 6, Math.max(-1e-9, u - mu), Math.min(1 + 1e-9, u + mu),
                Math.max(-1e-9, v - mv), Math.min(1 + 1e-9, v + mv), tolerance);
        if (r != RayPatchNewton.CONVERGED) {
            // Degenerate spot (collapsed edge) or a near-tangent ray: the clipped piece is already
            // within the convergence extent of the ray, so its centre is the root.
            RayPatchNewton.solve(ctx, tab, k, u, v, 0, 0, 1, 0, 1, Double.POSITIVE_INFINITY);
        }
        ctx.rootU = Math.min(1, Math.max(0, ctx.rootU));
        ctx.rootV = Math.min(1, Math.max(0, ctx.rootV));
        return true;
    }

    /**
     * Convex-hull clip of the piece at {@code base} in u ({@code alongU}) or v: writes the
     * parameter range {@code [a,b] ⊂ [0,1]} that can hold a root into {@code ctx.clip} and
     * returns false when it is empty. A column whose distances come within {@code eps} of zero
     * counts as touching zero, so a root exactly on the border of the piece survives rounding.
     */
    static boolean clipInterval(TraceContext ctx, double[] net, int base, int n, int m, boolean alongU, double eps) {
        double[] line = ctx.clip;
        clipLine(net, base, n, m, alongU, line);
        double[] lo = ctx.columnMin, hi = ctx.columnMax;
        columnDistances(net, base, n, m, alongU, line[0], line[1], lo, hi);
        // Where the convex hull of the points (c/deg, distance) meets zero
        if (!HullClip.zeroInterval(lo, hi, alongU ? n : m, eps, ctx.clip)) {
            return false;
        }
        double a = ctx.clip[0], b = ctx.clip[1];
        ctx.clip[0] = Math.max(0, a - WIDEN);
        ctx.clip[1] = Math.min(1, b + WIDEN);
        return true;
    }

    /**
     * Unit direction {@code (lx, ly)} into {@code out[0..1]} of the line through the ray (the
     * ray-space origin) along which distances are measured: parallel to the net's mean
     * v-direction (first two ray-space coordinates) when clipping in u, to its mean u-direction
     * when clipping in v, so distances vary along the clipped direction; the perpendicular of
     * the clipped direction when the other one vanishes.
     */
    static void clipLine(double[] net, int base, int n, int m, boolean alongU, double[] out) {
        int row = 3 * (n + 1);
        int p00 = base, pn0 = base + 3 * n, p0m = base + row * m, pnm = p0m + 3 * n;
        double ux = (net[pn0] - net[p00]) + (net[pnm] - net[p0m]);
        double uy = (net[pn0 + 1] - net[p00 + 1]) + (net[pnm + 1] - net[p0m + 1]);
        double vx = (net[p0m] - net[p00]) + (net[pnm] - net[pn0]);
        double vy = (net[p0m + 1] - net[p00 + 1]) + (net[pnm + 1] - net[pn0 + 1]);
        double lx, ly;
        double uu = ux * ux + uy * uy, vv = vx * vx + vy * vy;
        if (alongU) {
            if (vv > 1e-20 * uu) { // (uu ≥ 0, so this implies vv > 0)
                lx = vx; ly = vy;
            } else if (uu > 0) {
                lx = -uy; ly = ux;
            } else {
                lx = 0; ly = 1;
            }
        } else {
            if (uu > 1e-20 * vv) {
                lx = ux; ly = uy;
            } else if (vv > 0) {
                lx = -vy; ly = vx;
            } else {
                lx = 1; ly = 0;
            }
        }
        double invL = 1 / Math.sqrt(lx * lx + ly * ly);
        out[0] = lx * invL;
        out[1] = ly * invL;
    }

    /**
     * Signed distances of the net's points from the line {@code (lx, ly)} through the origin,
     * their range per column of the clipped direction (index {@code i} along u when
     * {@code alongU}, else {@code j} along v) into {@code lo[0..deg]}, {@code hi[0..deg]}.
     */
    private static void columnDistances(double[] net, int base, int n, int m, boolean alongU, double lx, double ly,
                                        double[] lo, double[] hi) {
        if (alongU) {
            for (int c = 0; c <= n; c++) {
                lo[c] = Double.POSITIVE_INFINITY;
                hi[c] = Double.NEGATIVE_INFINITY;
            }
            for (int j = 0, p = base; j <= m; j++) {
                for (int i = 0; i <= n; i++, p += 3) {
                    double dist = lx * net[p + 1] - ly * net[p];
                    if (dist < lo[i]) lo[i] = dist;
                    if (dist > hi[i]) hi[i] = dist;
                }
            }
        } else {
            for (int j = 0, p = base; j <= m; j++) {
                double rowLo = Double.POSITIVE_INFINITY, rowHi = Double.NEGATIVE_INFINITY;
                for (int i = 0; i <= n; i++, p += 3) {
                    double dist = lx * net[p + 1] - ly * net[p];
                    if (dist < rowLo) rowLo = dist;
                    if (dist > rowHi) rowHi = dist;
                }
                lo[j] = rowLo;
                hi[j] = rowHi;
            }
        }
    }

    /**
     * Splits the piece in slot {@code base} in half; the half nearer the ray origin goes to the
     * next slot (visited first), the other stays. Returns true when the upper half stayed (the
     * halves were swapped).
     */
    static boolean split(TraceContext ctx, double[] arena, int base, int len, int n, int m,
                         double[] boxes, int b4, boolean inU) {
        double[] tmp = ctx.tmpNet;
        System.arraycopy(arena, base, tmp, 0, len);
        int next = base + len;
        double u0 = boxes[b4], u1 = boxes[b4 + 1], v0 = boxes[b4 + 2], v1 = boxes[b4 + 3];
        if (inU) {
            DeCasteljau.splitU(tmp, 0, n, m, 3, 0.5, arena, base, arena, next);
        } else {
            DeCasteljau.splitV(tmp, 0, n, m, 3, 0.5, arena, base, arena, next);
        }
        double loMin = minThird(arena, base, len), hiMin = minThird(arena, next, len);
        boolean swap = loMin < hiMin; // the lower half is nearer: it must be in the next slot
        if (swap) {
            System.arraycopy(arena, base, tmp, 0, len);
            System.arraycopy(arena, next, arena, base, len);
            System.arraycopy(tmp, 0, arena, next, len);
        }
        double um = 0.5 * (u0 + u1), vm = 0.5 * (v0 + v1);
        int n4 = b4 + 4;
        // lower half box, upper half box
        double lu0 = u0, lu1 = inU ? um : u1, lv0 = v0, lv1 = inU ? v1 : vm;
        double hu0 = inU ? um : u0, hu1 = u1, hv0 = inU ? v0 : vm, hv1 = v1;
        if (swap) {
            boxes[b4] = hu0; boxes[b4 + 1] = hu1; boxes[b4 + 2] = hv0; boxes[b4 + 3] = hv1;
            boxes[n4] = lu0; boxes[n4 + 1] = lu1; boxes[n4 + 2] = lv0; boxes[n4 + 3] = lv1;
        } else {
            boxes[b4] = lu0; boxes[b4 + 1] = lu1; boxes[b4 + 2] = lv0; boxes[b4 + 3] = lv1;
            boxes[n4] = hu0; boxes[n4 + 1] = hu1; boxes[n4 + 2] = hv0; boxes[n4 + 3] = hv1;
        }
        return swap;
    }

    private static double minThird(double[] net, int base, int len) {
        double min = Double.POSITIVE_INFINITY;
        for (int p = base + 2, end = base + len; p < end; p += 3) {
            if (net[p] < min) min = net[p];
        }
        return min;
    }
}
