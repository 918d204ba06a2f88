package org.beziertracer.intersect;

import org.beziertracer.model.Scene;

/**
 * Leaves of the tessellated mode: the triangles of a {@link TriangleMesh}, met with its watertight
 * test. A hit keeps the triangle and its barycentric weights while searching; the winner's patch
 * (u,v) is interpolated over that triangle only ({@link #completeHit}), and its surface point is
 * the point on the triangle with the normal interpolated from the analytic vertex normals.
 *
 * <p>Immutable; shared by render threads, each with its own {@link TraceContext}.
 */
final class TriangleLeaves implements Leaves {

    final TriangleMesh mesh;
    private final int patchCount;

    private TriangleLeaves(TriangleMesh mesh, int patchCount) {
        this.mesh = mesh;
        this.patchCount = patchCount;
    }

    /** Tessellates every patch of {@code scene} (at least one) with {@code k×k} cells. */
    static TriangleLeaves build(Scene scene, int k) {
        return new TriangleLeaves(TriangleMesh.build(scene.patches(), k), scene.patchCount());
    }

    @Override
    public void beginRay(TraceContext ctx) {
        TriangleMesh.setRay(ctx);
    }

    @Override
    public double intersect(TraceContext ctx, int t, double tMax) {
        if (!mesh.intersect(ctx, t, ctx.tMin, tMax)) {
            return tMax;
        }
        ctx.recordHit(mesh.patchOf[t], t);
        ctx.best.b1 = ctx.rootB1;
        ctx.best.b2 = ctx.rootB2;
        return ctx.rootT;
    }

    @Override
    public boolean occludes(TraceContext ctx, int t, double tMax) {
        return mesh.intersect(ctx, t, ctx.tMin, tMax);
    }

    /** The patch parameters, interpolated over the winning triangle only. */
    @Override
    public void completeHit(Hit hit) {
        hit.u = mesh.uv(hit.subPatch, hit.b1, hit.b2, 0);
        hit.v = mesh.uv(hit.subPatch, hit.b1, hit.b2, 1);
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

    @Override
    public int count() { return mesh.count; }

    @Override
    public double[] bounds() { return mesh.bounds; }

    @Override
    public int subPatchCount() { return patchCount; }

    @Override
    public int triangleCount() { return mesh.count; }
}
