package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.PatchNormals;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.Scene;

/**
 * Leaves that are sub-patches of Bézier patches ({@link SubPatchTable}), each subclass one ray–patch
 * solver ({@link #solve}). What every patch solver shares lives here: the hit is recorded with the
 * parent patch's parameters, and the surface point is evaluated once, for the final hit, on the
 * parent patch (reusing the solver's last evaluation when it ended at exactly the hit).
 *
 * <p>A new solver is a subclass with its own {@link #solve} and {@link #with}, named by a
 * {@link Method} constant; a trimmed patch can wrap another {@code PatchLeaves} and reject the roots
 * outside its trim in {@link #solve}; a rational patch overrides {@link #surfacePoint} too.
 *
 * <p>Immutable; shared by render threads, each with its own {@link TraceContext}.
 */
abstract class PatchLeaves implements Leaves {

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
        SubPatchTable table = SubPatchTable.build(scene.patches(), options.effectiveSplit());
        return options.method().leaves.create(table, RELATIVE_TOLERANCE * sceneSize);
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
        if (!solve(ctx, s, ctx.tMin, tMax)) {
            return tMax;
        }
        int k = table.parent[s];
        ctx.recordHit(k, s);
        ctx.best.u = ctx.rootU;
        ctx.best.v = ctx.rootV;
        if (ctx.evalPatch == k && ctx.evalU == ctx.rootU && ctx.evalV == ctx.rootV) {
            ctx.keepEvaluationForHit();
        }
        return ctx.rootT;
    }

    @Override
    public final boolean occludes(TraceContext ctx, int s, double tMax) {
        ctx.solverCalls++;
        return solve(ctx, s, ctx.tMin, tMax);
    }

    /**
     * Position, derivatives and unit normal on the parent patch at the hit's (u,v); when the
     * solver's last evaluation was at exactly that point of that patch (Newton ends there), it is
     * reused instead of evaluated again (bit-identical).
     */
    @Override
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        int k = hit.index;
        int off = table.patchNetOffset[k], n = table.patchDegreeU[k], m = table.patchDegreeV[k];
        double[] e = ctx.hitEval;
        if (ctx.hitEvalPatch != k || ctx.hitEvalU != hit.u || ctx.hitEvalV != hit.v) {
            // Not the solver's last evaluation at this hit: evaluate (same kernel, same result)
            e = ctx.eval;
            ctx.evalPatch = -1;
            DeCasteljau.evaluateWithDerivatives(table.patchNets, off, n, m, hit.u, hit.v, e, ctx.scratch);
        }
        sp.px = e[0]; sp.py = e[1]; sp.pz = e[2];
        sp.dpdux = e[3]; sp.dpduy = e[4]; sp.dpduz = e[5];
        sp.dpdvx = e[6]; sp.dpdvy = e[7]; sp.dpdvz = e[8];
        double[] nrm = ctx.normal;
        PatchNormals.unitNormal(table.patchNets, off, n, m, hit.u, hit.v, e, table.patchSquaredExtent[k], nrm, 0,
                ctx.scratch);
        sp.nx = nrm[0]; sp.ny = nrm[1]; sp.nz = nrm[2];
    }

    /** Re-splits only the edited patch ({@link SubPatchTable#withPatch}). */
    @Override
    public final PatchLeaves withPatch(Scene edited, int index, double sceneSize) {
        return with(table.withPatch(index, edited.patches().get(index)), RELATIVE_TOLERANCE * sceneSize);
    }

    @Override
    public final int count() { return table.count; }

    @Override
    public final double[] bounds() { return table.bounds; }

    @Override
    public final int subPatchCount() { return table.count; }
}
