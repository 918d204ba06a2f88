package org.beziertracer.intersect;

import java.util.List;

import org.beziertracer.math.HeapBytes;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;

/**
 * Leaves that are the triangles of the scene's meshes ({@link Scene#meshes()}: an OBJ file's
 * polygon faces), met with the watertight test of {@link TriangleMesh}. All meshes are joined into
 * one run of triangles, mesh after mesh; a hit records {@link Hit#TRIANGLE}, the mesh's index, the
 * triangle (in the joined run) and its barycentric weights. Its (u,v) are the mesh's uvs
 * interpolated over the triangle when the mesh has them, else the barycentric weights
 * {@code (b1, b2)}; its normal is the mesh's vertex normals interpolated when it has them, else the
 * face normal (counter-clockwise corners seen from its front).
 *
 * <p>An edit of the scene's patches keeps these leaves as they are. Immutable; shared by render
 * threads, each with its own {@link TraceContext}.
 */
final class MeshLeaves implements FixedLeaves {

    final TriangleMesh triangles;
    private final Mesh[] meshes;
    /** Per mesh its first triangle in the joined run, then the total. */
    private final int[] firstTriangle;

    private MeshLeaves(TriangleMesh triangles, Mesh[] meshes, int[] firstTriangle) {
        this.triangles = triangles;
        this.meshes = meshes;
        this.firstTriangle = firstTriangle;
    }

    /** The triangles of {@code scene}'s meshes; null when it has none. */
    static MeshLeaves build(Scene scene) {
        List<Mesh> list = scene.meshes();
        if (list.isEmpty()) {
            return null;
        }
        int vertices = 0, count = 0;
        int[] first = new int[list.size() + 1];
        for (int k = 0; k < list.size(); k++) {
            first[k] = count;
            vertices += list.get(k).vertexCount();
            count += list.get(k).triangleCount();
        }
        first[list.size()] = count;
        double[] positions = new double[3 * vertices];
        int[] tris = new int[3 * count];
        int[] meshOf = new int[count];
        int v0 = 0;
        for (int k = 0; k < list.size(); k++) {
            Mesh m = list.get(k);
            for (int v = 0; v < m.vertexCount(); v++) {
                for (int c = 0; c < 3; c++) {
                    positions[3 * (v0 + v) + c] = m.position(v, c);
                }
            }
            for (int t = 0; t < m.triangleCount(); t++) {
                int g = first[k] + t;
                meshOf[g] = k;
                for (int c = 0; c < 3; c++) {
                    tris[3 * g + c] = v0 + m.triangleVertex(t, c);
                }
            }
            v0 += m.vertexCount();
        }
        TriangleMesh joined = TriangleMesh.of(new Mesh(positions, new double[0], new double[0], tris, meshOf));
        return new MeshLeaves(joined, list.toArray(new Mesh[0]), first);
    }

    /** About the heap {@link #build} holds for {@code triangles} triangles over {@code vertices} vertices. */
    static long estimateBytes(long vertices, long triangles) {
        return 2 * (vertices * 3 * 8 + triangles * 4 * 4) + triangles * (9 * 8 + 6 * 8 + 4);
    }

    @Override
    public void beginRay(TraceContext ctx) {
        TriangleMesh.setRay(ctx);
    }

    @Override
    public double intersect(TraceContext ctx, int t, double tMax) {
        if (!triangles.intersect(ctx, t, ctx.tMin, tMax)) {
            return tMax;
        }
        ctx.recordHit(Hit.TRIANGLE, triangles.patchOf[t], t);
        ctx.best.b1 = ctx.rootB1;
        ctx.best.b2 = ctx.rootB2;
        return ctx.rootT;
    }

    @Override
    public boolean occludes(TraceContext ctx, int t, double tMax) {
        return triangles.intersect(ctx, t, ctx.tMin, tMax);
    }

    /** (u,v): the mesh's uvs interpolated over the triangle, else the barycentric weights. */
    @Override
    public void completeHit(Hit hit) {
        Mesh m = meshes[hit.index];
        if (!m.hasUvs()) {
            hit.u = hit.b1;
            hit.v = hit.b2;
            return;
        }
        int t = hit.subPatch - firstTriangle[hit.index];
        double b0 = 1 - hit.b1 - hit.b2;
        int i0 = m.triangleVertex(t, 0), i1 = m.triangleVertex(t, 1), i2 = m.triangleVertex(t, 2);
        hit.u = b0 * m.uv(i0, 0) + hit.b1 * m.uv(i1, 0) + hit.b2 * m.uv(i2, 0);
        hit.v = b0 * m.uv(i0, 1) + hit.b1 * m.uv(i1, 1) + hit.b2 * m.uv(i2, 1);
    }

    /**
     * The point on the triangle; dp/du and dp/dv of the flat triangle from its uvs (its edges
     * without uvs, or when they are degenerate); the vertex normals interpolated, or the face normal.
     */
    @Override
    public void surfacePoint(TraceContext ctx, Hit hit, SurfacePoint sp) {
        int g = hit.subPatch;
        Mesh m = meshes[hit.index];
        int t = g - firstTriangle[hit.index];
        double b1 = hit.b1, b2 = hit.b2, b0 = 1 - b1 - b2;
        double[] p = triangles.corners;
        int o = 9 * g;
        sp.px = b0 * p[o] + b1 * p[o + 3] + b2 * p[o + 6];
        sp.py = b0 * p[o + 1] + b1 * p[o + 4] + b2 * p[o + 7];
        sp.pz = b0 * p[o + 2] + b1 * p[o + 5] + b2 * p[o + 8];
        double e1x = p[o + 3] - p[o], e1y = p[o + 4] - p[o + 1], e1z = p[o + 5] - p[o + 2];
        double e2x = p[o + 6] - p[o], e2y = p[o + 7] - p[o + 1], e2z = p[o + 8] - p[o + 2];
        int i0 = m.triangleVertex(t, 0), i1 = m.triangleVertex(t, 1), i2 = m.triangleVertex(t, 2);
        double du1 = 0, dv1 = 0, du2 = 0, dv2 = 0; // without uvs: a degenerate (u,v) triangle, the edges
        if (m.hasUvs()) {
            du1 = m.uv(i1, 0) - m.uv(i0, 0);
            dv1 = m.uv(i1, 1) - m.uv(i0, 1);
            du2 = m.uv(i2, 0) - m.uv(i0, 0);
            dv2 = m.uv(i2, 1) - m.uv(i0, 1);
        }
        TriangleMesh.derivatives(sp, e1x, e1y, e1z, e2x, e2y, e2z, du1, dv1, du2, dv2);
        double nx = 0, ny = 0, nz = 0; // without vertex normals: the face normal
        if (m.hasNormals()) {
            nx = b0 * m.normal(i0, 0) + b1 * m.normal(i1, 0) + b2 * m.normal(i2, 0);
            ny = b0 * m.normal(i0, 1) + b1 * m.normal(i1, 1) + b2 * m.normal(i2, 1);
            nz = b0 * m.normal(i0, 2) + b1 * m.normal(i1, 2) + b2 * m.normal(i2, 2);
        }
        TriangleMesh.shadingNormal(sp, nx, ny, nz, e1x, e1y, e1z, e2x, e2y, e2z);
    }

    @Override
    public long bytes() {
        return triangles.bytes() + HeapBytes.of(firstTriangle);
    }

    @Override
    public int count() { return triangles.count; }

    @Override
    public double[] bounds(int first, int n) {
        return java.util.Arrays.copyOfRange(triangles.bounds, 6 * first, 6 * (first + n));
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

    @Override
    public int triangleCount() { return triangles.count; }
}
