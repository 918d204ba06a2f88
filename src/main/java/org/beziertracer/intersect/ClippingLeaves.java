package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.HeapBytes;

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

    @Override
    boolean solve(TraceContext ctx, int s, double tMin, double tMax) {
        return BezierClipper.intersect(ctx, table, records, quadratics, quarters, slabs, s, tMin, tMax, tolerance);
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
