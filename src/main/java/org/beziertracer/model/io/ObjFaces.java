package org.beziertracer.model.io;

import java.util.Arrays;

import org.beziertracer.model.Mesh;

/**
 * The polygon statements of one OBJ parse ({@link ObjReader} hands them over): {@code vt u [v [w]]}
 * texture coordinates, {@code vn x y z} normals and {@code f} faces whose corners are {@code v},
 * {@code v/vt}, {@code v//vn} or {@code v/vt/vn} references (1-based, or negative counting back from
 * the last one defined so far). A face of n ≥ 3 corners is cut into the fan of triangles
 * {@code (1, k, k+1)}, keeping its winding. Every distinct corner (v, vt, vn) becomes one vertex of
 * the {@link Mesh}; the mesh has uvs when every corner gave a {@code vt}, and normals (made unit)
 * when every corner gave a {@code vn}, else none (then the face normal shades it).
 *
 * <p>Errors are one-line {@link ModelFormatException}s naming the file and the statement's line:
 * fewer than 3 corners, a malformed reference, an index out of range, a coordinate that is not a
 * finite number, more items than {@link ReadLimits#vertices()}.
 */
final class ObjFaces {

    private String file;
    private final ReadLimits limits;
    private double[] uvs = new double[2 * 16];
    private int uvCount;
    private double[] normals = new double[3 * 16];
    private int normalCount;
    /** Per mesh vertex its corner: v, vt, vn (-1 when not given). */
    private int[] corners = new int[3 * 64];
    private int vertexCount;
    private int[] triangles = new int[3 * 64];
    private int triangleCount;
    /** The mesh vertices of the corners with a vt or a vn, hashed by corner ({@link #mapped}); -1 for free slots. */
    private int[] table = new int[0];
    private int mappedCount;
    /** Per vertex v the mesh vertex of the corner that names only v, or -1. */
    private int[] plainIndex = new int[0];
    private boolean allUvs = true, allNormals = true;
    private int line;

    ObjFaces(String file, ReadLimits limits) {
        this.file = file;
        this.limits = limits;
    }

    /** Errors from now on name {@code name} (the file a {@code call} reads, then the caller again). */
    void file(String name) {
        this.file = name;
    }

    /** True when at least one face was read. */
    boolean any() { return triangleCount > 0; }

    /** {@code vt u [v [w]]}. */
    void textureVertex(String[] t, int lineNumber) {
        line = lineNumber;
        if (t.length < 2 || t.length > 4) {
            throw error("expected 1 to 3 texture coordinates after vt (u, v and w), found " + (t.length - 1) + " values");
        }
        if (uvCount >= limits.vertices()) {
            throw error("a file may have at most " + limits.vertices() + " texture vertices (vt); this is one more");
        }
        int number = uvCount + 1;
        double u = NumberText.parseFinite(t[1], "u of texture vertex " + number, file, line);
        double v = t.length > 2 ? NumberText.parseFinite(t[2], "v of texture vertex " + number, file, line) : 0;
        if (t.length > 3) {
            NumberText.parseFinite(t[3], "w of texture vertex " + number, file, line);
        }
        addUv(u, v);
    }

    /** {@code vn x y z}. */
    void normal(String[] t, int lineNumber) {
        line = lineNumber;
        if (t.length != 4) {
            throw error("expected 3 coordinates after vn, found " + (t.length - 1) + " values");
        }
        if (normalCount >= limits.vertices()) {
            throw error("a file may have at most " + limits.vertices() + " normals (vn); this is one more");
        }
        int number = normalCount + 1;
        double[] xyz = new double[3];
        for (int c = 0; c < 3; c++) {
            xyz[c] = NumberText.parseFinite(t[c + 1], "the " + "xyz".charAt(c) + " coordinate of normal " + number,
                    file, line);
        }
        addNormal(xyz[0], xyz[1], xyz[2]);
    }

    /** {@code f c1 c2 c3 …}: a polygon over the {@code defined} vertices read so far, cut into a fan. */
    void face(String[] t, int lineNumber, int defined) {
        line = lineNumber;
        int n = t.length - 1;
        if (n < 3) {
            throw error("expected at least 3 vertex references after " + t[0] + " (a polygon), found " + n);
        }
        if ((long) triangleCount + n - 2 > limits.vertices()) {
            throw error("a file may have at most " + limits.vertices() + " triangles of faces; this face makes more");
        }
        int[] c = cornerScratch(n);
        for (int k = 0; k < n; k++) {
            c[k] = corner(t[k + 1], k + 1, defined);
        }
        fan(c, n);
    }

    /**
     * {@link #face} of corners read in place ({@link ObjReader}) and already resolved to 0-based
     * indices: vertex {@code v[k]}, texture vertex {@code vt[k]} and normal {@code vn[k]} (-1 where
     * the corner names none) for {@code k < n}. False, having changed nothing, when the string path
     * would report a problem.
     */
    boolean plainFace(int[] v, int[] vt, int[] vn, int n, int lineNumber) {
        if (n < 3 || (long) triangleCount + n - 2 > limits.vertices()) {
            return false;
        }
        line = lineNumber;
        int[] c = cornerScratch(n);
        for (int k = 0; k < n; k++) {
            allUvs &= vt[k] >= 0;
            allNormals &= vn[k] >= 0;
            c[k] = vt[k] < 0 && vn[k] < 0 ? plainCorner(v[k]) : mapped(v[k], vt[k], vn[k]);
        }
        fan(c, n);
        return true;
    }

    /** How many texture vertices ({@code vt}) and normals ({@code vn}) are defined so far. */
    int uvCount() { return uvCount; }

    int normalCount() { return normalCount; }

    /**
     * {@link #textureVertex} of {@code vt u v} read in place ({@code v} = 0 for {@code vt u}); false,
     * having changed nothing, at the cap (the string path reports it).
     */
    boolean plainTextureVertex(double u, double v) {
        if (uvCount >= limits.vertices()) {
            return false;
        }
        addUv(u, v);
        return true;
    }

    /** {@link #normal} of {@code vn x y z} read in place; false, having changed nothing, at the cap. */
    boolean plainNormal(double x, double y, double z) {
        if (normalCount >= limits.vertices()) {
            return false;
        }
        addNormal(x, y, z);
        return true;
    }

    private void addUv(double u, double v) {
        if (2 * uvCount + 2 > uvs.length) {
            uvs = Arrays.copyOf(uvs, 2 * uvs.length);
        }
        uvs[2 * uvCount] = u;
        uvs[2 * uvCount + 1] = v;
        uvCount++;
    }

    private void addNormal(double x, double y, double z) {
        if (3 * normalCount + 3 > normals.length) {
            normals = Arrays.copyOf(normals, 2 * normals.length);
        }
        normals[3 * normalCount] = x;
        normals[3 * normalCount + 1] = y;
        normals[3 * normalCount + 2] = z;
        normalCount++;
    }

    /** The mesh vertices of one face's corners. */
    private int[] cornerScratch = new int[8];

    private int[] cornerScratch(int n) {
        if (n > cornerScratch.length) {
            cornerScratch = new int[Math.max(n, 2 * cornerScratch.length)];
        }
        return cornerScratch;
    }

    /** The triangles {@code (c0, c[k-1], c[k])} of a polygon of {@code n} mesh vertices, keeping its winding. */
    private void fan(int[] c, int n) {
        for (int k = 2; k < n; k++) {
            if (3 * triangleCount + 3 > triangles.length) {
                triangles = Arrays.copyOf(triangles, 2 * triangles.length);
            }
            triangles[3 * triangleCount] = c[0];
            triangles[3 * triangleCount + 1] = c[k - 1];
            triangles[3 * triangleCount + 2] = c[k];
            triangleCount++;
        }
    }

    /** The mesh vertex of one face corner. */
    private int corner(String token, int position, int defined) {
        String[] parts = token.split("/", -1);
        if (parts.length > 3 || parts[0].isEmpty() || parts.length == 3 && parts[2].isEmpty()
                || parts.length == 2 && parts[1].isEmpty()) {
            throw error("expected a vertex reference (v, v/vt, v//vn or v/vt/vn) for corner " + position
                    + " of the face, found " + NumberText.describe(token));
        }
        int v = reference(parts[0], token, position, defined, "vertex", "v");
        int vt = parts.length > 1 && !parts[1].isEmpty()
                ? reference(parts[1], token, position, uvCount, "texture vertex", "vt") : -1;
        int vn = parts.length > 2 ? reference(parts[2], token, position, normalCount, "normal", "vn") : -1;
        allUvs &= vt >= 0;
        allNormals &= vn >= 0;
        return vt < 0 && vn < 0 ? plainCorner(v) : mapped(v, vt, vn);
    }

    /**
     * The mesh vertex of the corner (v, vt, vn) with a vt or a vn: looked up in {@link #table}, an
     * open-addressing hash table (linear probing) of mesh vertices keyed by their corner in
     * {@link #corners}, kept at most half full; a new one when the corner is new.
     */
    private int mapped(int v, int vt, int vn) {
        if (2 * (mappedCount + 1) > table.length) {
            rehash(Math.max(64, 2 * table.length));
        }
        int mask = table.length - 1;
        for (int slot = hash(v, vt, vn) & mask; ; slot = (slot + 1) & mask) {
            int k = table[slot];
            if (k < 0) {
                table[slot] = vertexCount;
                mappedCount++;
                return newVertex(v, vt, vn);
            }
            if (corners[3 * k] == v && corners[3 * k + 1] == vt && corners[3 * k + 2] == vn) {
                return k;
            }
        }
    }

    private static int hash(int v, int vt, int vn) {
        int h = (v * 0x9E3779B1 + vt) * 0x9E3779B1 + vn;
        return h ^ (h >>> 15);
    }

    private void rehash(int size) {
        int[] old = table;
        table = new int[size];
        Arrays.fill(table, -1);
        int mask = size - 1;
        for (int k : old) {
            if (k >= 0) {
                int slot = hash(corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]) & mask;
                while (table[slot] >= 0) {
                    slot = (slot + 1) & mask;
                }
                table[slot] = k;
            }
        }
    }

    /**
     * The mesh vertex of a corner that names only vertex {@code v}: found in an array by {@code v}
     * rather than hashed (most meshes' corners are such; a corner with a vt or vn is another
     * vertex and goes through the map).
     */
    private int plainCorner(int v) {
        if (v >= plainIndex.length) {
            int old = plainIndex.length;
            plainIndex = Arrays.copyOf(plainIndex, Math.max(v + 1, 2 * old));
            Arrays.fill(plainIndex, old, plainIndex.length, -1);
        }
        int known = plainIndex[v];
        if (known >= 0) {
            return known;
        }
        plainIndex[v] = vertexCount;
        return newVertex(v, -1, -1);
    }

    /** A new mesh vertex for the corner (v, vt, vn); its index. */
    private int newVertex(int v, int vt, int vn) {
        if (3 * vertexCount + 3 > corners.length) {
            corners = Arrays.copyOf(corners, 2 * corners.length);
        }
        corners[3 * vertexCount] = v;
        corners[3 * vertexCount + 1] = vt;
        corners[3 * vertexCount + 2] = vn;
        return vertexCount++;
    }

    private int reference(String text, String token, int position, int defined, String what, String keyword) {
        if (!NumberText.isWhole(text)) {
            throw error("expected a " + what + " index for corner " + position + " of the face, found "
                    + NumberText.describe(token));
        }
        if (defined == 0) {
            throw error("expected a " + what + " index for corner " + position + " of the face, found "
                    + NumberText.describe(token) + " but no " + what + " (" + keyword + ") is defined before this line");
        }
        int i = ObjVertices.resolve(NumberText.parseWhole(text), defined);
        if (i < 0) {
            throw error("expected a " + what + " index for corner " + position + " of the face in 1.." + defined
                    + " or -" + defined + "..-1, found " + NumberText.describe(token) + ": index out of range");
        }
        return i;
    }

    /** The faces read, as one mesh over {@code vertices}; null when there were none. */
    Mesh mesh(ObjVertices vertices) {
        if (triangleCount == 0) {
            return null;
        }
        double[] positions = new double[3 * vertexCount];
        double[] uv = allUvs ? new double[2 * vertexCount] : null;
        double[] nrm = allNormals ? new double[3 * vertexCount] : null;
        for (int k = 0; k < vertexCount; k++) {
            int v = corners[3 * k], vt = corners[3 * k + 1], vn = corners[3 * k + 2];
            for (int c = 0; c < 3; c++) {
                positions[3 * k + c] = vertices.vertex(v, c);
            }
            if (uv != null) {
                uv[2 * k] = uvs[2 * vt];
                uv[2 * k + 1] = uvs[2 * vt + 1];
            }
            if (nrm != null) {
                double x = normals[3 * vn], y = normals[3 * vn + 1], z = normals[3 * vn + 2];
                double len = Math.sqrt(x * x + y * y + z * z);
                double s = len > 0 && Double.isFinite(len) ? 1 / len : 0;
                nrm[3 * k] = x * s;
                nrm[3 * k + 1] = y * s;
                nrm[3 * k + 2] = z * s;
            }
        }
        return Mesh.faces(positions, nrm, uv, Arrays.copyOf(triangles, 3 * triangleCount));
    }

    private ModelFormatException error(String detail) {
        return new ModelFormatException(file, line, detail);
    }
}
