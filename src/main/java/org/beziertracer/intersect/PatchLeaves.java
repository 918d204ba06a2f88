package org.beziertracer.intersect;

import org.beziertracer.accel.LaneIntersector;
import org.beziertracer.accel.LaneOccluder;
import org.beziertracer.geometry.PatchNormals;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.geometry.SurfaceCurvature;
import org.beziertracer.model.Scene;

/**
 * Leaves that are sub-patches of Bézier patches ({@link SubPatchTable}), each subclass one ray–patch
 * solver ({@link #solve}). What every patch solver shares lives here: the hit is recorded with the
 * parent patch's parameters, and the surface point is evaluated once, for the final hit, on the
 * parent patch (reusing the solver's last evaluation when it ended at exactly the hit).
 *
 * <p>A new solver is a subclass with its own {@link #solve} and {@link #with}, named by a
 * {@link Method} constant. Rational patches need nothing here beyond their evaluation (the solvers
 * handle their leaves, {@link RationalNets}); a scene with trimmed patches gets its solver wrapped
 * in {@link TrimmedLeaves}. Hits of pieces of free-form surfaces report the surface's own (u,v)
 * ({@link #completeHit}, {@link SurfaceParameters}).
 *
 * <p>Immutable; shared by render threads, each with its own {@link TraceContext}.
 */
abstract class PatchLeaves implements Leaves, LaneIntersector<TraceContext>, LaneOccluder<TraceContext> {

    /** Root-polish residual tolerance, as a fraction of the scene size. */
    static final double RELATIVE_TOLERANCE = 1e-12;

    final SubPatchTable table;
    /** Residual tolerance of the root polish, in scene units. */
    final double tolerance;

    PatchLeaves(SubPatchTable table, double tolerance) {
        this.table = table;
        this.tolerance = tolerance;
    }

    /** Makes patch leaves of one solver; {@link Method} holds one per method. */
    @FunctionalInterface
    interface Factory {
        PatchLeaves create(SubPatchTable table, double tolerance);
    }

    /** Pre-splits the scene's patches as {@code options} say and picks the solver of its method. */
    static PatchLeaves build(Scene scene, IntersectOptions options, double sceneSize) {
        SubPatchTable table = SubPatchTable.build(scene.patches(), options.effectiveSplit(), scene.instances());
        return TrimmedLeaves.ifTrimmed(options.method().leaves.create(table, RELATIVE_TOLERANCE * sceneSize));
    }

    /**
     * Nearest root of sub-patch {@code s} with {@code tMin < t < tMax}: on success the ray
     * parameter and the parent patch's (u,v) are in {@code ctx.rootT, rootU, rootV} and the result
     * is true. When the solver's last evaluation of the parent patch ({@code ctx.eval},
     * {@code ctx.evalPatch, evalU, evalV}) is at the root, {@link #surfacePoint} reuses it.
     */
    abstract boolean solve(TraceContext ctx, int s, double tMin, double tMax);

    /** The same solver over another table, with another tolerance (after an edit). */
    abstract PatchLeaves with(SubPatchTable edited, double editedTolerance);

    @Override
    public final double intersect(TraceContext ctx, int s, double tMax) {
        ctx.solverCalls++;
        ctx.ensurePlanes();
        if (!solve(ctx, s, ctx.tMin, tMax)) {
            return tMax;
        }
        return recordRoot(ctx, s);
    }

    @Override
    public final org.beziertracer.accel.LaneIntersector<TraceContext> lanes() { return this; }

    @Override
    public final LaneOccluder<TraceContext> anyLanes() { return this; }

    /** Records the solver's root ({@code ctx.root*}) on leaf {@code s} as the best hit; returns its t. */
    final double recordRoot(TraceContext ctx, int s) {
        int k = table.parent[s];
        ctx.recordHit(k, s);
        ctx.best.u = ctx.rootU;
        ctx.best.v = ctx.rootV;
        if (ctx.evalPatch == k && ctx.evalU == ctx.rootU && ctx.evalV == ctx.rootV) {
            ctx.keepEvaluationForHit();
        }
        return ctx.rootT;
    }

    /**
     * Leaf {@code s} against the lanes {@code lanes[0..count)} of the context's {@link RayBatch}
     * ({@link org.beziertracer.accel.LaneIntersector}): the same answers as {@link #intersect} for
     * each lane alone. Here each lane is solved alone in turn; a solver with stages that run across
     * lanes ({@link ClippingLeaves}) overrides it.
     */
    @Override
    public void intersect(TraceContext ctx, int s, int[] lanes, int count, double[] tMax) {
        RayBatch batch = ctx.batch;
        int k = table.parent[s];
        for (int j = 0; j < count; j++) {
            int lane = lanes[j];
            batch.loadRay(ctx, lane);
            ctx.solverCalls++;
            if (solve(ctx, s, ctx.tMin, tMax[lane])) {
                tMax[lane] = batch.record(ctx, lane, k, s);
            }
        }
    }

    @Override
    public final boolean occludes(TraceContext ctx, int s, double tMax) {
        ctx.solverCalls++;
        ctx.ensurePlanes();
        return !provenBehind(ctx, s) && solve(ctx, s, ctx.tMin, tMax);
    }

    /**
     * A leaf of the patch a shadow ray leaves, provably behind it, is skipped; but one proven
     * single-root costs less to solve (Newton, from the origin's point on its own leaf).
     */
    final boolean provenBehind(TraceContext ctx, int s) {
        int origin = ctx.originLeaf;
        if (origin >= 0 && table.parent[s] == table.parent[origin] && !RootUniqueness.atMostOneRoot(ctx, table, s)
                && OriginLeaf.cannotMeet(ctx, table, s)) {
            ctx.originCannotMeet++;
            return true;
        }
        return false;
    }

    /**
     * Leaf {@code s} against the shadow-ray lanes {@code lanes[0..count)} of the context's
     * {@link RayBatch} ({@link LaneOccluder}): the answers of {@link #occludes(TraceContext, int,
     * double)} for each lane alone. Here each lane is solved alone in turn; {@link ClippingLeaves}
     * overrides it.
     */
    @Override
    public void occludes(TraceContext ctx, int s, int[] lanes, int count, double[] tMax, boolean[] occluded) {
        RayBatch batch = ctx.batch;
        for (int j = 0; j < count; j++) {
            int lane = lanes[j];
            batch.loadShadowRay(ctx, lane);
            if (occludes(ctx, s, tMax[lane])) {
                occluded[lane] = true;
            }
        }
    }

    /** A hit on a piece of a free-form surface reports the surface's own (u,v). */
    @Override
    public final void completeHit(Hit hit) {
        SurfaceParameters.toSurface(table.patchDomain, hit);
    }

    /**
     * Position, derivatives and unit normal on the parent patch at the hit's (u,v) (a rational
     * patch through its homogeneous net); when the solver's last evaluation was at exactly that
     * point of that patch (Newton ends there), it is reused instead of evaluated again
     * (bit-identical). For a piece of a free-form surface the derivatives are with respect to the
     * surface's parameters, which the hit reports.
     */
    @Override
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        int k = hit.index;
        int off = table.patchNetOffset[k], n = table.patchDegreeU[k], m = table.patchDegreeV[k], dim = table.patchDim[k];
        double[] domain = table.patchDomain;
        boolean plain = SurfaceParameters.unit(domain, k);
        double u = plain ? hit.u : SurfaceParameters.s(domain, k, hit.u);
        double v = plain ? hit.v : SurfaceParameters.t(domain, k, hit.v);
        double[] e = ctx.hitEval;
        if (ctx.hitEvalPatch != k || ctx.hitEvalU != u || ctx.hitEvalV != v) {
            // Not the solver's last evaluation at this hit: evaluate (same kernel, same result)
            e = ctx.eval;
            ctx.evalPatch = -1;
            table.evaluatePatch(k, u, v, e, ctx.scratch);
            ctx.evaluations++;
        } else {
            ctx.hitEvaluations++;
        }
        double du = plain ? 1 : 1 / (domain[4 * k + 1] - domain[4 * k]);
        double dv = plain ? 1 : 1 / (domain[4 * k + 3] - domain[4 * k + 2]);
        sp.px = e[0]; sp.py = e[1]; sp.pz = e[2];
        sp.dpdux = e[3] * du; sp.dpduy = e[4] * du; sp.dpduz = e[5] * du;
        sp.dpdvx = e[6] * dv; sp.dpdvy = e[7] * dv; sp.dpdvz = e[8] * dv;
        double[] nrm = ctx.normal;
        PatchNormals.unitNormal(table.patchNets, off, n, m, dim, u, v, e, table.patchSquaredExtent[k], nrm, 0,
                ctx.scratch);
        sp.nx = nrm[0]; sp.ny = nrm[1]; sp.nz = nrm[2];
    }

    /**
     * Exact curvature of the parent patch at the hit's (u,v) ({@link SurfaceCurvature}, through
     * the homogeneous net of a rational patch); the principal curvatures do not depend on the
     * parameters, so a piece of a free-form surface is measured in its own [0,1]².
     */
    @Override
    public final boolean curvature(TraceContext ctx, Hit hit, double[] out) {
        int k = hit.index;
        double[] domain = table.patchDomain;
        boolean plain = SurfaceParameters.unit(domain, k);
        double u = plain ? hit.u : SurfaceParameters.s(domain, k, hit.u);
        double v = plain ? hit.v : SurfaceParameters.t(domain, k, hit.v);
        SurfaceCurvature.at(table.patchNets, table.patchNetOffset[k], table.patchDegreeU[k], table.patchDegreeV[k],
                table.patchDim[k], u, v, table.patchSquaredExtent[k], out, ctx.curvatureScratch);
        return true;
    }

    /** Re-splits only the edited patch, as {@link #withPatches} keeping its split. */
    @Override
    public final PatchLeaves withPatch(Scene edited, int index, double sceneSize) {
        return withPatches(edited, new int[] {index}, sceneSize, true);
    }

    /**
     * Re-splits only the edited patches, in one new table, with {@code keepSplit} each along its old
     * halvings where they still fit ({@link SubPatchTable#withPatches(int[], java.util.List, boolean)}: a drag usually
     * keeps the leaf count, and the BVH is refitted); the solver's per-leaf data of the other
     * patches is copied ({@link #with(SubPatchTable, double, int[])}) unless the edit split every
     * patch afresh ({@link SubPatchTable#keepsUntouchedLeaves}).
     */
    @Override
    public final PatchLeaves withPatches(Scene edited, int[] indices, double sceneSize, boolean keepSplit) {
        java.util.List<org.beziertracer.model.BezierPatch> replacements = new java.util.ArrayList<>(indices.length);
        for (int index : indices) {
            replacements.add(edited.patches().get(index));
        }
        SubPatchTable after = table.withPatches(indices, replacements, keepSplit);
        double tol = RELATIVE_TOLERANCE * sceneSize;
        return TrimmedLeaves.ifTrimmed(table.keepsUntouchedLeaves(after) ? with(after, tol, indices) : with(after, tol));
    }

    /**
     * {@link #with(SubPatchTable, double)} for {@code edited}, this table edited in the patches
     * {@code editedPatches} only: a solver with per-leaf data computes it for those patches' leaves
     * and copies the rest ({@link EditedLeafData}).
     */
    PatchLeaves with(SubPatchTable edited, double editedTolerance, int[] editedPatches) {
        return with(edited, editedTolerance);
    }

    /** The table's {@link SubPatchTable#keepsUntouchedLeaves}. */
    @Override
    public final boolean keepsUntouchedLeaves(Leaves before) {
        return before instanceof PatchLeaves p && p.table.keepsUntouchedLeaves(table);
    }

    @Override
    public final long bytes() { return table.bytes() + solverBytes(); }

    /** Heap held by the solver's own per-leaf data beyond the table; none by default. */
    long solverBytes() { return 0; }

    @Override
    public final int count() { return table.count; }

    @Override
    public final double[] bounds(int first, int n) { return table.bounds(first, n); }

    @Override
    public final int firstLeaf(int k) { return table.firstOf[k]; }

    @Override
    public final int leafCount(int k) { return table.countOf(k); }

    @Override
    public final int subPatchCount() { return table.count; }
}
