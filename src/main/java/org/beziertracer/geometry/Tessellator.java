package org.beziertracer.geometry;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;

/**
 * Uniform tessellation of Bézier patches into a {@link Mesh}, for export and previews (the
 * renderer itself never triangulates).
 *
 * <p>Each patch gets its own {@code (k+1)×(k+1)} grid of vertices at parameters
 * {@code (a/k, b/k)}, vertex {@code b·(k+1) + a} of the patch (u fastest), with positions from
 * {@link DeCasteljau#evaluate} ({@link RationalDeCasteljau#evaluate} for a rational patch), analytic
 * unit normals from {@link PatchNormals#unitNormal} (including the limit normal at collapsed
 * edges) and the patch's own parameters (in {@code [0,1]²}) as uvs. Trim loops are not applied
 * here: the mesh covers the whole patch. Each grid cell
 * gives two triangles, {@code (a,b),(a+1,b),(a+1,b+1)} and {@code (a,b),(a+1,b+1),(a,b+1)}, so
 * triangles wind counter-clockwise around {@code ∂S/∂u × ∂S/∂v}. Vertices are not shared
 * between patches, and cells at a collapsed edge yield zero-area triangles which are kept so
 * that every patch has exactly {@code 2k²} triangles, in cell order.
 *
 * <p>Stateless and thread-safe.
 */
public final class Tessellator {

    /** Largest accepted number of cells per patch side. */
    public static final int MAX_SEGMENTS = 1024;

    private Tessellator() {}

    /** Tessellates one patch with {@code k×k} cells. */
    public static Mesh tessellate(BezierPatch patch, int k) {
        return tessellate(List.of(patch), k);
    }

    /**
     * Tessellates every patch with {@code k×k} cells; triangles of patch {@code p} (its index in
     * the list) are tagged {@code p} in {@link Mesh#patchOfTriangle}.
     *
     * @throws IllegalArgumentException when {@code k} is not in {@code 1..}{@value #MAX_SEGMENTS}
     *                                  or the list is empty
     */
    public static Mesh tessellate(List<BezierPatch> patches, int k) {
        if (k < 1 || k > MAX_SEGMENTS) {
            throw new IllegalArgumentException("segments per patch side must be 1.." + MAX_SEGMENTS + ", got " + k);
        }
        if (patches.isEmpty()) {
            throw new IllegalArgumentException("nothing to tessellate: no patches");
        }
        if (3L * patches.size() * 2L * k * k > Integer.MAX_VALUE) {
            throw new IllegalArgumentException(patches.size() + " patches of " + k + "x" + k + " cells make "
                    + 2L * k * k * patches.size() + " triangles, more than a mesh can index");
        }
        int perPatchVertices = (k + 1) * (k + 1), perPatchTriangles = 2 * k * k;
        int vertexCount = patches.size() * perPatchVertices;
        double[] positions = new double[3 * vertexCount], normals = new double[3 * vertexCount];
        double[] uvs = new double[2 * vertexCount];
        int[] triangles = new int[3 * patches.size() * perPatchTriangles];
        int[] patchOf = new int[patches.size() * perPatchTriangles];
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int tri = 0;
        for (int p = 0; p < patches.size(); p++) {
            BezierPatch patch = patches.get(p);
            double[] net = Patches.workingNet(patch);
            int n = patch.degreeU(), m = patch.degreeV(), dim = Patches.dim(patch);
            int base = p * perPatchVertices;
            // Vertices
            for (int b = 0; b <= k; b++) {
                double v = (double) b / k;
                for (int a = 0; a <= k; a++) {
                    double u = (double) a / k;
                    int vert = base + b * (k + 1) + a;
                    if (dim == 4) {
                        RationalDeCasteljau.evaluate(net, 0, n, m, u, v, positions, 3 * vert, scratch);
                    } else {
                        DeCasteljau.evaluate(net, 0, n, m, 3, u, v, positions, 3 * vert, scratch);
                    }
                    PatchNormals.unitNormal(net, 0, n, m, dim, u, v, normals, 3 * vert, scratch);
                    uvs[2 * vert] = u;
                    uvs[2 * vert + 1] = v;
                }
            }
            // Two triangles per cell
            for (int b = 0; b < k; b++) {
                for (int a = 0; a < k; a++) {
                    int v00 = base + b * (k + 1) + a, v10 = v00 + 1, v01 = v00 + k + 1, v11 = v01 + 1;
                    tri = putTriangle(triangles, patchOf, tri, p, v00, v10, v11);
                    tri = putTriangle(triangles, patchOf, tri, p, v00, v11, v01);
                }
            }
        }
        return new Mesh(positions, normals, uvs, triangles, patchOf);
    }

    private static int putTriangle(int[] triangles, int[] patchOf, int t, int patch, int a, int b, int c) {
        triangles[3 * t] = a;
        triangles[3 * t + 1] = b;
        triangles[3 * t + 2] = c;
        patchOf[t] = patch;
        return t + 1;
    }
}
