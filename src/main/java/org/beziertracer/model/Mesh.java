package org.beziertracer.model;

import java.util.Arrays;

import org.beziertracer.math.Aabb;

/**
 * An immutable indexed triangle mesh, e.g. a tessellation of Bézier patches for export.
 *
 * <h2>Layout</h2>
 * All arrays are flat:
 * <ul>
 *   <li>{@code positions}: {@code 3·vertexCount} doubles, {@code x,y,z} of vertex {@code k} at
 *       {@code 3k, 3k+1, 3k+2};</li>
 *   <li>{@code normals}: {@code 3·vertexCount} doubles, the unit normal of vertex {@code k}
 *       at the same indices;</li>
 *   <li>{@code uvs}: {@code 2·vertexCount} doubles, the patch parameters {@code u,v} of vertex
 *       {@code k} at {@code 2k, 2k+1} (parameters within the vertex's own patch);</li>
 *   <li>{@code triangles}: {@code 3·triangleCount} zero-based vertex indices, counter-clockwise
 *       seen from the side the vertex normals point to;</li>
 *   <li>{@code patchOfTriangle}: {@code triangleCount} indices of the source patch of each
 *       triangle.</li>
 * </ul>
 * A mesh read from polygon faces ({@link #faces}) may have no normals (then the face normal
 * shades it) or no uvs: the array is then empty ({@link #hasNormals()}, {@link #hasUvs()}), and
 * every triangle's "patch" is 0.
 *
 * <p>The constructor copies every array and the accessors return copies, so instances are
 * immutable and safe to share between threads. For loops over large meshes use the indexed
 * getters, which do not copy.
 */
public final class Mesh {

    private final double[] positions;
    private final double[] normals;
    private final double[] uvs;
    private final int[] triangles;
    private final int[] patchOfTriangle;

    /**
     * @throws IllegalArgumentException when the array lengths disagree with each other, a
     *                                  coordinate is not finite or a vertex index is out of range
     */
    public Mesh(double[] positions, double[] normals, double[] uvs, int[] triangles, int[] patchOfTriangle) {
        if (positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions length must be a multiple of 3, got " + positions.length);
        }
        int vertexCount = positions.length / 3;
        if (normals.length != 3 * vertexCount && normals.length != 0
                || uvs.length != 2 * vertexCount && uvs.length != 0) {
            throw new IllegalArgumentException("for " + vertexCount + " vertices expected " + 3 * vertexCount
                    + " normal and " + 2 * vertexCount + " uv values, got " + normals.length + " and " + uvs.length);
        }
        if (triangles.length % 3 != 0 || patchOfTriangle.length != triangles.length / 3) {
            throw new IllegalArgumentException("triangles length " + triangles.length
                    + " must be 3 x patchOfTriangle length " + patchOfTriangle.length);
        }
        checkFinite("positions", positions);
        checkFinite("normals", normals);
        checkFinite("uvs", uvs);
        for (int k = 0; k < triangles.length; k++) {
            if (triangles[k] < 0 || triangles[k] >= vertexCount) {
                throw new IllegalArgumentException("triangle " + k / 3 + " refers to vertex " + triangles[k]
                        + " of " + vertexCount);
            }
        }
        this.positions = positions.clone();
        this.normals = normals.clone();
        this.uvs = uvs.clone();
        this.triangles = triangles.clone();
        this.patchOfTriangle = patchOfTriangle.clone();
    }

    /**
     * A mesh of polygon faces already cut into triangles: vertex positions, optional unit normals
     * and uvs ({@code null} when the faces give none), and the triangles' vertex indices.
     *
     * @throws IllegalArgumentException as the constructor
     */
    public static Mesh faces(double[] positions, double[] normals, double[] uvs, int[] triangles) {
        return new Mesh(positions, normals == null ? new double[0] : normals, uvs == null ? new double[0] : uvs,
                triangles, new int[triangles.length / 3]);
    }

    /** True when every vertex has a normal ({@link #normal}); false for faces that gave none. */
    public boolean hasNormals() { return normals.length > 0 || positions.length == 0; }

    /** True when every vertex has (u,v) ({@link #uv}); false for faces that gave none. */
    public boolean hasUvs() { return uvs.length > 0 || positions.length == 0; }

    /** The box of the vertex positions ({@link Aabb#EMPTY} without vertices). */
    public Aabb bounds() {
        if (positions.length == 0) {
            return Aabb.EMPTY;
        }
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int k = 0; k < positions.length; k += 3) {
            for (int c = 0; c < 3; c++) {
                lo[c] = Math.min(lo[c], positions[k + c]);
                hi[c] = Math.max(hi[c], positions[k + c]);
            }
        }
        return new Aabb(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    }

    private static void checkFinite(String what, double[] a) {
        for (int k = 0; k < a.length; k++) {
            if (!Double.isFinite(a[k])) {
                throw new IllegalArgumentException(what + "[" + k + "] is not finite: " + a[k]);
            }
        }
    }

    public int vertexCount() { return positions.length / 3; }

    public int triangleCount() { return patchOfTriangle.length; }

    /** Coordinate {@code c} (0..2) of the position of vertex {@code k}. */
    public double position(int k, int c) { return positions[3 * k + c]; }

    /** Coordinate {@code c} (0..2) of the unit normal of vertex {@code k}. */
    public double normal(int k, int c) { return normals[3 * k + c]; }

    /** Parameter {@code c} (0 = u, 1 = v) of vertex {@code k}. */
    public double uv(int k, int c) { return uvs[2 * k + c]; }

    /** Vertex index {@code corner} (0..2) of triangle {@code t}. */
    public int triangleVertex(int t, int corner) { return triangles[3 * t + corner]; }

    /** Source patch of triangle {@code t}. */
    public int patchOfTriangle(int t) { return patchOfTriangle[t]; }

    /** Copies of the flat arrays (layout in the class comment). */
    public double[] positions() { return positions.clone(); }

    public double[] normals() { return normals.clone(); }

    public double[] uvs() { return uvs.clone(); }

    public int[] triangles() { return triangles.clone(); }

    public int[] patchOfTriangle() { return patchOfTriangle.clone(); }

    @Override
    public boolean equals(Object o) {
        return o instanceof Mesh x && Arrays.equals(x.positions, positions) && Arrays.equals(x.normals, normals)
                && Arrays.equals(x.uvs, uvs) && Arrays.equals(x.triangles, triangles)
                && Arrays.equals(x.patchOfTriangle, patchOfTriangle);
    }

    @Override
    public int hashCode() { return 31 * Arrays.hashCode(positions) + Arrays.hashCode(triangles); }

    @Override
    public String toString() { return "Mesh[" + vertexCount() + " vertices, " + triangleCount() + " triangles]"; }
}
