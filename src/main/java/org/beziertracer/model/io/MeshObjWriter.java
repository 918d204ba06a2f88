package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Path;

/**
 * Writes a triangle mesh (for example a tessellated Bézier scene) as a plain Wavefront OBJ
 * polygon file that any 3D tool can import: {@code v x y z}, {@code vt u v}, {@code vn x y z}
 * per vertex, then {@code f a/a/a b/b/b c/c/c} per triangle with 1-based indices (the same index
 * for position, texture coordinate and normal, as the arrays are per vertex). A big mesh can be
 * streamed in pieces ({@link #header}, then {@link #writePiece} per piece): each piece's vertices
 * then come just before its faces.
 *
 * <h2>Array layout</h2>
 * <ul>
 *   <li>{@code positions}: {@code x,y,z} per vertex, {@code 3·vertexCount} doubles;</li>
 *   <li>{@code normals}: {@code x,y,z} per vertex, same vertex count, or null (then faces are
 *       written {@code a/a} or {@code a});</li>
 *   <li>{@code uvs}: {@code u,v} per vertex, or null (then faces are {@code a//a} or {@code a});</li>
 *   <li>{@code triangles}: three 0-based vertex indices per triangle.</li>
 * </ul>
 * The arrays are only read. Numbers use the shortest round-trip text. Stateless and thread-safe.
 */
public final class MeshObjWriter {
    private MeshObjWriter() {}

    /** Writes the mesh to {@code file} atomically (see {@link AtomicFiles}). */
    public static void write(Path file, double[] positions, double[] normals, double[] uvs, int[] triangles)
            throws IOException {
        AtomicFiles.write(file, out -> write(out, positions, normals, uvs, triangles));
    }

    /**
     * Writes the mesh to {@code out} (not closed).
     *
     * @throws IllegalArgumentException when the array lengths disagree or an index is out of range
     */
    public static void write(Writer out, double[] positions, double[] normals, double[] uvs, int[] triangles)
            throws IOException {
        checkLayout(positions, normals, uvs, triangles);
        header(out, positions.length / 3, triangles.length / 3);
        piece(out, positions, normals, uvs, triangles, 0);
        out.flush();
    }

    /**
     * The first line of a mesh written piece by piece ({@link #writePiece}): how many vertices and
     * triangles all the pieces hold.
     */
    public static void header(Writer out, long vertexCount, long triangleCount) throws IOException {
        out.write("# Bézier Tracer mesh: " + vertexCount + " vertices, " + triangleCount + " triangles\n");
    }

    /**
     * Writes one piece of a mesh streamed piece by piece (a patch's tessellation): its {@code v},
     * {@code vt} and {@code vn} lines, then its faces, whose indices follow the {@code firstVertex}
     * vertices the pieces before it wrote. OBJ indices count every vertex written so far, so the
     * pieces together read as one mesh; only one piece need be in memory.
     *
     * @throws IllegalArgumentException when the array lengths disagree or an index is out of range
     */
    public static void writePiece(Writer out, double[] positions, double[] normals, double[] uvs, int[] triangles,
                                  long firstVertex) throws IOException {
        checkLayout(positions, normals, uvs, triangles);
        piece(out, positions, normals, uvs, triangles, firstVertex);
    }

    private static void piece(Writer out, double[] positions, double[] normals, double[] uvs, int[] triangles,
                              long firstVertex) throws IOException {
        int vertexCount = positions.length / 3;
        StringBuilder sb = new StringBuilder(128);
        for (int v = 0; v < vertexCount; v++) {
            sb.setLength(0);
            triple(sb.append("v "), positions, 3 * v);
            out.write(sb.toString());
        }
        if (uvs != null) {
            for (int v = 0; v < vertexCount; v++) {
                sb.setLength(0);
                sb.append("vt ").append(NumberText.format(uvs[2 * v])).append(' ')
                        .append(NumberText.format(uvs[2 * v + 1])).append('\n');
                out.write(sb.toString());
            }
        }
        if (normals != null) {
            for (int v = 0; v < vertexCount; v++) {
                sb.setLength(0);
                triple(sb.append("vn "), normals, 3 * v);
                out.write(sb.toString());
            }
        }
        writeFaces(out, sb, triangles, firstVertex, uvs != null, normals != null);
    }

    /** Checks the arrays' layout before anything is written. */
    private static void checkLayout(double[] positions, double[] normals, double[] uvs, int[] triangles) {
        if (positions == null || positions.length % 3 != 0) {
            throw new IllegalArgumentException("positions must hold x,y,z per vertex, got "
                    + (positions == null ? "null" : positions.length + " doubles"));
        }
        int vertexCount = positions.length / 3;
        if (normals != null && normals.length != 3 * vertexCount) {
            throw new IllegalArgumentException("normals must hold x,y,z for each of the " + vertexCount
                    + " vertices, got " + normals.length + " doubles");
        }
        if (uvs != null && uvs.length != 2 * vertexCount) {
            throw new IllegalArgumentException("uvs must hold u,v for each of the " + vertexCount
                    + " vertices, got " + uvs.length + " doubles");
        }
        if (triangles == null || triangles.length % 3 != 0) {
            throw new IllegalArgumentException("triangles must hold 3 vertex indices each, got "
                    + (triangles == null ? "null" : triangles.length + " ints"));
        }
        for (int k = 0; k < triangles.length; k++) {
            if (triangles[k] < 0 || triangles[k] >= vertexCount) {
                throw new IllegalArgumentException("triangle " + k / 3 + " refers to vertex " + triangles[k]
                        + ", outside 0.." + (vertexCount - 1));
            }
        }
    }

    /** The faces, {@code f a/a/a b/b/b c/c/c} with the texture and normal indices that exist. */
    private static void writeFaces(Writer out, StringBuilder sb, int[] triangles, long firstVertex, boolean uvs,
                                   boolean normals) throws IOException {
        for (int t = 0; t < triangles.length; t += 3) {
            sb.setLength(0);
            sb.append('f');
            for (int c = 0; c < 3; c++) {
                long index = firstVertex + triangles[t + c] + 1;
                sb.append(' ').append(index);
                if (uvs || normals) {
                    sb.append('/');
                    if (uvs) {
                        sb.append(index);
                    }
                    if (normals) {
                        sb.append('/').append(index);
                    }
                }
            }
            out.write(sb.append('\n').toString());
        }
    }

    private static void triple(StringBuilder sb, double[] a, int k) {
        sb.append(NumberText.format(a[k])).append(' ').append(NumberText.format(a[k + 1])).append(' ')
                .append(NumberText.format(a[k + 2])).append('\n');
    }
}
