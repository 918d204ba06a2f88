package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.geometry.TrimCurves;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Leaves of the tessellated mode: the triangles of a {@link TriangleMesh}, met with its watertight
 * test. A hit keeps the triangle and its barycentric weights while searching; the winner's patch
 * (u,v) is interpolated over that triangle only ({@link #completeHit}), and its surface point is
 * the point on the triangle with the normal interpolated from the analytic vertex normals. A hit
 * on a trimmed patch counts only inside its trim region, decided at the interpolated (u,v) on the
 * exact trim curves ({@link TrimmedLeaves#inside}); hits report the surface's own (u,v)
 * ({@link SurfaceParameters}).
 *
 * <p>Immutable; shared by render threads, each with its own {@link TraceContext}.
 */
final class TriangleLeaves implements Leaves {

    final TriangleMesh mesh;
    private final int patchCount;
    /** Per patch its trim curves (null when untrimmed); null when no patch is trimmed. */
    private final TrimCurves[] trims;
    /** Per patch {@code u0, u1, v0, v1} of its surface's parameters. */
    private final double[] domains;

    private TriangleLeaves(TriangleMesh mesh, List<BezierPatch> patches) {
        this.mesh = mesh;
        this.patchCount = patches.size();
        TrimCurves[] t = TrimCurves.forPatches(patches);
        this.trims = java.util.Arrays.stream(t).allMatch(java.util.Objects::isNull) ? null : t;
        this.domains = SubPatchTable.domains(patches);
    }

    /** Tessellates every patch of {@code scene} (at least one) with {@code k×k} cells. */
    static TriangleLeaves build(Scene scene, int k) {
        return new TriangleLeaves(TriangleMesh.build(scene.patches(), k), scene.patches());
    }

    /** True when triangle {@code t}'s hit (barycentric weights in the context) is inside its patch's trim region. */
    private boolean inTrim(TraceContext ctx, int t) {
        if (trims == null) {
            return true;
        }
        int k = mesh.patchOf[t];
        return trims[k] == null || TrimmedLeaves.inside(domains, k, trims[k], mesh.uv(t, ctx.rootB1, ctx.rootB2, 0),
                mesh.uv(t, ctx.rootB1, ctx.rootB2, 1), ctx.trimScratch);
    }

    @Override
    public void beginRay(TraceContext ctx) {
        TriangleMesh.setRay(ctx);
    }

    @Override
    public double intersect(TraceContext ctx, int t, double tMax) {
        if (!mesh.intersect(ctx, t, ctx.tMin, tMax) || !inTrim(ctx, t)) {
            return tMax;
        }
        ctx.recordHit(mesh.patchOf[t], t);
        ctx.best.b1 = ctx.rootB1;
        ctx.best.b2 = ctx.rootB2;
        return ctx.rootT;
    }

    @Override
    public boolean occludes(TraceContext ctx, int t, double tMax) {
        return mesh.intersect(ctx, t, ctx.tMin, tMax) && inTrim(ctx, t);
    }

    /** The patch parameters, interpolated over the winning triangle only. */
    @Override
    public void completeHit(Hit hit) {
        hit.u = mesh.uv(hit.subPatch, hit.b1, hit.b2, 0);
        hit.v = mesh.uv(hit.subPatch, hit.b1, hit.b2, 1);
        SurfaceParameters.toSurface(domains, hit);
    }

    @Override
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        mesh.surfacePoint(hit.subPatch, hit.b1, hit.b2, sp);
    }

    /** The whole mesh is tessellated again (the mode is for measurement, not editing). */
    @Override
    public TriangleLeaves withPatch(Scene edited, int index, double sceneSize) {
        return build(edited, mesh.segments);
    }

    /** The whole mesh is tessellated again, once. */
    @Override
    public TriangleLeaves withPatches(Scene edited, int[] indices, double sceneSize, boolean keepSplit) {
        return build(edited, mesh.segments);
    }

    /** Every patch is tessellated alike, so the untouched patches' triangles are the same. */
    @Override
    public boolean keepsUntouchedLeaves(Leaves before) { return before instanceof TriangleLeaves; }

    @Override
    public long bytes() { return mesh.bytes(); }

    @Override
    public int count() { return mesh.count; }

    @Override
    public double[] bounds(int first, int n) { return java.util.Arrays.copyOfRange(mesh.bounds, 6 * first, 6 * (first + n)); }

    /** Triangles are grouped by patch, {@code 2·K²} each ({@link TriangleMesh}). */
    @Override
    public int firstLeaf(int k) { return k * leafCount(k); }

    @Override
    public int leafCount(int k) { return 2 * mesh.segments * mesh.segments; }

    @Override
    public int subPatchCount() { return patchCount; }

    @Override
    public int triangleCount() { return mesh.count; }
}
