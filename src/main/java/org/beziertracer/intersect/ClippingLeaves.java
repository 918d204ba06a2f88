package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;

/**
 * Sub-patch leaves solved by Bézier clipping ({@link BezierClipper}): exact, the default. Up to
 * {@link #RECORD_LEAVES} leaves (65,536), each also gets its {@link NewtonLeafRecords} (64 bytes): the
 * enclosure that rejects most leaves a ray misses before any evaluation, and Newton's start, and its
 * {@link LeafSlabs} (72 bytes), which reject most of the rest that the ray passes beside. A
 * bigger table (a model of tens of thousands of patches, issue [6]'s memory budget of about 2 KB a
 * patch) goes without and searches every leaf its ray reaches.
 */
final class ClippingLeaves extends PatchLeaves {

    /** Most leaves that get records (4 MB of them): a single model of up to about 30,000 patches. */
    static final int RECORD_LEAVES = 1 << 16;

    /** Null above {@link #RECORD_LEAVES} leaves. */
    private final float[] records;
    /** {@link LeafQuadratics} of the leaves above bicubic; null without records or without such leaves. */
    private final float[] quadratics;
    /** {@link LeafQuarters} of the leaves above bicubic, made as rays need them; null without records or such leaves. */
    private final LeafQuarters quarters;
    /** {@link LeafSlabs} of every leaf (72 bytes each); null without records. */
    private final float[] slabs;

    ClippingLeaves(SubPatchTable table, double tolerance) {
        super(table, tolerance);
        this.records = hasRecords(table.count) ? NewtonLeafRecords.build(table) : null;
        this.quadratics = records != null ? LeafQuadratics.build(table) : null;
        this.quarters = quarters(table, records);
        this.slabs = records != null ? LeafSlabs.build(table) : null;
    }

    private ClippingLeaves(SubPatchTable table, double tolerance, float[] records, float[] quadratics,
                           float[] slabs) {
        super(table, tolerance);
        this.records = records;
        this.quadratics = quadratics;
        this.quarters = quarters(table, records);
        this.slabs = slabs;
    }

    private static LeafQuarters quarters(SubPatchTable table, float[] records) {
        return records != null ? LeafQuarters.of(table) : null;
    }

    /** True when a table of {@code leaves} leaves gets records. */
    static boolean hasRecords(long leaves) {
        return leaves <= RECORD_LEAVES;
    }

    /**
     * About the bytes these leaves keep beside the table ({@link Method#solverBytes}): up to
     * {@link #RECORD_LEAVES} leaves, each leaf's {@link NewtonLeafRecords} and {@link LeafSlabs}, and
     * its {@link LeafQuadratics} once a polynomial patch is above bicubic; nothing above. The
     * {@link LeafQuarters}, made as rays need them, are not counted.
     */
    static long estimateBytes(List<BezierPatch> patches, long leaves) {
        if (!hasRecords(leaves)) {
            return 0;
        }
        long floats = NewtonLeafRecords.STRIDE + LeafSlabs.STRIDE;
        if (patches.stream().anyMatch(p -> !p.isRational() && LeafQuadratics.worthIt(p.degreeU(), p.degreeV()))) {
            floats += LeafQuadratics.STRIDE;
        }
        return 4L * floats * leaves;
    }

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        return BezierClipper.intersect(ctx, table, records, quadratics, quarters, slabs, s, tMin, tMax, tolerance);
    }

    /**
     * The lanes of a batch that reach leaf {@code s}, in stages: each lane's cull and start
     * ({@link BezierClipper#begin}); the Newton solves of the lanes whose leaf is proven single-root,
     * all at once ({@link NewtonLanes}: their evaluations side by side in SIMD registers); then each
     * of those lanes' refinement and, where Newton failed, the rest of its search
     * ({@link BezierClipper#afterNewton}). Every lane's answer, and the work it counts, is what
     * {@link #intersect(TraceContext, int, double)} gives it alone. On a patch without a power form
     * (rational, above degree 9) each lane is solved alone.
     */
    @Override
    public void intersect(TraceContext ctx, int s, int[] lanes, int count, double[] tMax) {
        if (table.patchPowerOffset[table.parent[s]] < 0) {
            super.intersect(ctx, s, lanes, count, tMax);
        } else {
            solveLanes(ctx, s, lanes, count, tMax, null);
        }
    }

    /**
     * {@link #intersect(TraceContext, int, int[], int, double[])} for shadow rays: the answers of
     * {@link #occludes(TraceContext, int, double)} for each lane alone. A lane on the leaf it leaves,
     * or whose Newton start is the point it leaves, is solved alone (its first iterate is that
     * point's evaluation, {@link RayPatchNewton#startsAtOrigin}); on the leaf it leaves, after the
     * batch's other leaves, and only when none of them blocked it ({@link RayBatch#putOff}).
     */
    @Override
    public void occludes(TraceContext ctx, int s, int[] lanes, int count, double[] tMax, boolean[] occluded) {
        if (table.patchPowerOffset[table.parent[s]] < 0) {
            super.occludes(ctx, s, lanes, count, tMax, occluded);
        } else {
            solveLanes(ctx, s, lanes, count, tMax, occluded);
        }
    }

    /**
     * Shadow-ray lane {@code lane}'s own leaf {@code s} (the leaf its ray leaves, whose call is
     * counted and whose proof that the ray passes behind it failed), solved alone: sets
     * {@code occluded[lane]} when the ray meets it ahead of its origin.
     */
    void solveOwn(TraceContext ctx, int s, int lane, double[] tMax, boolean[] occluded) {
        ctx.batch.loadShadowRay(ctx, lane);
        if (solve(ctx, s, ctx.tMin, tMax[lane])) {
            occluded[lane] = true;
        }
    }

    /**
     * The stages over the lanes: closest hits when {@code occluded} is null (a hit lowers the lane's
     * {@code tMax} and is recorded in the batch), else any hits (a hit sets {@code occluded[lane]}).
     */
    private void solveLanes(TraceContext ctx, int s, int[] lanes, int count, double[] tMax, boolean[] occluded) {
        boolean anyHit = occluded != null;
        int k = table.parent[s];
        RayBatch batch = ctx.batch;
        NewtonLanes newton = ctx.newtonLanes;
        newton.ensure(count);
        float[] bx = table.boxes;
        double u0 = bx[4 * s], u1 = bx[4 * s + 1], v0 = bx[4 * s + 2], v1 = bx[4 * s + 3];
        int slots = 0;
        // Cull and start, lane by lane
        for (int j = 0; j < count; j++) {
            int lane = lanes[j];
            if (anyHit) {
                batch.loadShadowRay(ctx, lane);
            } else {
                batch.loadRay(ctx, lane);
            }
            ctx.solverCalls++;
            if (anyHit && provenBehind(ctx, s)) {
                continue; // a leaf of the patch the ray leaves, proven behind it
            }
            if (anyHit && s == ctx.originLeaf) {
                // the leaf the ray leaves, solved alone (from the origin's own evaluation), last:
                // when no other leaf blocked the ray (RayBatch.putOff)
                if (!batch.putOff(lane, this, s)) {
                    solveOwn(ctx, s, lane, tMax, occluded);
                }
                continue;
            }
            int stage = BezierClipper.begin(ctx, table, records, quadratics, quarters, slabs, s, ctx.tMin, tMax[lane],
                    tolerance);
            if (stage == BezierClipper.NEWTON) {
                double u = u0 + (u1 - u0) * ctx.pendingSu, v = v0 + (v1 - v0) * ctx.pendingSv;
                if (anyHit && RayPatchNewton.startsAtOrigin(ctx, table, k, u, v)) {
                    stage = BezierClipper.afterNewton(ctx, table, slabs, s, ctx.tMin, tMax[lane], tolerance,
                            BezierClipper.newtonFrom(ctx, table, s, ctx.pendingSu, ctx.pendingSv, tolerance))
                            ? BezierClipper.HIT : BezierClipper.MISS;
                } else {
                    newton.lane[slots] = lane;
                    newton.nextU[slots] = u;
                    newton.nextV[slots] = v;
                    newton.keepPending(ctx, slots++);
                    continue;
                }
            }
            if (stage == BezierClipper.HIT) {
                hit(ctx, batch, lane, k, s, tMax, occluded);
            }
        }
        if (slots == 0) {
            return;
        }
        // Newton on the single-root lanes together
        newton.solve(ctx, ctx.kernel, batch, table, k, slots, BezierClipper.NEWTON_STEPS, u0, u1, v0, v1, tolerance);
        // Each lane's refinement, or the rest of its search
        for (int j = 0; j < slots; j++) {
            int lane = newton.lane[j];
            if (anyHit) {
                batch.loadShadowRay(ctx, lane);
            } else {
                batch.loadRay(ctx, lane);
            }
            newton.toContext(ctx, j, k);
            boolean converged = newton.status[j] == RayPatchNewton.CONVERGED;
            if (converged) {
                RayPatchNewton.refine(ctx, table, k, u0, u1, v0, v1, tolerance);
            }
            if (BezierClipper.afterNewton(ctx, table, slabs, s, ctx.tMin, tMax[lane], tolerance, converged)) {
                hit(ctx, batch, lane, k, s, tMax, occluded);
            }
        }
    }

    /** A lane's root on leaf {@code s}: its closest hit so far, or its shadow ray blocked. */
    private static void hit(TraceContext ctx, RayBatch batch, int lane, int k, int s, double[] tMax, boolean[] occluded) {
        if (occluded != null) {
            occluded[lane] = true;
        } else {
            tMax[lane] = batch.record(ctx, lane, k, s);
        }
    }

    @Override
    ClippingLeaves with(SubPatchTable edited, double editedTolerance) {
        return new ClippingLeaves(edited, editedTolerance);
    }

    /** The records and models of the patches not edited are copied, not recomputed. */
    @Override
    ClippingLeaves with(SubPatchTable edited, double editedTolerance, int[] editedPatches) {
        if (records == null || !hasRecords(edited.count)) {
            return with(edited, editedTolerance);
        }
        return new ClippingLeaves(edited, editedTolerance,
                NewtonLeafRecords.edited(records, table, edited, editedPatches),
                LeafQuadratics.edited(quadratics, table, edited, editedPatches),
                LeafSlabs.edited(slabs, table, edited, editedPatches));
    }

    @Override
    long solverBytes() {
        return HeapBytes.of(records) + HeapBytes.of(quadratics) + HeapBytes.of(slabs) + (quarters == null ? 0 : quarters.bytes());
    }
}
