package org.beziertracer.geometry;

import java.util.List;
import java.util.stream.IntStream;

import org.beziertracer.math.Bounds;
import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;

/**
 * Every sub-patch (leaf) of every patch of a scene, in flat arrays indexed by sub-patch number
 * {@code s = 0..count-1}, the leaves of patch {@code k} being {@code firstOf[k] ..
 * firstOf[k+1]-1}. Immutable; shared by render threads.
 *
 * <p><b>Per leaf</b> (about 106 bytes, and its net unless it is the whole patch):
 * <ul>
 *   <li>{@code parent[s]}: index of the patch in the scene;</li>
 *   <li>{@code degreeU[s]}, {@code degreeV[s]}: degrees (those of the parent);</li>
 *   <li>{@code netOffset[s]}: where its control net starts in {@link #nets} (layout of
 *       {@code BezierPatch}: u fastest, 3 doubles a point); a leaf that is its whole patch
 *       shares the patch's net ({@code netOffset[s] == patchNetOffset[k]});</li>
 *   <li>{@code boxes[4s..4s+3]}: {@code u0, u1, v0, v1}, its parameter box in the parent, as
 *       floats (halvings of [0,1]: exact);</li>
 *   <li>{@code diagonal[s]}: the diagonal of its control-point box;</li>
 *   <li>{@code uniqueness[9s..]}: the ray-independent single-root data of
 *       {@link HodographBounds}.</li>
 * </ul>
 * The leaves' control-point boxes (which contain them, by the convex-hull property) are not
 * kept: {@link #bounds(int, int)} makes them for a BVH build or refit.
 *
 * <p><b>Per patch</b>: {@code firstOf}, degrees, {@code patchSquaredExtent} and its whole net in
 * {@link #nets} at {@code patchNetOffset[k]}, followed by its leaves' nets when it is split.
 * {@link #patchNets} is the same array as {@link #nets}.
 *
 * <p><b>Scene-relative split</b>: besides {@link SplitOptions}, a piece whose control-box diagonal
 * is below {@link #minSize()} is not split ({@link PatchSplitter}); the size is chosen so the
 * scene gets about {@link #LEAF_BUDGET} leaves' worth of surface, which leaves small scenes as the
 * options say and keeps a model of 100,000 patches at one or two leaves a patch.
 *
 * <p>An edit of one patch re-splits only that patch ({@link #withPatch}); the other patches'
 * leaves are copied as they are.
 */
public final class SubPatchTable {

    /** Scenes with at least this many patches are split in parallel. */
    static final int PARALLEL_PATCHES = 64;
    /**
     * Leaves' worth of surface a scene gets: pieces smaller than {@code τ}, with
     * {@code τ² = Σ (patch control-box diagonal)² / LEAF_BUDGET}, are not split.
     */
    public static final int LEAF_BUDGET = 1 << 17;
    /** Retained bytes per leaf besides its net: parent, degrees, net offset, box, diagonal, uniqueness. */
    static final int LEAF_BYTES = 4 + 2 + 4 + 4 * 4 + 8 + HodographBounds.STRIDE * 8;
    /** Retained bytes per patch besides its net: offsets, degrees, first leaf, squared extent. */
    static final int PATCH_BYTES = 4 + 4 + 4 + 4 + 8;

    private final List<BezierPatch> patches;
    private final SplitOptions options;
    private final double minSize;
    public final int count;
    public final int[] parent;
    public final byte[] degreeU;
    public final byte[] degreeV;
    public final int[] netOffset;
    /** Every control net: per patch its whole net, then its leaves' nets when it is split. */
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

    /** Empty arrays for {@code patchCount} patches and {@code leaves} leaves, nets of {@code netDoubles}. */
    private SubPatchTable(List<BezierPatch> patches, SplitOptions options, double minSize, int leaves,
                          int netDoubles) {
        this.patches = List.copyOf(patches);
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
        patchDegreeU = new int[patchCount];
        patchDegreeV = new int[patchCount];
        patchSquaredExtent = new double[patchCount];
    }

    /** Splits every patch. */
    public static SubPatchTable build(List<BezierPatch> patches, SplitOptions options) {
        double minSize = minSize(patches, options);
        // The pieces of split patches only: a patch that stays whole is copied from itself, so a
        // model of a million small patches holds no second copy of its nets while it is built
        PatchPieces[] pieces = new PatchPieces[patches.size()];
        boolean parallel = pieces.length >= PARALLEL_PATCHES;
        IntStream range = IntStream.range(0, pieces.length);
        (parallel ? range.parallel() : range).forEach(k -> {
            PatchPieces p = PatchSplitter.split(patches.get(k), options, minSize);
            pieces[k] = p.count() > 1 ? p : null;
        });
        int leaves = 0;
        long doubles = 0;
        for (int k = 0; k < pieces.length; k++) {
            leaves += leafCount(pieces[k]);
            doubles += regionLength(patches.get(k), pieces[k]);
        }
        SubPatchTable t = new SubPatchTable(patches, options, minSize, leaves, checkedLength(doubles));
        int s = 0, off = 0;
        for (int k = 0; k < pieces.length; k++) {
            t.firstOf[k] = s;
            t.patchNetOffset[k] = off;
            s += leafCount(pieces[k]);
            off += (int) regionLength(patches.get(k), pieces[k]);
        }
        t.firstOf[pieces.length] = s;
        IntStream fill = IntStream.range(0, pieces.length);
        (parallel ? fill.parallel() : fill).forEach(k -> t.fill(k, pieces[k]));
        return t;
    }

    /** Leaves of a patch: its pieces, or 1 for a patch that stays whole ({@code null}). */
    private static int leafCount(PatchPieces p) {
        return p == null ? 1 : p.count();
    }

    /**
     * Doubles patch {@code patch} takes in {@link #nets}: its whole net, and its leaves' nets when
     * it is split into {@code pieces} (null or one piece: whole).
     */
    private static long regionLength(BezierPatch patch, PatchPieces pieces) {
        long net = 3L * patch.pointCount();
        return pieces == null || pieces.count() == 1 ? net : net * (1 + pieces.count());
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

    /** Writes patch {@code k}'s region (its offsets already set) from its pieces (null: whole). */
    private void fill(int k, PatchPieces p) {
        BezierPatch patch = patches.get(k);
        int n = patch.degreeU(), m = patch.degreeV(), points = patch.pointCount(), len = 3 * points;
        int off = patchNetOffset[k], s0 = firstOf[k], leaves = leafCount(p);
        patch.copyNetInto(nets, off);
        patchDegreeU[k] = n;
        patchDegreeV[k] = m;
        patchSquaredExtent[k] = PatchNormals.squaredExtent(nets, off, n, m);
        if (leaves > 1) {
            System.arraycopy(p.nets(), 0, nets, off + len, leaves * len);
        }
        double[] pieceBoxes = leaves > 1 ? p.boxes() : WHOLE;
        double[] box = new double[6];
        for (int i = 0; i < leaves; i++) {
            int s = s0 + i, o = leaves == 1 ? off : off + (i + 1) * len;
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
            HodographBounds.compute(nets, o, n, m, uniqueness, HodographBounds.STRIDE * s, box);
        }
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
        for (BezierPatch p : patches) {
            double d = p.controlBounds().diagonal();
            sum += d * d;
        }
        return Math.sqrt(sum / LEAF_BUDGET);
    }

    /** A new table with patch {@code index} replaced and re-split; the other patches' leaves are copied. */
    public SubPatchTable withPatch(int index, BezierPatch patch) {
        PatchPieces p = PatchSplitter.split(patch, options, minSize);
        int oldFirst = firstOf[index], oldCount = firstOf[index + 1] - oldFirst;
        int oldOff = patchNetOffset[index];
        int oldLen = index + 1 < patchNetOffset.length ? patchNetOffset[index + 1] - oldOff : nets.length - oldOff;
        int dLeaves = p.count() - oldCount;
        int dNets = checkedLength(regionLength(patch, p)) - oldLen;
        var list = new java.util.ArrayList<>(patches);
        list.set(index, patch);
        SubPatchTable t = new SubPatchTable(list, options, minSize, count + dLeaves,
                checkedLength((long) nets.length + dNets));
        // Leaves and nets before the edited patch, then after it (shifted)
        copyLeaves(t, 0, 0, oldFirst, 0);
        int after = oldFirst + oldCount;
        copyLeaves(t, after, after + dLeaves, count - after, dNets);
        System.arraycopy(nets, 0, t.nets, 0, oldOff);
        System.arraycopy(nets, oldOff + oldLen, t.nets, oldOff + oldLen + dNets, nets.length - oldOff - oldLen);
        int patchCount = patchNetOffset.length;
        for (int k = 0; k < patchCount; k++) {
            boolean later = k > index;
            t.firstOf[k] = firstOf[k] + (later ? dLeaves : 0);
            t.patchNetOffset[k] = patchNetOffset[k] + (later ? dNets : 0);
            t.patchDegreeU[k] = patchDegreeU[k];
            t.patchDegreeV[k] = patchDegreeV[k];
            t.patchSquaredExtent[k] = patchSquaredExtent[k];
        }
        t.firstOf[patchCount] = t.count;
        t.fill(index, p);
        return t;
    }

    /** Copies {@code n} leaves from {@code from} to {@code t}'s {@code to}, their nets moved by {@code dNets}. */
    private void copyLeaves(SubPatchTable t, int from, int to, int n, int dNets) {
        System.arraycopy(parent, from, t.parent, to, n);
        System.arraycopy(degreeU, from, t.degreeU, to, n);
        System.arraycopy(degreeV, from, t.degreeV, to, n);
        System.arraycopy(boxes, 4 * from, t.boxes, 4 * to, 4 * n);
        System.arraycopy(diagonal, from, t.diagonal, to, n);
        int q = HodographBounds.STRIDE;
        System.arraycopy(uniqueness, q * from, t.uniqueness, q * to, q * n);
        for (int i = 0; i < n; i++) {
            t.netOffset[to + i] = netOffset[from + i] + dNets;
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
    public static Estimate estimate(List<BezierPatch> patches, SplitOptions options) {
        int n = patches.size();
        if (n == 0) {
            return new Estimate(0, 0);
        }
        double minSize = minSize(patches, options);
        int samples = Math.min(n, ESTIMATE_SAMPLE);
        long leaves = 0, regions = 0, pieceDoubles = 0;
        for (int k = 0; k < samples; k++) {
            PatchPieces p = PatchSplitter.split(patches.get((int) ((long) k * n / samples)), options, minSize);
            leaves += p.count();
            regions += regionLength(patches.get((int) ((long) k * n / samples)), p);
            pieceDoubles += p.count() > 1 ? p.nets().length + p.boxes().length : 0;
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
                + HeapBytes.of(patchNetOffset) + HeapBytes.of(patchDegreeU) + HeapBytes.of(patchDegreeV)
                + HeapBytes.of(uniqueness) + HeapBytes.of(patchSquaredExtent);
    }

    /** Number of sub-patches of patch {@code index}. */
    public int countOf(int index) { return firstOf[index + 1] - firstOf[index]; }

    public int patchCount() { return patchNetOffset.length; }

    public List<BezierPatch> patches() { return patches; }

    public SplitOptions options() { return options; }

    /** The scene-relative stop in force: pieces with a smaller control-box diagonal are not split. */
    public double minSize() { return minSize; }
}
