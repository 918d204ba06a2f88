package org.beziertracer.intersect;

import org.beziertracer.accel.Accelerator;
import org.beziertracer.accel.Bvh;
import org.beziertracer.accel.FlatList;
import org.beziertracer.geometry.PatchNormals;
import org.beziertracer.geometry.RationalDeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.geometry.TrimCurves;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The whole-scene ray queries: {@link #closestHit} and {@link #occluded} over Bézier patches
 * (sub-patch BVH, then the chosen solver at the leaves), planes and spheres.
 *
 * <p>Immutable snapshot: build once per scene, share between render threads, each with its own
 * {@link TraceContext}. An edit of one patch makes a new snapshot with {@link #withPatch}, which
 * re-splits only that patch and refits the BVH (or rebuilds it when the number of sub-patches
 * changed).
 *
 * <p>In tessellated mode ({@link IntersectOptions#tessellate()} {@code = K > 0}) the patches are
 * replaced by a uniform triangle mesh ({@link TriangleMesh}) in the same kind of BVH; hits still
 * report the patch index and its (u,v), interpolated over the triangle, and
 * {@link #surfacePoint} returns the point on the triangle with the interpolated analytic normal.
 */
public final class SceneIntersector {

    final Scene scene;
    final SubPatchTable table;
    /** The triangles in tessellated mode; null in exact mode. */
    final TriangleMesh mesh;
    final Accelerator accel;
    final IntersectOptions options;
    final Method method;
    final AnalyticShapes shapes;
    /** Residual tolerance of the root polish, in scene units. */
    final double tolerance;
    final double sceneSize;
    final double buildMillis;
    /** The leaf solver without the trim test, for {@link TrimFilter} (one object, bound once). */
    private final TrimFilter.Solver untrimmed = this::solveLeaf;

    private SceneIntersector(Scene scene, SubPatchTable table, TriangleMesh mesh, Accelerator accel,
                             IntersectOptions options, double buildMillis) {
        this.scene = scene;
        this.table = table;
        this.mesh = mesh;
        this.accel = accel;
        this.options = options;
        this.method = options.method();
        this.shapes = new AnalyticShapes(scene.planes(), scene.spheres());
        double size = scene.patches().isEmpty() ? 1 : scene.controlBounds().diagonal();
        this.sceneSize = size > 0 ? size : 1;
        this.tolerance = 1e-12 * sceneSize;
        this.buildMillis = buildMillis;
    }

    /** Splits the patches and builds the acceleration structure. */
    public static SceneIntersector build(Scene scene, IntersectOptions options) {
        long t0 = System.nanoTime();
        if (options.tessellated()) {
            SubPatchTable whole = SubPatchTable.build(scene.patches(), SplitOptions.wholePatches());
            TriangleMesh mesh = scene.patches().isEmpty() ? null
                    : TriangleMesh.build(scene.patches(), options.tessellate());
            Accelerator accel = mesh == null ? FlatList.build(new double[0], 0)
                    : options.bvh() ? Bvh.build(mesh.bounds, mesh.count, options.bvhOptions())
                    : FlatList.build(mesh.bounds, mesh.count);
            return new SceneIntersector(scene, whole, mesh, accel, options, (System.nanoTime() - t0) / 1e6);
        }
        SubPatchTable table = SubPatchTable.build(scene.patches(), options.effectiveSplit());
        Accelerator accel = buildAccel(table, options);
        return new SceneIntersector(scene, table, null, accel, options, (System.nanoTime() - t0) / 1e6);
    }

    private static Accelerator buildAccel(SubPatchTable table, IntersectOptions options) {
        return options.bvh() ? Bvh.build(table.bounds, table.count, options.bvhOptions())
                : FlatList.build(table.bounds, table.count);
    }

    /**
     * A new snapshot with patch {@code index} replaced: only that patch is re-split; the BVH is
     * refitted when its sub-patch count is unchanged, else rebuilt.
     */
    public SceneIntersector withPatch(int index, BezierPatch patch) {
        if (options.tessellated()) {
            return build(scene.withPatch(index, patch), options); // the mesh is rebuilt whole
        }
        long t0 = System.nanoTime();
        SubPatchTable newTable = table.withPatch(index, patch);
        Accelerator newAccel;
        if (newTable.count == table.count && accel instanceof Bvh bvh) {
            newAccel = bvh.refit(newTable.bounds);
        } else {
            newAccel = buildAccel(newTable, options);
        }
        return new SceneIntersector(scene.withPatch(index, patch), newTable, null, newAccel, options,
                (System.nanoTime() - t0) / 1e6);
    }

    /** A fresh per-thread context. */
    public TraceContext newContext() { return new TraceContext(); }

    /**
     * Closest hit of the ray {@code o + t d}, {@code tMin < t < tMax}. Fills {@code hit} and
     * returns true when there is one. {@code d} need not be unit; t is along d as given.
     */
    public boolean closestHit(TraceContext ctx, double ox, double oy, double oz, double dx, double dy, double dz,
                              double tMin, double tMax, Hit hit) {
        bind(ctx);
        ctx.setRay(ox, oy, oz, dx, dy, dz);
        ctx.tMin = tMin;
        ctx.found = false;
        ctx.hitEvalPatch = -1;
        double best = tMax;
        if (mesh != null) {
            TriangleMesh.setRay(ctx);
        }
        if (accel.primCount() > 0) {
            best = accel.closestHit(ox, oy, oz, ctx.invDx, ctx.invDy, ctx.invDz, tMin, tMax, ctx, ctx.stack);
        }
        boolean any = ctx.found;
        if (any) {
            if (mesh != null) {
                // Tessellated: the patch parameters, interpolated over the winning triangle only
                Hit b = ctx.best;
                b.u = mesh.uv(b.subPatch, b.b1, b.b2, 0);
                b.v = mesh.uv(b.subPatch, b.b1, b.b2, 1);
            }
            hit.set(ctx.best);
            SurfaceParameters.toSurface(table, hit);
            best = hit.t;
        }
        for (int k = 0; k < shapes.planeCount; k++) {
            double t = shapes.planeT(k, ctx);
            if (t > tMin && t < best) {
                best = t;
                any = true;
                hit.t = t;
                hit.kind = Hit.PLANE;
                hit.index = k;
                hit.subPatch = -1;
            }
        }
        for (int k = 0; k < shapes.sphereCount; k++) {
            double t = shapes.sphereT(k, ctx, tMin, best);
            if (t > tMin && t < best) {
                best = t;
                any = true;
                hit.t = t;
                hit.kind = Hit.SPHERE;
                hit.index = k;
                hit.subPatch = -1;
            }
        }
        if (any && hit.kind != Hit.PATCH) {
            double px = ox + hit.t * dx, py = oy + hit.t * dy, pz = oz + hit.t * dz;
            if (hit.kind == Hit.PLANE) {
                shapes.planeUv(hit.index, px, py, pz, hit);
            } else {
                shapes.sphereUv(hit.index, px, py, pz, hit);
            }
        }
        return any;
    }

    /** True when anything blocks the ray for {@code tMin < t < tMax} (any-hit query). */
    public boolean occluded(TraceContext ctx, double ox, double oy, double oz, double dx, double dy, double dz,
                            double tMin, double tMax) {
        bind(ctx);
        ctx.setRay(ox, oy, oz, dx, dy, dz);
        ctx.tMin = tMin;
        for (int k = 0; k < shapes.sphereCount; k++) {
            if (!Double.isNaN(shapes.sphereT(k, ctx, tMin, tMax))) {
                return true;
            }
        }
        for (int k = 0; k < shapes.planeCount; k++) {
            double t = shapes.planeT(k, ctx);
            if (t > tMin && t < tMax) {
                return true;
            }
        }
        if (mesh != null) {
            TriangleMesh.setRay(ctx);
        }
        return accel.primCount() > 0
                && accel.occluded(ox, oy, oz, ctx.invDx, ctx.invDy, ctx.invDz, tMin, tMax, ctx, ctx.stack);
    }

    private void bind(TraceContext ctx) {
        ctx.scene = this;
        if (ctx.stack.length < accel.stackSize()) {
            ctx.stack = new int[accel.stackSize()];
        }
    }

    /**
     * Runs the selected solver on sub-patch {@code s}, keeping only roots inside the trim region
     * of a leaf that needs the test ({@link TrimFilter}); the root goes to {@code ctx.root*}.
     */
    boolean solvePatch(TraceContext ctx, int s, double tMin, double tMax) {
        if (table.trimTest != null && table.trimTest[s]) {
            return TrimFilter.solve(untrimmed, table, ctx, s, tMin, tMax);
        }
        return solveLeaf(ctx, s, tMin, tMax);
    }

    /** True when a tessellated-mode hit on triangle {@code prim} lies inside its patch's trim region. */
    boolean keepsTriangleHit(TraceContext ctx, int prim) {
        int k = mesh.patchOf[prim];
        TrimCurves trim = table.patchTrim[k];
        return trim == null || TrimFilter.inside(table, ctx, k, trim, mesh.uv(prim, ctx.rootB1, ctx.rootB2, 0),
                mesh.uv(prim, ctx.rootB1, ctx.rootB2, 1));
    }

    /** The selected solver on sub-patch {@code s}, trims ignored. */
    private boolean solveLeaf(TraceContext ctx, int s, double tMin, double tMax) {
        ctx.solverCalls++;
        switch (method) {
            case CLIPPING:
                return BezierClipper.intersect(ctx, table, s, tMin, tMax, tolerance);
            case NEWTON:
                return NewtonSolver.intersect(ctx, table, s, tMin, tMax, tolerance);
            default:
                return SubdivisionSolver.intersect(ctx, table, s, tMin, tMax, tolerance);
        }
    }

    /**
     * Evaluates the surface at a hit (position, dp/du, dp/dv, unit normal), on the parent patch
     * for patch hits; when the solver's last evaluation was at exactly the hit's (u,v) of that
     * patch (Newton ends there), it is reused instead of evaluated again (bit-identical). Call
     * right after {@link #closestHit} with the same context (it uses the context's ray).
     */
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        sp.u = hit.u;
        sp.v = hit.v;
        sp.kind = hit.kind;
        sp.index = hit.index;
        if (hit.kind == Hit.PATCH && mesh != null) {
            mesh.surfacePoint(hit.subPatch, hit.b1, hit.b2, sp);
        } else if (hit.kind == Hit.PATCH) {
            patchPoint(ctx, hit, sp);
        } else if (hit.kind == Hit.PLANE) {
            shapes.planePoint(hit.index, hit, ctx, sp);
        } else {
            shapes.spherePoint(hit.index, hit, ctx, sp);
        }
    }

    /**
     * The patch geometry at a patch hit, on the parent patch (rational through its homogeneous
     * net); for a piece of a free-form surface the derivatives are with respect to the surface's
     * parameters, which the hit reports.
     */
    private void patchPoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        int k = hit.index;
        int off = table.patchNetOffset[k], n = table.patchDegreeU[k], m = table.patchDegreeV[k], dim = table.patchDim[k];
        boolean plain = SurfaceParameters.unit(table, k);
        double u = plain ? hit.u : SurfaceParameters.s(table, k, hit.u);
        double v = plain ? hit.v : SurfaceParameters.t(table, k, hit.v);
        double[] e = ctx.hitEval;
        if (ctx.hitEvalPatch != k || ctx.hitEvalU != u || ctx.hitEvalV != v) {
            // Not the solver's last evaluation at this hit: evaluate (same kernel, same result)
            e = ctx.eval;
            ctx.evalPatch = -1;
            RationalDeCasteljau.pointAndDerivatives(table.patchNets, off, n, m, dim, u, v, e, ctx.scratch);
        }
        double su = 1, sv = 1;
        if (!plain) {
            su = 1 / (table.patchDomain[4 * k + 1] - table.patchDomain[4 * k]);
            sv = 1 / (table.patchDomain[4 * k + 3] - table.patchDomain[4 * k + 2]);
        }
        sp.px = e[0]; sp.py = e[1]; sp.pz = e[2];
        sp.dpdux = e[3] * su; sp.dpduy = e[4] * su; sp.dpduz = e[5] * su;
        sp.dpdvx = e[6] * sv; sp.dpdvy = e[7] * sv; sp.dpdvz = e[8] * sv;
        double[] nrm = ctx.normal;
        PatchNormals.unitNormal(table.patchNets, off, n, m, dim, u, v, e, table.patchSquaredExtent[k], nrm, 0,
                ctx.scratch);
        sp.nx = nrm[0]; sp.ny = nrm[1]; sp.nz = nrm[2];
    }

    public Scene scene() { return scene; }

    public SubPatchTable table() { return table; }

    public IntersectOptions options() { return options; }

    /** Sub-patches in exact mode (whole patches with the BVH off). */
    public int subPatchCount() { return table.count; }

    /** Triangles in tessellated mode, 0 in exact mode. */
    public int triangleCount() { return mesh == null ? 0 : mesh.count; }

    /** Primitives in the acceleration structure: sub-patches, or triangles in tessellated mode. */
    public int primitiveCount() { return accel.primCount(); }

    public int nodeCount() { return accel.nodeCount(); }

    public int depth() { return accel.depth(); }

    public double buildMillis() { return buildMillis; }

    public double sceneSize() { return sceneSize; }
}
