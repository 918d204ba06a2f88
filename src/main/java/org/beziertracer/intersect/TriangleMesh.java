package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.geometry.Tessellator;
import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;

/**
 * The tessellated mode's geometry: every patch replaced by the uniform {@code K×K}-cell grid of
 * {@link Tessellator} (two triangles a cell, analytic unit normals and patch parameters at the
 * vertices), intersected with the watertight ray–triangle test of S. Woop, C. Benthin, I. Wald,
 * "Watertight ray/triangle intersection", JCGT 2(1), 2013. Shared edges are evaluated with the
 * same arithmetic from both sides, so a ray through an edge or a vertex cannot slip between two
 * triangles of the grid (nor between two patches whose border vertices coincide).
 *
 * <h2>Layout</h2>
 * <ul>
 *   <li>{@code corners[9t .. 9t+8]}: the three vertex positions of triangle {@code t},
 *       {@code x0 y0 z0 x1 y1 z1 x2 y2 z2}, copied out of the mesh so that the hot loop reads
 *       one contiguous run per triangle;</li>
 *   <li>{@code bounds[6t .. 6t+5]}: its axis-aligned box, for the BVH;</li>
 *   <li>{@link #mesh}: the indexed {@link Mesh} (vertex normals, uvs, patch of each triangle),
 *       read only for the final hit.</li>
 * </ul>
 * Zero-area triangles at collapsed patch edges are kept (the Woop test never reports them).
 *
 * <p>Immutable and shared by render threads; queries use the caller's {@link TraceContext} and
 * do not allocate.
 */
final class TriangleMesh {

    final int segments;
    final Mesh mesh;
    final int count;
    final double[] corners;
    final double[] bounds;
    final int[] patchOf;

    private TriangleMesh(int segments, Mesh mesh) {
        this.segments = segments;
        this.mesh = mesh;
        this.count = mesh.triangleCount();
        this.corners = new double[9 * count];
        this.bounds = new double[6 * count];
        this.patchOf = mesh.patchOfTriangle();
        for (int t = 0; t < count; t++) {
            for (int corner = 0; corner < 3; corner++) {
                int vert = mesh.triangleVertex(t, corner);
                for (int c = 0; c < 3; c++) {
                    corners[9 * t + 3 * corner + c] = mesh.position(vert, c);
                }
            }
            for (int c = 0; c < 3; c++) {
                double a = corners[9 * t + c], b = corners[9 * t + 3 + c], d = corners[9 * t + 6 + c];
                bounds[6 * t + c] = Math.min(a, Math.min(b, d));
                bounds[6 * t + 3 + c] = Math.max(a, Math.max(b, d));
            }
        }
    }

    /**
     * About the most heap {@link #build} holds at once for {@code patchCount} patches of
     * {@code k×k} cells, in bytes: the indexed {@link Mesh} (vertex positions, normals and uvs,
     * triangle indices and patch tags, which the mesh copies once when it is made) and this
     * class's corner, box and patch arrays. The BVH over the triangles is estimated by
     * {@link org.beziertracer.accel.Bvh#estimateBytes}. Keep this in step with the fields above.
     */
    static long estimateBytes(long patchCount, int k) {
        long vertices = patchCount * (k + 1L) * (k + 1L);
        long triangles = patchCount * 2L * k * k;
        long mesh = vertices * (3 * 8 + 3 * 8 + 2 * 8) + triangles * (3 * 4 + 4);
        long own = triangles * (9 * 8 + 6 * 8 + 4);
        return 2 * mesh + own;                                 // the mesh's arrays exist twice while it copies them
    }

    /** Heap held by the mesh and this class's arrays, in bytes. */
    long bytes() {
        int v = mesh.vertexCount(), t = mesh.triangleCount();
        return HeapBytes.array(3L * v, 8) + HeapBytes.array(3L * v, 8) + HeapBytes.array(2L * v, 8)
                + HeapBytes.array(3L * t, 4) + HeapBytes.array(t, 4)
                + HeapBytes.of(corners) + HeapBytes.of(bounds) + HeapBytes.of(patchOf);
    }

    /**
     * The triangles of {@code mesh} as they are (a scene's meshes joined into one, the source
     * index of each triangle's mesh in its patch tags): {@link #segments} 0, and only
     * {@link #intersect} and the arrays are used ({@link MeshLeaves} shades them).
     */
    static TriangleMesh of(Mesh mesh) {
        return new TriangleMesh(0, mesh);
    }

    /** Tessellates every patch with {@code k×k} cells (build time; allocates). */
    static TriangleMesh build(List<BezierPatch> patches, int k) {
        return new TriangleMesh(k, Tessellator.tessellate(patches, k));
    }

    /**
     * Per-ray set-up of the watertight test: the axis {@code kz} where the direction is largest,
     * the other two axes (swapped when {@code d[kz] < 0} to keep the winding), and the shear
     * that maps the ray onto the +z axis. Stored in the context.
     */
    static void setRay(TraceContext ctx) {
        double ax = Math.abs(ctx.dx), ay = Math.abs(ctx.dy), az = Math.abs(ctx.dz);
        int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        int kx = kz == 2 ? 0 : kz + 1;
        int ky = kx == 2 ? 0 : kx + 1;
        double dkz = component(ctx.dx, ctx.dy, ctx.dz, kz);
        if (dkz < 0) {
            int swap = kx;
            kx = ky;
            ky = swap;
        }
        ctx.kx = kx;
        ctx.ky = ky;
        ctx.kz = kz;
        ctx.shearX = component(ctx.dx, ctx.dy, ctx.dz, kx) / dkz;
        ctx.shearY = component(ctx.dx, ctx.dy, ctx.dz, ky) / dkz;
        ctx.shearZ = 1.0 / dkz;
        ctx.permOx = component(ctx.ox, ctx.oy, ctx.oz, kx);
        ctx.permOy = component(ctx.ox, ctx.oy, ctx.oz, ky);
        ctx.permOz = component(ctx.ox, ctx.oy, ctx.oz, kz);
    }

    private static double component(double x, double y, double z, int axis) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    /**
     * Watertight test of triangle {@code t} against the context's ray (after {@link #setRay}) for
     * {@code tMin < t < tMax}. On a hit stores the ray parameter in {@code ctx.rootT} and the
     * barycentric weights of the second and third corner in {@code ctx.rootB1}, {@code ctx.rootB2}.
     */
    boolean intersect(TraceContext ctx, int t, double tMin, double tMax) {
        final double[] p = corners;
        final int o = 9 * t;
        final int kx = ctx.kx, ky = ctx.ky, kz = ctx.kz;
        final double sx = ctx.shearX, sy = ctx.shearY, sz = ctx.shearZ;
        // Vertices relative to the ray origin, in the permuted frame
        final double ox = ctx.permOx, oy = ctx.permOy, oz = ctx.permOz;
        double axr = p[o + kx] - ox, ayr = p[o + ky] - oy, azr = p[o + kz] - oz;
        double bxr = p[o + 3 + kx] - ox, byr = p[o + 3 + ky] - oy, bzr = p[o + 3 + kz] - oz;
        double cxr = p[o + 6 + kx] - ox, cyr = p[o + 6 + ky] - oy, czr = p[o + 6 + kz] - oz;
        // Shear so that the ray is the +z axis
        double ax = axr - sx * azr, ay = ayr - sy * azr;
        double bx = bxr - sx * bzr, by = byr - sy * bzr;
        double cx = cxr - sx * czr, cy = cyr - sy * czr;
        // Scaled barycentrics: edge functions
        double u = cx * by - cy * bx;
        double v = ax * cy - ay * cx;
        double w = bx * ay - by * ax;
        if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) {
            return false;
        }
        double det = u + v + w;
        if (det == 0) {
            return false;
        }
        // Scaled distance, compared without dividing first
        double tScaled = u * (sz * azr) + v * (sz * bzr) + w * (sz * czr);
        double tHit = tScaled / det;
        if (!(tHit > tMin && tHit < tMax)) {
            return false;
        }
        double inv = 1.0 / det;
        ctx.rootT = tHit;
        ctx.rootB1 = v * inv;
        ctx.rootB2 = w * inv;
        return true;
    }

    /** Patch parameter {@code c} (0 = u, 1 = v) at barycentric weights (b1, b2) of triangle {@code t}. */
    double uv(int t, double b1, double b2, int c) {
        double b0 = 1 - b1 - b2;
        return b0 * mesh.uv(mesh.triangleVertex(t, 0), c) + b1 * mesh.uv(mesh.triangleVertex(t, 1), c)
                + b2 * mesh.uv(mesh.triangleVertex(t, 2), c);
    }

    /**
     * Surface point of a tessellated hit: the position on the triangle, {@code dp/du} and
     * {@code dp/dv} of the flat triangle from its vertex parameters (pbrt's triangle
     * derivatives), and the unit normal interpolated from the analytic vertex normals (falling
     * back to the geometric normal if the interpolant vanishes).
     */
    void surfacePoint(int t, double b1, double b2, SurfacePoint sp) {
        double b0 = 1 - b1 - b2;
        int i0 = mesh.triangleVertex(t, 0), i1 = mesh.triangleVertex(t, 1), i2 = mesh.triangleVertex(t, 2);
        int o = 9 * t;
        double[] p = corners;
        sp.px = b0 * p[o] + b1 * p[o + 3] + b2 * p[o + 6];
        sp.py = b0 * p[o + 1] + b1 * p[o + 4] + b2 * p[o + 7];
        sp.pz = b0 * p[o + 2] + b1 * p[o + 5] + b2 * p[o + 8];
        // Derivatives of the flat triangle: [e1 e2] = [dpdu dpdv] [du1 du2; dv1 dv2]
        double e1x = p[o + 3] - p[o], e1y = p[o + 4] - p[o + 1], e1z = p[o + 5] - p[o + 2];
        double e2x = p[o + 6] - p[o], e2y = p[o + 7] - p[o + 1], e2z = p[o + 8] - p[o + 2];
        double du1 = mesh.uv(i1, 0) - mesh.uv(i0, 0), dv1 = mesh.uv(i1, 1) - mesh.uv(i0, 1);
        double du2 = mesh.uv(i2, 0) - mesh.uv(i0, 0), dv2 = mesh.uv(i2, 1) - mesh.uv(i0, 1);
        derivatives(sp, e1x, e1y, e1z, e2x, e2y, e2z, du1, dv1, du2, dv2);
        // Shading normal: interpolated analytic vertex normals
        double nx = b0 * mesh.normal(i0, 0) + b1 * mesh.normal(i1, 0) + b2 * mesh.normal(i2, 0);
        double ny = b0 * mesh.normal(i0, 1) + b1 * mesh.normal(i1, 1) + b2 * mesh.normal(i2, 1);
        double nz = b0 * mesh.normal(i0, 2) + b1 * mesh.normal(i1, 2) + b2 * mesh.normal(i2, 2);
        shadingNormal(sp, nx, ny, nz, e1x, e1y, e1z, e2x, e2y, e2z);
    }

    /**
     * The unit shading normal into {@code sp}: the interpolated vertex normal {@code n}, or, where it
     * vanishes (none given, or opposite normals cancelling), the face normal {@code e1 × e2}; +z for a
     * degenerate triangle.
     */
    static void shadingNormal(SurfacePoint sp, double nx, double ny, double nz, double e1x, double e1y, double e1z,
                              double e2x, double e2y, double e2z) {
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 1e-300)) {
            nx = e1y * e2z - e1z * e2y;
            ny = e1z * e2x - e1x * e2z;
            nz = e1x * e2y - e1y * e2x;
            len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        }
        if (len > 0) {
            sp.nx = nx / len; sp.ny = ny / len; sp.nz = nz / len;
        } else {
            sp.nx = 0; sp.ny = 0; sp.nz = 1;
        }
    }

    /**
     * The flat triangle's derivatives into {@code sp}: solves {@code [e1 e2] = [dpdu dpdv] [du1 du2;
     * dv1 dv2]} for the edges {@code e1, e2} and their steps in (u,v); the edges themselves when the
     * (u,v) triangle is degenerate.
     */
    static void derivatives(SurfacePoint sp, double e1x, double e1y, double e1z, double e2x, double e2y,
                            double e2z, double du1, double dv1, double du2, double dv2) {
        double det = du1 * dv2 - dv1 * du2;
        if (det != 0) {
            double inv = 1 / det;
            sp.dpdux = (dv2 * e1x - dv1 * e2x) * inv;
            sp.dpduy = (dv2 * e1y - dv1 * e2y) * inv;
            sp.dpduz = (dv2 * e1z - dv1 * e2z) * inv;
            sp.dpdvx = (du1 * e2x - du2 * e1x) * inv;
            sp.dpdvy = (du1 * e2y - du2 * e1y) * inv;
            sp.dpdvz = (du1 * e2z - du2 * e1z) * inv;
        } else {
            sp.dpdux = e1x; sp.dpduy = e1y; sp.dpduz = e1z;
            sp.dpdvx = e2x; sp.dpdvy = e2y; sp.dpdvz = e2z;
        }
    }
}
