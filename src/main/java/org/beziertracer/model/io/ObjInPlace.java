package org.beziertracer.model.io;

import java.util.Arrays;

/**
 * What {@link ObjReader} reads without making strings: the statements that fill big models —
 * {@code v x y z}, {@code surf} with plain indices, {@code f} with {@code v}, {@code v/vt},
 * {@code v//vn} or {@code v/vt/vn} corners, {@code vt} and {@code vn} — parsed from the line's
 * characters where they lie ({@link TextSource#nextLine()}), and the fields of short statements
 * that come again and again ({@code deg 3 3}, {@code end}) split once. Each reader hands the
 * values to the same state the string path fills ({@link ObjVertices}, {@link ObjFreeForm#plainSurf},
 * {@link ObjFaces#plainFace}) or, when a statement is in any other form or would be an error,
 * returns false having changed nothing, and the string path reads or reports it: the model is
 * the same to the bit either way ({@code ObjInPlaceTest}). Counts what it read, for the tests
 * that pin the work. One parse; not thread-safe.
 */
final class ObjInPlace {
    private final ObjVertices vertices;
    private final ObjFreeForm freeForm;
    private final ObjFaces faces;
    private final ReadLimits limits;
    /** The numbers of the vertex (texture vertex, normal) being read. */
    private final double[] xyz = new double[3];
    /** How many vertices, surfs and faces (with texture vertices and normals) were read here. */
    int vertexCount, surfCount, faceCount;

    ObjInPlace(ObjVertices vertices, ObjFreeForm freeForm, ObjFaces faces, ReadLimits limits) {
        this.vertices = vertices;
        this.freeForm = freeForm;
        this.faces = faces;
        this.limits = limits;
    }

    /**
     * Reads the one-line statement {@code a[from..to)} (no leading or trailing blanks, no comment)
     * of line {@code line} when it is one of the kinds read here; false, having changed nothing,
     * otherwise.
     */
    boolean statement(char[] a, int from, int to, int line) {
        return vertex(a, from, to) || surf(a, from, to, line) || face(a, from, to, line)
                || textureOrNormal(a, from, to);
    }

    /**
     * Reads {@code v x y z} (three finite decimals, no weight) from {@code a[from..to)}, a
     * statement without leading or trailing blanks: most lines of a big model are such
     * vertices. Returns false, having read nothing, for anything else, which the general path
     * then reads or reports.
     */
    boolean vertex(char[] a, int from, int to) {
        if (to - from < 7 || a[from] != 'v' || !Fields.separator(a[from + 1]) || freeForm.skipping()
                || vertices.count() >= limits.vertices() || decimals(a, from + 1, to, 3) != 3) {
            return false;
        }
        vertices.add(xyz[0], xyz[1], xyz[2], 1);
        vertexCount++;
        return true;
    }

    /**
     * Reads {@code vt u [v [w]]} and {@code vn x y z} of plain decimals in place, as
     * {@link ObjFaces#plainTextureVertex} and {@link ObjFaces#plainNormal} can; false, having
     * read nothing, for anything else.
     */
    private boolean textureOrNormal(char[] a, int from, int to) {
        if (to - from < 4 || a[from] != 'v' || !Fields.separator(a[from + 2]) || freeForm.skipping()) {
            return false;
        }
        if (a[from + 1] == 't') {
            int n = decimals(a, from + 2, to, 3);
            return n >= 1 && faces.plainTextureVertex(xyz[0], n > 1 ? xyz[1] : 0) && countFaceItem();
        }
        return a[from + 1] == 'n' && decimals(a, from + 2, to, 3) == 3
                && faces.plainNormal(xyz[0], xyz[1], xyz[2]) && countFaceItem();
    }

    private boolean countFaceItem() {
        faceCount++;
        return true;
    }

    /**
     * The fields of {@code a[i..to)} as finite plain decimals into {@link #xyz}: how many, or -1
     * when a field is not a finite decimal or there are more than {@code max}.
     */
    private int decimals(char[] a, int i, int to, int max) {
        int n = 0;
        for (;;) {
            while (i < to && Fields.separator(a[i])) {
                i++;
            }
            if (i == to) {
                return n;
            }
            int start = i;
            while (i < to && !Fields.separator(a[i])) {
                i++;
            }
            double x = NumberText.finiteOrNaN(a, start, i);
            if (n == max || Double.isNaN(x)) {
                return -1;
            }
            xyz[n++] = x;
        }
    }

    /** The corners of the face {@link #face} reads, 0-based: vertex, texture vertex and normal (-1: none). */
    private int[] faceV = new int[8], faceVt = new int[8], faceVn = new int[8];

    /**
     * Reads {@code f c1 c2 c3 …} whose corners are {@code v}, {@code v/vt}, {@code v//vn} or
     * {@code v/vt/vn} of plain whole numbers in range, from {@code a[from..to)} (a statement
     * without leading or trailing blanks) in place, as {@link ObjFaces#plainFace} can; false,
     * having read nothing, for anything else, which the string path reads or reports.
     */
    private boolean face(char[] a, int from, int to, int line) {
        if (to - from < 7 || a[from] != 'f' || !Fields.separator(a[from + 1]) || freeForm.skipping()) {
            return false;
        }
        int n = 0;
        for (int i = from + 1; ; ) {
            while (i < to && Fields.separator(a[i])) {
                i++;
            }
            if (i == to) {
                break;
            }
            int start = i;
            while (i < to && !Fields.separator(a[i])) {
                i++;
            }
            if (n == faceV.length) {
                faceV = Arrays.copyOf(faceV, 2 * n);
                faceVt = Arrays.copyOf(faceVt, 2 * n);
                faceVn = Arrays.copyOf(faceVn, 2 * n);
            }
            if (!corner(a, start, i, n++)) {
                return false;
            }
        }
        if (!faces.plainFace(faceV, faceVt, faceVn, n, line)) {
            return false;
        }
        faceCount++;
        return true;
    }

    /** One corner {@code a[from..to)} into {@code faceV/Vt/Vn[k]}; false when it is not plain and in range. */
    private boolean corner(char[] a, int from, int to, int k) {
        int slash1 = from;
        while (slash1 < to && a[slash1] != '/') {
            slash1++;
        }
        faceV[k] = ObjVertices.resolve(NumberText.wholeOrMin(a, from, slash1), vertices.count());
        faceVt[k] = -1;
        faceVn[k] = -1;
        if (faceV[k] < 0) {
            return false;
        }
        if (slash1 == to) {
            return true; // v
        }
        int slash2 = slash1 + 1;
        while (slash2 < to && a[slash2] != '/') {
            slash2++;
        }
        if (slash2 > slash1 + 1) { // v/vt or v/vt/vn
            faceVt[k] = ObjVertices.resolve(NumberText.wholeOrMin(a, slash1 + 1, slash2), faces.uvCount());
            if (faceVt[k] < 0) {
                return false;
            }
        }
        if (slash2 == to) {
            return slash2 > slash1 + 1; // v/vt (v/ is malformed)
        }
        faceVn[k] = ObjVertices.resolve(NumberText.wholeOrMin(a, slash2 + 1, to), faces.normalCount());
        return faceVn[k] >= 0; // a third slash makes the number malformed
    }

    /** The fields of the statement {@link #surf} reads: {@code a[fieldStart[k]..fieldEnd[k])}. */
    private int[] fieldStart = new int[32], fieldEnd = new int[32];

    /**
     * Reads {@code surf s0 s1 t0 t1 i1 i2 …} of plain numbers from {@code a[from..to)} (a
     * statement without leading or trailing blanks) in place, as {@link ObjFreeForm#plainSurf}
     * can; false, having read nothing, for anything else.
     */
    private boolean surf(char[] a, int from, int to, int line) {
        if (to - from < 5 || a[from] != 's' || a[from + 1] != 'u' || a[from + 2] != 'r' || a[from + 3] != 'f'
                || !Fields.separator(a[from + 4])) {
            return false;
        }
        int fields = 0;
        for (int i = from; i < to; ) {
            if (fields == fieldStart.length) {
                fieldStart = Arrays.copyOf(fieldStart, 2 * fields);
                fieldEnd = Arrays.copyOf(fieldEnd, 2 * fields);
            }
            fieldStart[fields] = i;
            while (i < to && !Fields.separator(a[i])) {
                i++;
            }
            fieldEnd[fields++] = i;
            while (i < to && Fields.separator(a[i])) {
                i++;
            }
        }
        if (!freeForm.plainSurf(a, fieldStart, fieldEnd, fields, line)) {
            return false;
        }
        surfCount++;
        return true;
    }

    /**
     * Short statements split lately, and their fields, one slot for each value of a first
     * character's low three bits: {@code deg 3 3} and {@code end} come again and again.
     */
    private final char[][] recentText = new char[8][32];
    private final int[] recentLength = {-1, -1, -1, -1, -1, -1, -1, -1};
    private final String[][] recentFields = new String[8][];

    /**
     * {@link Fields#of} of {@code a[from..to)}; a short statement equal to a recent one gets
     * the same fields again (no handler changes its fields) instead of new strings.
     */
    String[] fields(char[] a, int from, int to) {
        int n = to - from, slot = a[from] & 7;
        if (n == recentLength[slot] && Arrays.equals(a, from, to, recentText[slot], 0, n)) {
            return recentFields[slot];
        }
        String[] fields = Fields.of(new String(a, from, n));
        if (n <= recentText[slot].length) {
            System.arraycopy(a, from, recentText[slot], 0, n);
            recentLength[slot] = n;
            recentFields[slot] = fields;
        }
        return fields;
    }
}
