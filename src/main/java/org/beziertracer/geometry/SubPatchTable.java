package org.beziertracer.geometry;

import java.util.List;
import java.util.stream.IntStream;

import org.beziertracer.math.Bounds;
import org.beziertracer.model.BezierPatch;

/**
 * Every sub-patch of every patch of a scene, in flat arrays indexed by sub-patch number
 * {@code s = 0..count-1}. Immutable; shared by render threads.
 *
 * <ul>
 *   <li>{@code parent[s]}: index of the patch in the scene;</li>
 *   <li>{@code degreeU[s]}, {@code degreeV[s]}: degrees (those of the parent);</li>
 *   <li>{@code netOffset[s]}: where its control net starts in {@code nets} (layout of
 *       {@code BezierPatch}: u fastest, 3 doubles a point);</li>
 *   <li>{@code boxes[4s..4s+3]}: {@code u0, u1, v0, v1}, its parameter box in the parent;</li>
 *   <li>{@code bounds[6s..6s+5]}: the axis-aligned box of its control points, which contains
 *       the sub-patch by the convex-hull property.</li>
 * </ul>
 *
 * <p>An edit of one patch re-splits only that patch ({@link #withPatch}); the other patches'
 * pieces are reused.
 */
public final class SubPatchTable {

    /** Scenes with at least this many patches are split in parallel. */
    static final int PARALLEL_PATCHES = 64;

    private final List<BezierPatch> patches;
    private final PatchPieces[] pieces;
    private final SplitOptions options;
    public final int count;
    public final int[] parent;
    public final int[] degreeU;
    public final int[] degreeV;
    public final int[] netOffset;
    public final double[] nets;
    public final double[] boxes;
    public final double[] bounds;
    /** First sub-patch of each patch; {@code firstOf[patchCount] == count}. */
    public final int[] firstOf;
    /** The whole patches' control nets, one after another (for the final Newton polish and evaluation). */
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

    private SubPatchTable(List<BezierPatch> patches, PatchPieces[] pieces, SplitOptions options) {
        this.patches = List.copyOf(patches);
        this.pieces = pieces;
        this.options = options;
        patchNetOffset = new int[pieces.length];
        patchDegreeU = new int[pieces.length];
        patchDegreeV = new int[pieces.length];
        int patchDoubles = 0;
        for (int k = 0; k < pieces.length; k++) {
            patchNetOffset[k] = patchDoubles;
            patchDegreeU[k] = pieces[k].degreeU();
            patchDegreeV[k] = pieces[k].degreeV();
            patchDoubles += pieces[k].netLength();
        }
        patchNets = new double[patchDoubles];
        patchSquaredExtent = new double[pieces.length];
        for (int k = 0; k < pieces.length; k++) {
            this.patches.get(k).copyNetInto(patchNets, patchNetOffset[k]);
            patchSquaredExtent[k] = PatchNormals.squaredExtent(patchNets, patchNetOffset[k],
                    patchDegreeU[k], patchDegreeV[k]);
        }
        int total = 0;
        int doubles = 0;
        for (PatchPieces p : pieces) {
            total += p.count();
            doubles += p.nets().length;
        }
        count = total;
        parent = new int[total];
        degreeU = new int[total];
        degreeV = new int[total];
        netOffset = new int[total];
        nets = new double[doubles];
        boxes = new double[4 * total];
        bounds = new double[6 * total];
        uniqueness = new double[HodographBounds.STRIDE * total];
        firstOf = new int[pieces.length + 1];
        double[] box = new double[6];
        int s = 0, off = 0;
        for (int k = 0; k < pieces.length; k++) {
            PatchPieces p = pieces[k];
            firstOf[k] = s;
            System.arraycopy(p.nets(), 0, nets, off, p.nets().length);
            System.arraycopy(p.boxes(), 0, boxes, 4 * s, 4 * p.count());
            int len = p.netLength();
            for (int i = 0; i < p.count(); i++, s++, off += len) {
                parent[s] = k;
                degreeU[s] = p.degreeU();
                degreeV[s] = p.degreeV();
                netOffset[s] = off;
                Bounds.ofPoints(nets, off, len / 3, box);
                System.arraycopy(box, 0, bounds, 6 * s, 6);
                HodographBounds.compute(nets, off, p.degreeU(), p.degreeV(), uniqueness,
                        HodographBounds.STRIDE * s, box);
            }
        }
        firstOf[pieces.length] = s;
    }

    /** Splits every patch. */
    public static SubPatchTable build(List<BezierPatch> patches, SplitOptions options) {
        PatchPieces[] pieces = new PatchPieces[patches.size()];
        // Patches split independently; large scenes use the common fork-join pool (build time only)
        IntStream range = IntStream.range(0, pieces.length);
        (pieces.length >= PARALLEL_PATCHES ? range.parallel() : range)
                .forEach(k -> pieces[k] = PatchSplitter.split(patches.get(k), options));
        return new SubPatchTable(patches, pieces, options);
    }

    /** Patches split for real by {@link #estimateCount}; more are sampled evenly. */
    static final int ESTIMATE_SAMPLE = 64;

    /**
     * About how many sub-patches {@link #build} would make: exact for up to
     * {@value #ESTIMATE_SAMPLE} patches, else the mean of that many evenly spaced patches, split
     * for real, times the patch count. Cheap (allocates only the sample's pieces).
     */
    public static long estimateCount(List<BezierPatch> patches, SplitOptions options) {
        int n = patches.size();
        if (n == 0) {
            return 0;
        }
        if (!options.enabled() || options.maxDepth() == 0) {
            return n;
        }
        int samples = Math.min(n, ESTIMATE_SAMPLE);
        long pieces = 0;
        for (int k = 0; k < samples; k++) {
            pieces += PatchSplitter.split(patches.get((int) ((long) k * n / samples)), options).count();
        }
        return (long) Math.ceil((double) pieces * n / samples);
    }

    /**
     * About the most heap {@link #build} holds at once for {@code subPatchCount} sub-patches (from
     * {@link #estimateCount}), in bytes: every array of the table (which keeps the patches'
     * {@link PatchPieces} too, so each sub-patch net is held twice) plus the patches' own nets.
     * Keep this in step with the fields above when the layout changes.
     */
    public static long estimateBytes(List<BezierPatch> patches, long subPatchCount) {
        if (patches.isEmpty()) {
            return 0;
        }
        long netDoubles = 0;
        for (BezierPatch p : patches) {
            netDoubles += 3L * p.pointCount();
        }
        double meanNet = (double) netDoubles / patches.size();
        long perSubPatch = (long) Math.ceil(2 * 8 * meanNet)      // nets, in the table and in the pieces
                + 2 * 4 * 8                                         // boxes, in the table and in the pieces
                + 6 * 8 + HodographBounds.STRIDE * 8               // bounds, uniqueness
                + 4 * 4;                                            // parent, degreeU, degreeV, netOffset
        long perPatch = 8 * 3 * 4 + 8 + 4 + 96;                    // patch arrays, extent, firstOf, pieces objects
        return subPatchCount * perSubPatch + 8 * netDoubles + patches.size() * perPatch;
    }

    /** A new table with patch {@code index} replaced and re-split; the others are reused. */
    public SubPatchTable withPatch(int index, BezierPatch patch) {
        PatchPieces[] copy = pieces.clone();
        copy[index] = PatchSplitter.split(patch, options);
        var list = new java.util.ArrayList<>(patches);
        list.set(index, patch);
        return new SubPatchTable(list, copy, options);
    }

    /** Number of sub-patches of patch {@code index}. */
    public int countOf(int index) { return pieces[index].count(); }

    public int patchCount() { return pieces.length; }

    public List<BezierPatch> patches() { return patches; }

    public SplitOptions options() { return options; }
}
