package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.model.Scene;

/**
 * Leaves that are the scene's spheres, met by formula ({@link AnalyticShapes#sphereT}): one BVH
 * leaf per sphere, its box the sphere's. A hit records {@link Hit#SPHERE} and the sphere's index;
 * its (u,v) are the spherical texture coordinates and its surface point the one
 * {@link AnalyticShapes} gives, as when the spheres were tested outside the BVH.
 *
 * <p>An edit of the scene's patches keeps these leaves as they are. Immutable; shared by render
 * threads.
 */
final class SphereLeaves implements FixedLeaves {

    final AnalyticShapes shapes;

    private SphereLeaves(AnalyticShapes shapes) {
        this.shapes = shapes;
    }

    /** The spheres of {@code scene}; null when it has none. */
    static SphereLeaves build(Scene scene) {
        return scene.spheres().isEmpty() ? null : new SphereLeaves(new AnalyticShapes(List.of(), scene.spheres()));
    }

    @Override
    public double intersect(TraceContext ctx, int k, double tMax) {
        double t = shapes.sphereT(k, ctx, ctx.tMin, tMax);
        if (!(t < tMax)) {
            return tMax;
        }
        ctx.rootT = t;
        ctx.recordHit(Hit.SPHERE, k, k);
        return t;
    }

    @Override
    public boolean occludes(TraceContext ctx, int k, double tMax) {
        return !Double.isNaN(shapes.sphereT(k, ctx, ctx.tMin, tMax));
    }

    /** The spherical texture coordinates of the hit point. */
    @Override
    public void completeHit(TraceContext ctx, Hit hit) {
        shapes.sphereUv(hit.index, ctx.ox + hit.t * ctx.dx, ctx.oy + hit.t * ctx.dy, ctx.oz + hit.t * ctx.dz, hit);
    }

    @Override
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        shapes.spherePoint(hit.index, hit, ctx, sp);
    }

    @Override
    public boolean holdsSpheres() { return true; }

    @Override
    public long bytes() { return org.beziertracer.math.HeapBytes.of(shapes.spheres); }

    @Override
    public int count() { return shapes.sphereCount; }

    @Override
    public double[] bounds(int first, int n) {
        double[] b = new double[6 * n];
        double[] s = shapes.spheres;
        for (int i = 0; i < n; i++) {
            int o = AnalyticShapes.SPHERE_STRIDE * (first + i);
            double r = s[o + 3];
            for (int c = 0; c < 3; c++) {
                b[6 * i + c] = s[o + c] - r;
                b[6 * i + 3 + c] = s[o + c] + r;
            }
        }
        return b;
    }

    /** No patches here. */
    @Override
    public int firstLeaf(int k) { return 0; }

    /** None of these leaves is a patch's (so a big scene of them is not grouped by patch). */
    @Override
    public int patchLeafCount() { return 0; }

    @Override
    public int leafCount(int k) { return 0; }

    @Override
    public int subPatchCount() { return 0; }
}
