package org.beziertracer.model.io;

import java.util.Arrays;

/**
 * The vertex tables of one OBJ parse: geometric vertices {@code v x y z [w]} and parameter-space
 * vertices {@code vp u v [w]} (weights default to 1), and the resolution of their references
 * (1-based, or negative counting back from the last one defined so far). Never pre-allocated
 * from counts in the file. Geometric vertices are kept in blocks of {@value #BLOCK} that are never
 * copied (a model of a million vertices would otherwise copy its table twenty times over, 60 MB
 * of garbage at its end); parameter vertices, which are few, in one array grown by doubling.
 */
final class ObjVertices {
    /** Vertices a block holds: a power of two, {@code 4·BLOCK} doubles (256 KB) a block. */
    static final int BLOCK = 1 << 13;
    private static final int SHIFT = Integer.numberOfTrailingZeros(BLOCK);
    private double[][] blocks = new double[8][];
    private int count;
    private double[] uvw = new double[3 * 16];
    private int paramCount;

    void add(double x, double y, double z, double w) {
        int b = count >>> SHIFT;
        if (b == blocks.length) {
            blocks = Arrays.copyOf(blocks, 2 * b);
        }
        double[] xyzw = blocks[b];
        if (xyzw == null) { // the first block grows from small: a file of a few vertices needs no 256 KB
            xyzw = blocks[b] = new double[b == 0 ? 4 * 64 : 4 * BLOCK];
        } else if (b == 0 && 4 * count + 4 > xyzw.length) {
            xyzw = blocks[0] = Arrays.copyOf(xyzw, Math.min(2 * xyzw.length, 4 * BLOCK));
        }
        int k = 4 * (count++ & (BLOCK - 1));
        xyzw[k] = x;
        xyzw[k + 1] = y;
        xyzw[k + 2] = z;
        xyzw[k + 3] = w;
    }

    void addParam(double u, double v, double w) {
        if (3 * paramCount + 3 > uvw.length) {
            uvw = Arrays.copyOf(uvw, uvw.length * 2);
        }
        int k = 3 * paramCount++;
        uvw[k] = u;
        uvw[k + 1] = v;
        uvw[k + 2] = w;
    }

    int count() { return count; }

    int paramCount() { return paramCount; }

    /** Coordinate {@code c} (0..2 = x, y, z; 3 = weight) of 0-based vertex {@code index}. */
    double vertex(int index, int c) { return blocks[index >>> SHIFT][4 * (index & (BLOCK - 1)) + c]; }

    /** Coordinate {@code c} (0..1 = u, v; 2 = weight) of 0-based parameter vertex {@code index}. */
    double param(int index, int c) { return uvw[3 * index + c]; }

    /**
     * The 0-based index of a reference to one of {@code defined} items: {@code 1..defined}, or
     * {@code -defined..-1} counting back; -1 when out of range.
     */
    static int resolve(long reference, int defined) {
        if (reference >= 1 && reference <= defined) {
            return (int) reference - 1;
        }
        if (reference <= -1 && reference >= -defined) {
            return (int) (defined + reference);
        }
        return -1;
    }
}
