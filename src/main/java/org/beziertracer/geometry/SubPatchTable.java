package org.beziertracer.geometry;

import java.util.Arrays;
import java.util.List;
import java.util.stream.IntStream;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Bounds;
import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Instance;
import org.beziertracer.model.Placement;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.TrimRegion;

/**
 * Every sub-patch (leaf) of every patch of a scene, in flat arrays indexed by sub-patch number
 * {@code s = 0..count-1}, the leaves of patch {@code k} being {@code firstOf[k] ..
 * firstOf[k+1]-1}. Immutable; shared by render threads.
 *
 * <p><b>Per leaf</b> (about 106 bytes, and its net unless it is the whole patch):
 * <ul>
 *   <li>{@code parent[s]}: index of the patch in the scene;</li>
 *   <li>{@code degreeU[s]}, {@code degreeV[s]}: degrees (those of the parent);</li>
 *   <li>{@code netOffset[s]}: where its Euclidean control net starts in {@link #nets} (layout of
 *       {@code BezierPatch}: u fastest, 3 doubles a point); a leaf that is its whole polynomial,
 *       untrimmed patch shares the patch's net ({@code netOffset[s] == patchNetOffset[k]});</li>
 *   <li>{@code boxes[4s..4s+3]}: {@code u0, u1, v0, v1}, its parameter box in the parent, as
 *       floats (halvings of [0,1]: exact);</li>
 *   <li>{@code diagonal[s]}: the diagonal of its control-point box;</li>
 *   <li>{@code uniqueness[9s..]}: the ray-independent single-root data of
 *       {@link HodographBounds}.</li>
 * </ul>
 * The leaves' control-point boxes (which contain them by the convex-hull property, for a rational
 * patch too: its Euclidean points, the weights being positive) are not kept:
 * {@link #bounds(int, int)} makes them for a BVH build or refit.
 *
 * <p><b>Per patch</b>: {@code firstOf}, degrees, {@code patchSquaredExtent}, {@link #patchDim},
 * {@link #patchDomain}, {@link #patchTrim} and its whole net in {@link #nets} at
 * {@code patchNetOffset[k]} (padded to a multiple of 3 doubles), followed by its leaves' nets
 * when they are not the patch itself. {@link #patchNets} is the same array as {@link #nets}.
 * A polynomial patch of degree up to {@link PowerForm#MAX_DEGREE}, in a scene of at most
 * {@link #POWER_PATCHES} patches, also has its {@link PowerForm} there, after its net
 * ({@link #patchPowerOffset}): the Newton iterations and the hit's evaluation use it.
 *
 * <p><b>Rational patches</b> keep Euclidean leaf nets and their weights in {@link #weights} (null
 * when no patch is rational); the whole patch's net is then homogeneous ({@link #patchDim} 4, see
 * {@link RationalDeCasteljau}). <b>Trimmed patches</b> have their {@link TrimCurves} and
 * parameter domain; their leaves wholly outside the trim region are not in the table at all, and
 * {@link #trimTest} says which of the others need their hits tested.
 *
 * <p><b>Scene-relative split</b>: besides {@link SplitOptions}, a piece whose control-box diagonal
 * is below {@link #minSize()} is not split ({@link PatchSplitter}); the size is chosen so the
 * scene gets about {@link #LEAF_BUDGET} leaves' worth of surface, which leaves small scenes as the
 * options say and keeps a model of 100,000 patches at one or two leaves a patch.
 *
 * <p>An edit re-splits only the edited patches ({@link #withPatches}); the other patches' leaves
 * are copied as they are.
 */
public final class SubPatchTable {

    /** Scenes with at least this many patches are split in parallel. */
    static final int PARALLEL_PATCHES = 64;
    /** Patches split one after another in one working memory ({@link PatchSplitter.Workspace}). */
    static final int SPLIT_RUN = 32;
    /**
     * Leaves' worth of surface a scene gets: pieces smaller than {@code τ}, with
     * {@code τ² = Σ (patch control-box diagonal)² / LEAF_BUDGET}, are not split.
     */
    public static final int LEAF_BUDGET = 1 << 17;
    /** Retained bytes per leaf besides its net: parent, degrees, net offset, box, diagonal, uniqueness. */
    static final int LEAF_BYTES = 4 + 2 + 4 + 4 * 4 + 8 + HodographBounds.STRIDE * 8;
    /** Retained bytes per patch besides its net: offsets, degrees, first leaf, squared extent, dim, curvature, domain. */
    static final int PATCH_BYTES = 4 + 4 + 4 + 4 + 8 + 4 + 4 + 4 * 8 + 4;
    /**
     * Most patches whose tables keep their {@link PowerForm}s (a bicubic one is 384 bytes more): a
     * single model of up to about 30,000 patches, as {@code ClippingLeaves} keeps its leaf records.
     */
    public static final int POWER_PATCHES = 1 << 15;

    private final List<BezierPatch> patches;
    private final SplitOptions options;
    private final double minSize;
    public final int count;
    /**
     * Work of the build: the patches that went through {@link PatchSplitter} (a model used several
     * times counts once; an edit counts the patches it re-split).
     */
    public final int splitPatches;
    public final int[] parent;
    public final byte[] degreeU;
    public final byte[] degreeV;
    public final int[] netOffset;
    /** Every control net: per patch its whole net, then its leaves' nets when they are not the patch itself. */
    public final double[] nets;
    public final float[] boxes;
    /** Diagonal of each leaf's control-point box. */
    public final double[] diagonal;
    /** First sub-patch of each patch; {@code firstOf[patchCount] == count}. */
    public final int[] firstOf;
    /** The whole patches' control nets (for the final Newton polish and evaluation): {@link #nets}. */
    public final double[] patchNets;
    /** Where patch {@code k}'s net starts in {@link #patchNets}. */
    public final int[] patchNetOffset;
    /** Where patch {@code k}'s {@link PowerForm} starts in {@link #patchNets}; −1 when it has none. */
    public final int[] patchPowerOffset;
    /** Degrees of patch {@code k}. */
    public final int[] patchDegreeU;
    public final int[] patchDegreeV;
    /**
     * Per sub-patch, {@link HodographBounds#STRIDE} doubles: the ray-independent single-root data
     * of {@link HodographBounds} (cross product of the mean derivative directions and its bound).
     */
    public final double[] uniqueness;
    /** {@link PatchNormals#squaredExtent} of patch {@code k}'s net (for the normal at a hit). */
    public final double[] patchSquaredExtent;
    /**
     * Per patch a bound on its second derivatives ({@link NetMeasures#secondDerivativeBound}, as
     * a float rounded up), with which a Newton step near a root is taken without evaluating the
     * patch again; {@code +∞} for a rational patch (no such bound is kept for it).
     */
    public final float[] patchCurvature;
    /** 3: patch {@code k}'s net in {@link #patchNets} is Euclidean; 4: homogeneous (a rational patch). */
    public final int[] patchDim;
    /**
     * Null when no patch is rational; else one weight per control point of {@link #nets}, the
     * weight of point {@code i} of sub-patch {@code s} at {@code weights[netOffset[s]/3 + i]} (1
     * for polynomial patches).
     */
    public final double[] weights;
    /** Null when no patch is trimmed; else per sub-patch whether its hits need the trim test. */
    public final boolean[] trimTest;
    /** Per patch its trim curves, or null when untrimmed. */
    public final TrimCurves[] patchTrim;
    /** Per patch {@code u0, u1, v0, v1}: its part of its surface's parameter domain ({@code 0,1,0,1} when plain). */
    public final double[] patchDomain;

    /** Empty arrays for {@code patchCount} patches and {@code leaves} leaves, nets of {@code netDoubles}. */
    private SubPatchTable(List<BezierPatch> patches, SplitOptions options, double minSize, int leaves,
                          int netDoubles, boolean rational, TrimCurves[] trims, int splitPatches) {
        this.patches = List.copyOf(patches);
        this.splitPatches = splitPatches;
        this.options = options;
        this.minSize = minSize;
        int patchCount = patches.size();
        count = leaves;
        parent = new int[leaves];
        degreeU = new byte[leaves];
        degreeV = new byte[leaves];
        netOffset = new int[leaves];
        boxes = new float[4 * leaves];
        diagonal = new double[leaves];
        uniqueness = new double[HodographBounds.STRIDE * leaves];
        nets = new double[netDoubles];
        patchNets = nets;
        firstOf = new int[patchCount + 1];
        patchNetOffset = new int[patchCount];
        patchPowerOffset = new int[patchCount];
        patchDegreeU = new int[patchCount];
        patchDegreeV = new int[patchCount];
        patchSquaredExtent = new double[patchCount];
        patchDim = new int[patchCount];
        patchCurvature = new float[patchCount];
        patchDomain = new double[4 * patchCount];
        patchTrim = trims;
        weights = rational ? new double[netDoubles / 3] : null;
        trimTest = anyTrim(trims) ? new boolean[leaves] : null;
    }

    private static boolean anyTrim(TrimCurves[] trims) {
        for (TrimCurves t : trims) {
            if (t != null) {
                return true;
            }
        }
        return false;
    }

    /**
     * Splits every patch (the trim curves of each distinct trim region are built once), as
     * {@code requested} says for a scene of this many patches ({@link SplitOptions#forPatches}).
     */
    public static SubPatchTable build(List<BezierPatch> patches, SplitOptions requested) {
        return build(patches, requested, List.of());
    }

    /**
     * As {@link #build(List, SplitOptions)}, splitting each distinct model of {@code instances}
     * once: the pieces of a patch placed by a {@linkplain Placement#similarity() similarity} are
     * its model patch's pieces, their nets mapped by the placement (de Casteljau's points are
     * affine combinations of the net, so this is the same split of the placed patch, up to
     * rounding; the leaves' boxes are made from the mapped nets, so they still hold the surface).
     * Other placements (a scale that differs between axes) split their patches themselves, as
     * the scene's own: their flatness and the Newton leaves' refinement are not kept by the map.
     */
    public static SubPatchTable build(List<BezierPatch> patches, SplitOptions requested, List<Instance> instances) {
        SplitOptions options = requested.forPatches(patches.size());
        double minSize = minSize(patches, options);
        TrimCurves[] trims = TrimCurves.forPatches(patches);
        // The pieces that are not the patch itself only: a patch that stays whole is copied from
        // itself, so a model of a million small patches holds no second copy of its nets while built
        PatchPieces[] pieces = new PatchPieces[patches.size()];
        Instance[] placedBy = new Instance[patches.size()];
        for (Instance in : instances) {
            if (in.placement().similarity()) {
                Arrays.fill(placedBy, in.first(), in.first() + in.count(), in);
            }
        }
        boolean parallel = pieces.length >= PARALLEL_PATCHES;
        // In runs of patches, each with one working memory of the splitter
        IntStream runs = IntStream.range(0, (pieces.length + SPLIT_RUN - 1) / SPLIT_RUN);
        java.util.concurrent.atomic.AtomicInteger split = new java.util.concurrent.atomic.AtomicInteger();
        (parallel ? runs.parallel() : runs).forEach(r -> {
            PatchSplitter.Workspace w = new PatchSplitter.Workspace();
            for (int k = r * SPLIT_RUN, end = Math.min(pieces.length, k + SPLIT_RUN); k < end; k++) {
                if (placedBy[k] == null) {
                    pieces[k] = kept(PatchSplitter.split(patches.get(k), options, trims[k], minSize, w));
                    split.incrementAndGet();
                }
            }
        });
        // Each distinct model once (its patches carry the trim regions of their placed copies),
        // then every placed patch from its model patch's pieces
        var models = new java.util.IdentityHashMap<List<BezierPatch>, PatchPieces[]>();
        for (Instance in : instances) {
            if (in.placement().similarity() && !models.containsKey(in.model())) {
                PatchPieces[] own = new PatchPieces[in.count()];
                IntStream js = IntStream.range(0, own.length);
                (own.length >= PARALLEL_PATCHES ? js.parallel() : js).forEach(j -> own[j] = kept(PatchSplitter.split(
                        in.model().get(j), options, trims[in.first() + j], minSize, new PatchSplitter.Workspace())));
                split.addAndGet(own.length);
                models.put(in.model(), own);
            }
        }
        IntStream placed = IntStream.range(0, pieces.length).filter(k -> placedBy[k] != null);
        (parallel ? placed.parallel() : placed).forEach(k -> {
            Instance in = placedBy[k];
            pieces[k] = mapped(models.get(in.model())[k - in.first()], in.placement());
        });
        return assemble(patches, options, minSize, trims, pieces, parallel, split.get());
    }

    /** {@code p}'s pieces with their nets mapped by {@code placement} (null: a whole leaf stays whole). */
    private static PatchPieces mapped(PatchPieces p, Placement placement) {
        if (p == null) {
            return null;
        }
        double[] nets = p.nets().clone();
        placement.mapPoints(nets, 0, nets.length / 3);
        return new PatchPieces(p.degreeU(), p.degreeV(), p.count(), nets, p.boxes(), p.weights(), p.trimTest());
    }

    /** The table of {@code patches} split into {@code pieces} (null: a whole leaf sharing the patch's net). */
    private static SubPatchTable assemble(List<BezierPatch> patches, SplitOptions options, double minSize,
                                          TrimCurves[] trims, PatchPieces[] pieces, boolean parallel,
                                          int splitPatches) {
        int leaves = 0;
        long doubles = 0;
        boolean rational = false;
        for (int k = 0; k < pieces.length; k++) {
            leaves += leafCount(pieces[k]);
            doubles += regionLength(patches.get(k), pieces[k], pieces.length);
            rational |= patches.get(k).isRational();
        }
        SubPatchTable t = new SubPatchTable(patches, options, minSize, leaves, checkedLength(doubles), rational, trims,
                splitPatches);
        int s = 0, off = 0;
        for (int k = 0; k < pieces.length; k++) {
            t.firstOf[k] = s;
            t.patchNetOffset[k] = off;
            s += leafCount(pieces[k]);
            off += (int) regionLength(patches.get(k), pieces[k], pieces.length);
        }
        t.firstOf[pieces.length] = s;
        IntStream fill = IntStream.range(0, pieces.length);
        (parallel ? fill.parallel() : fill).forEach(k -> t.fill(k, pieces[k], false));
        return t;
    }

    /** The pieces to keep: null when the patch is one whole polynomial, untrimmed leaf (it shares its net). */
    private static PatchPieces kept(PatchPieces p) {
        return p.count() == 1 && p.weights() == null && p.trimTest() == null ? null : p;
    }

    /** Leaves of a patch: its pieces, or 1 for a patch that stays whole ({@code null}). */
    private static int leafCount(PatchPieces p) {
        return p == null ? 1 : p.count();
    }

    /** Doubles of a patch's own net in {@link #nets}: homogeneous for a rational patch, padded to a multiple of 3. */
    private static long patchLength(BezierPatch patch) {
        long d = (long) Patches.dim(patch) * patch.pointCount();
        return (d + 2) / 3 * 3;
    }

    /** True when {@code patch}, in a scene of {@code patchCount} patches, keeps its {@link PowerForm}. */
    static boolean hasPower(BezierPatch patch, int patchCount) {
        return patchCount <= POWER_PATCHES && !patch.isRational() && PowerForm.has(patch.degreeU(), patch.degreeV());
    }

    /** Doubles of a patch's own net and its power form (when it has one) in {@link #nets}. */
    private static long ownLength(BezierPatch patch, int patchCount) {
        return patchLength(patch) + (hasPower(patch, patchCount) ? 3L * patch.pointCount() : 0);
    }

    /**
     * Doubles patch {@code patch} takes in {@link #nets}: its whole net, its power form, and its
     * leaves' nets when they are not the patch itself ({@code pieces} non-null).
     */
    private static long regionLength(BezierPatch patch, PatchPieces pieces, int patchCount) {
        return ownLength(patch, patchCount) + (pieces == null ? 0 : 3L * patch.pointCount() * pieces.count());
    }

    private static int checkedLength(long doubles) {
        if (doubles > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("the sub-patch nets need " + doubles
                    + " numbers, more than one array can hold");
        }
        return (int) doubles;
    }

    /** The parameter box of a whole patch. */
    private static final double[] WHOLE = {0, 1, 0, 1};

    /**
     * Writes patch {@code k}'s region (its offsets already set) from its pieces (null: whole); with
     * {@code parallelLeaves} (an edit, which fills one patch or a few) its leaves in chunks on the
     * common pool (a build fills patches in parallel instead, when it has many).
     */
    private void fill(int k, PatchPieces p, boolean parallelLeaves) {
        BezierPatch patch = patches.get(k);
        int n = patch.degreeU(), m = patch.degreeV(), points = patch.pointCount(), len = 3 * points;
        int off = patchNetOffset[k], leaves = leafCount(p), dim = Patches.dim(patch);
        if (dim == 3) {
            patch.copyNetInto(nets, off);
        } else {
            double[] h = Patches.workingNet(patch);
            System.arraycopy(h, 0, nets, off, h.length);
        }
        patchDegreeU[k] = n;
        patchDegreeV[k] = m;
        patchDim[k] = dim;
        patchSquaredExtent[k] = PatchNormals.squaredExtent(nets, off, n, m, dim);
        patchCurvature[k] = dim == 3 ? Math.nextUp((float) NetMeasures.secondDerivativeBound(nets, off, n, m))
                : Float.POSITIVE_INFINITY;
        PatchDomain d = patch.domain();
        patchDomain[4 * k] = d.u0();
        patchDomain[4 * k + 1] = d.u1();
        patchDomain[4 * k + 2] = d.v0();
        patchDomain[4 * k + 3] = d.v1();
        int power = off + (int) patchLength(patch);
        if (hasPower(patch, patches.size()) && PowerForm.fromBezier(nets, off, n, m, nets, power)) {
            patchPowerOffset[k] = power;
        } else {
            // (a net so large that its power form overflows keeps de Casteljau; its room stays unused)
            patchPowerOffset[k] = -1;
        }
        int leafBase = off + (int) ownLength(patch, patches.size());
        if (p != null) {
            System.arraycopy(p.nets(), 0, nets, leafBase, leaves * len);
        }
        if (!parallelLeaves || leaves <= LEAF_CHUNK) {
            fillLeaves(k, p, 0, leaves);
        } else {
            java.util.stream.IntStream.range(0, (leaves + LEAF_CHUNK - 1) / LEAF_CHUNK).parallel()
                    .forEach(c -> fillLeaves(k, p, c * LEAF_CHUNK, Math.min(leaves, (c + 1) * LEAF_CHUNK)));
        }
    }

    /** Leaves of one patch that a task of {@link #fill} handles (a degree-9 patch has hundreds). */
    private static final int LEAF_CHUNK = 128;

    /** The leaves {@code from .. to-1} of patch {@code k} (its region written) from its pieces (null: whole). */
    private void fillLeaves(int k, PatchPieces p, int from, int to) {
        int n = patchDegreeU[k], m = patchDegreeV[k], points = (n + 1) * (m + 1), len = 3 * points;
        int off = patchNetOffset[k], s0 = firstOf[k];
        int leafBase = off + (int) ownLength(patches.get(k), patches.size());
        double[] pieceBoxes = p == null ? WHOLE : p.boxes();
        double[] box = new double[6];
        for (int i = from; i < to; i++) {
            int s = s0 + i, o = p == null ? off : leafBase + i * len;
            parent[s] = k;
            degreeU[s] = (byte) n;
            degreeV[s] = (byte) m;
            netOffset[s] = o;
            for (int c = 0; c < 4; c++) {
                boxes[4 * s + c] = (float) pieceBoxes[4 * i + c];
            }
            Bounds.ofPoints(nets, o, points, box);
            double dx = box[3] - box[0], dy = box[4] - box[1], dz = box[5] - box[2];
            diagonal[s] = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (p != null && p.weights() != null) {
                // the derivative bounds of a rational piece come from its homogeneous net
                System.arraycopy(p.weights(), i * points, weights, o / 3, points);
                HodographBounds.computeRational(nets, o, weights, o / 3, n, m, uniqueness, HodographBounds.STRIDE * s);
            } else {
                HodographBounds.compute(nets, o, n, m, uniqueness, HodographBounds.STRIDE * s, box);
                if (weights != null) {
                    Arrays.fill(weights, o / 3, o / 3 + points, 1);
                }
            }
            if (trimTest != null) {
                trimTest[s] = p != null && p.trimTest() != null && p.trimTest()[i];
            }
        }
    }

    /** {@code u0, u1, v0, v1} of each patch's {@link PatchDomain}, one after another. */
    public static double[] domains(List<BezierPatch> patches) {
        double[] out = new double[4 * patches.size()];
        for (int k = 0; k < patches.size(); k++) {
            PatchDomain d = patches.get(k).domain();
            out[4 * k] = d.u0();
            out[4 * k + 1] = d.u1();
            out[4 * k + 2] = d.v0();
            out[4 * k + 3] = d.v1();
        }
        return out;
    }

    /**
     * The scene-relative stop: {@code τ = sqrt(Σ d_k² / LEAF_BUDGET)} over the patches' control-box
     * diagonals {@code d_k}; 0 when splitting is off. For a scene of N similar patches of diagonal
     * d this is {@code d·sqrt(N / LEAF_BUDGET)}: below any leaf's size for small N.
     */
    static double minSize(List<BezierPatch> patches, SplitOptions options) {
        if (!options.enabled() || options.maxDepth() == 0) {
            return 0;
        }
        double sum = 0;
        double[] box = new double[6];
        for (BezierPatch p : patches) {
            p.controlBoundsInto(box); // the diagonal of controlBounds(), no box made a patch
            double d = Aabb.diagonal(box[3] - box[0], box[4] - box[1], box[5] - box[2]);
            sum += d * d;
        }
        return Math.sqrt(sum / LEAF_BUDGET);
    }

    /** A new table with patch {@code index} replaced and re-split; the other patches' leaves are copied. */
    public SubPatchTable withPatch(int index, BezierPatch patch) {
        return withPatches(new int[] {index}, List.of(patch));
    }

    /**
     * A new table with patches {@code indices[k]} replaced by {@code replacements.get(k)} and
     * re-split, the other patches' leaves copied: one pass over the table however many patches
     * changed (an edit that moves a point shared by several patches).
     */
    public SubPatchTable withPatches(int[] indices, List<BezierPatch> replacements) {
        return withPatches(indices, replacements, false);
    }

    /**
     * As {@link #withPatches(int[], List)}; with {@code keepSplit}, an edited patch of unchanged
     * degree, untrimmed before and after, is re-split along its old halvings
     * ({@link PatchSplitter#resplit}): its leaves stay where they are still near flat, so a drag
     * usually keeps the leaf count (and the BVH is refitted). Such a table may have more leaves than
     * a fresh split of the same patches (a leaf the edit made flatter is not merged back). A patch
     * that changes degree, becomes rational or polynomial, or is trimmed is split afresh; an edit
     * that changes the table's storage splits every patch afresh ({@link #keepsUntouchedLeaves}).
     */
    public SubPatchTable withPatches(int[] indices, List<BezierPatch> replacements, boolean keepSplit) {
        var list = new java.util.ArrayList<>(patches);
        TrimCurves[] trims = patchTrim.clone();
        boolean rational = weights != null;
        for (int k = 0; k < indices.length; k++) {
            int index = indices[k];
            BezierPatch patch = replacements.get(k);
            TrimRegion region = patch.trim();
            if (region == null) {
                trims[index] = null;
            } else if (region != patches.get(index).trim() || trims[index] == null) {
                trims[index] = TrimCurves.of(region);
            }
            list.set(index, patch);
            rational |= patch.isRational();
        }
        if (rational != (weights != null) || anyTrim(trims) != (trimTest != null)) {
            return rebuilt(list, trims);
        }
        int[] edited = Arrays.stream(indices).distinct().sorted().toArray();
        PatchPieces[] pieces = new PatchPieces[edited.length];
        int[] dLeaves = new int[edited.length];
        long[] dNets = new long[edited.length];
        long leaves = count, doubles = nets.length;
        PatchSplitter.Workspace w = new PatchSplitter.Workspace();
        for (int e = 0; e < edited.length; e++) {
            int k = edited[e];
            BezierPatch was = patches.get(k), now = list.get(k);
            PatchPieces p = keepSplit && was.trim() == null && was.degreeU() == now.degreeU()
                    && was.degreeV() == now.degreeV() && was.isRational() == now.isRational()
                    ? PatchSplitter.resplit(now, options, minSize, w, boxes, firstOf[k], firstOf[k + 1]) : null;
            pieces[e] = kept(p != null ? p : PatchSplitter.split(now, options, trims[k], minSize, w));
            dLeaves[e] = leafCount(pieces[e]) - (firstOf[k + 1] - firstOf[k]);
            dNets[e] = regionLength(list.get(k), pieces[e], list.size()) - (regionEnd(k) - patchNetOffset[k]);
            leaves += dLeaves[e];
            doubles += dNets[e];
        }
        SubPatchTable t = new SubPatchTable(list, options, minSize, (int) leaves, checkedLength(doubles), rational, trims,
                edited.length);
        copyAround(t, edited, dLeaves, dNets);
        for (int e = 0; e < edited.length; e++) {
            t.fill(edited[e], pieces[e], true);
        }
        return t;
    }

    /**
     * True when {@code edited}, made from this table by {@link #withPatches}, holds this table's
     * leaves (shifted) for every patch the edit did not touch; false when the edit split every
     * patch afresh because it made the first rational or trimmed patch or removed the last one
     * (the table's storage changes then), so that a patch re-split along kept halvings earlier may
     * now have other leaves.
     */
    public boolean keepsUntouchedLeaves(SubPatchTable edited) {
        return (edited.weights != null) == (weights != null) && (edited.trimTest != null) == (trimTest != null);
    }

    /** A table built afresh from {@code list} with this table's stop (an edit that made the first rational or trimmed patch). */
    private SubPatchTable rebuilt(List<BezierPatch> list, TrimCurves[] trims) {
        PatchPieces[] pieces = new PatchPieces[list.size()];
        PatchSplitter.Workspace w = new PatchSplitter.Workspace();
        for (int k = 0; k < pieces.length; k++) {
            pieces[k] = kept(PatchSplitter.split(list.get(k), options, trims[k], minSize, w));
        }
        return assemble(list, options, minSize, trims, pieces, false, pieces.length);
    }

    /** End of patch {@code k}'s region in {@link #nets}. */
    private int regionEnd(int k) {
        return k + 1 < patchNetOffset.length ? patchNetOffset[k + 1] : nets.length;
    }

    /**
     * Copies into {@code t} every patch's offsets and data and every leaf of the patches that were
     * not edited, shifted past the edited patches' new sizes ({@code edited} sorted).
     */
    private void copyAround(SubPatchTable t, int[] edited, int[] dLeaves, long[] dNets) {
        int fromLeaf = 0, fromNet = 0, shiftL = 0, shiftN = 0;
        for (int e = 0; e < edited.length; e++) {
            int k = edited[e];
            copyRange(t, fromLeaf, firstOf[k] - fromLeaf, fromNet, patchNetOffset[k] - fromNet, shiftL, shiftN);
            fromLeaf = firstOf[k + 1];
            fromNet = regionEnd(k);
            shiftL += dLeaves[e];
            shiftN += (int) dNets[e];
        }
        copyRange(t, fromLeaf, count - fromLeaf, fromNet, nets.length - fromNet, shiftL, shiftN);
        int patchCount = patchNetOffset.length;
        shiftL = 0;
        shiftN = 0;
        for (int k = 0, e = 0; k < patchCount; k++) {
            t.firstOf[k] = firstOf[k] + shiftL;
            t.patchNetOffset[k] = patchNetOffset[k] + shiftN;
            t.patchPowerOffset[k] = patchPowerOffset[k] < 0 ? -1 : patchPowerOffset[k] + shiftN;
            t.patchDegreeU[k] = patchDegreeU[k];
            t.patchDegreeV[k] = patchDegreeV[k];
            t.patchSquaredExtent[k] = patchSquaredExtent[k];
            t.patchDim[k] = patchDim[k];
            t.patchCurvature[k] = patchCurvature[k];
            System.arraycopy(patchDomain, 4 * k, t.patchDomain, 4 * k, 4);
            if (e < edited.length && edited[e] == k) {
                shiftL += dLeaves[e];
                shiftN += (int) dNets[e];
                e++;
            }
        }
        t.firstOf[patchCount] = t.count;
    }

    /** Copies {@code n} leaves from {@code from} and {@code len} net doubles from {@code net} into {@code t}, shifted. */
    private void copyRange(SubPatchTable t, int from, int n, int net, int len, int shiftL, int shiftN) {
        int to = from + shiftL;
        System.arraycopy(parent, from, t.parent, to, n);
        System.arraycopy(degreeU, from, t.degreeU, to, n);
        System.arraycopy(degreeV, from, t.degreeV, to, n);
        System.arraycopy(boxes, 4 * from, t.boxes, 4 * to, 4 * n);
        System.arraycopy(diagonal, from, t.diagonal, to, n);
        int q = HodographBounds.STRIDE;
        System.arraycopy(uniqueness, q * from, t.uniqueness, q * to, q * n);
        if (trimTest != null) {
            System.arraycopy(trimTest, from, t.trimTest, to, n);
        }
        for (int i = 0; i < n; i++) {
            t.netOffset[to + i] = netOffset[from + i] + shiftN;
        }
        System.arraycopy(nets, net, t.nets, net + shiftN, len);
        if (weights != null) {
            System.arraycopy(weights, net / 3, t.weights, (net + shiftN) / 3, len / 3);
        }
    }

    /**
     * The control-point boxes of leaves {@code first .. first+n-1}, six doubles each
     * ({@code minX, minY, minZ, maxX, maxY, maxZ}), in a new array: for a BVH build or refit.
     */
    public double[] bounds(int first, int n) {
        double[] out = new double[6 * n];
        IntStream range = IntStream.range(0, n);
        (n >= 1 << 14 ? range.parallel() : range).forEach(i -> {
            int s = first + i;
            Bounds.ofPoints(nets, netOffset[s], (degreeU[s] + 1) * (degreeV[s] + 1), out, 6 * i);
        });
        return out;
    }

    /** Patches split for real by {@link #estimate}; more are sampled evenly. */
    static final int ESTIMATE_SAMPLE = 64;

    /**
     * About how many leaves {@link #build} makes and the most heap it holds at once.
     *
     * @param leaves exact for up to {@value #ESTIMATE_SAMPLE} patches, else the mean of that many
     *               evenly spaced patches, split for real, times the patch count
     * @param bytes  the table's arrays ({@link #bytes()}) plus the pieces the split patches are
     *               split into first (nets and boxes, dropped once copied)
     */
    public record Estimate(long leaves, long bytes) {}

    /** {@link Estimate} of {@link #build}{@code (patches, options)}; splits at most {@value #ESTIMATE_SAMPLE} patches. */
    public static Estimate estimate(List<BezierPatch> patches, SplitOptions requested) {
        int n = patches.size();
        SplitOptions options = requested.forPatches(n);
        if (n == 0) {
            return new Estimate(0, 0);
        }
        double minSize = minSize(patches, options);
        int samples = Math.min(n, ESTIMATE_SAMPLE);
        long leaves = 0, regions = 0, pieceDoubles = 0;
        for (int k = 0; k < samples; k++) {
            BezierPatch patch = patches.get((int) ((long) k * n / samples));
            PatchPieces p = kept(PatchSplitter.split(patch, options, minSize));
            leaves += leafCount(p);
            regions += regionLength(patch, p, n);
            pieceDoubles += p != null ? p.nets().length + p.boxes().length : 0;
        }
        double scale = (double) n / samples;
        long leafCount = (long) Math.ceil(leaves * scale);
        long bytes = (long) Math.ceil((regions + pieceDoubles) * 8 * scale)
                + leafCount * LEAF_BYTES + (long) n * (PATCH_BYTES + 64);
        return new Estimate(leafCount, bytes);
    }

    /** Heap held by this table's arrays, in bytes (not the patches themselves). */
    public long bytes() {
        return HeapBytes.of(parent) + HeapBytes.of(degreeU) + HeapBytes.of(degreeV) + HeapBytes.of(netOffset)
                + HeapBytes.of(nets) + HeapBytes.of(boxes) + HeapBytes.of(diagonal) + HeapBytes.of(firstOf)
                + HeapBytes.of(patchNetOffset) + HeapBytes.of(patchPowerOffset) + HeapBytes.of(patchDegreeU)
                + HeapBytes.of(patchDegreeV)
                + HeapBytes.of(uniqueness) + HeapBytes.of(patchSquaredExtent) + HeapBytes.of(patchDim)
                + HeapBytes.of(patchCurvature)
                + HeapBytes.of(patchDomain) + HeapBytes.of(weights) + HeapBytes.of(trimTest);
    }

    /**
     * {@code S}, {@code ∂S/∂u}, {@code ∂S/∂v} of patch {@code k} at {@code (u, v)} into
     * {@code out[0..9)}: from its {@link PowerForm} when it has one, else by
     * {@link RationalDeCasteljau#pointAndDerivatives} ({@code scratch} as that asks).
     */
    public void evaluatePatch(int k, double u, double v, double[] out, double[] scratch) {
        int power = patchPowerOffset[k];
        if (power >= 0) {
            PowerForm.evaluateWithDerivatives(nets, power, patchDegreeU[k], patchDegreeV[k], u, v, out, 0);
        } else {
            RationalDeCasteljau.pointAndDerivatives(nets, patchNetOffset[k], patchDegreeU[k], patchDegreeV[k],
                    patchDim[k], u, v, out, scratch);
        }
    }

    /** Number of sub-patches of patch {@code index}. */
    public int countOf(int index) { return firstOf[index + 1] - firstOf[index]; }

    public int patchCount() { return patchNetOffset.length; }

    public List<BezierPatch> patches() { return patches; }

    public SplitOptions options() { return options; }

    /** The scene-relative stop in force: pieces with a smaller control-box diagonal are not split. */
    public double minSize() { return minSize; }
}
