package org.beziertracer.app;

/**
 * Points bucketed by their coordinates quantised to cubic cells ({@link WeldIndex}): an
 * open-addressing hash table of cells (linear probing), each holding a chain of point numbers.
 * A cell is known by a 32-bit hash of its integer coordinates only; two cells whose hashes
 * collide share a chain, which costs a few extra comparisons and never a wrong answer, since the
 * caller compares real distances. Memory: two {@code int}s per slot (about three slots per point)
 * and one per point. Not thread-safe (one per build).
 */
final class CellTable {

    /** Returned by {@link #firstNear}/{@link #nextNear} when there is no further cell. */
    static final int END = -1;

    private final double cell;
    private final int[] key;
    private final int[] head;
    private final int[] chain;
    private final int mask;
    // The cells near the last query point, found by firstNear and handed out by nextNear
    private final int[] near = new int[27];
    private int nearCount, nearNext;

    /**
     * @param points how many points will be added (numbered {@code 0..points-1})
     * @param cell   side of a cell, in scene units (positive)
     */
    CellTable(int points, double cell) {
        this.cell = cell;
        int cap = Integer.highestOneBit(Math.max(16, points + points / 2)) << 1;
        key = new int[cap];
        head = new int[cap];
        java.util.Arrays.fill(head, -1);
        chain = new int[points];
        mask = cap - 1;
    }

    /** Adds point {@code g} at {@code (x, y, z)} to its cell. */
    void add(double x, double y, double z, int g) {
        int h = hash(index(x), index(y), index(z));
        int s = slot(h);
        if (head[s] < 0) {
            key[s] = h;
        }
        chain[g] = head[s];
        head[s] = g;
    }

    /**
     * The first existing cell that may hold points within {@code tol} of {@code (x, y, z)}: the
     * point's own cell and, on each axis where the point lies within {@code tol} of a face, the
     * cell beyond it. Then call {@link #nextNear} until {@link #END}.
     */
    int firstNear(double x, double y, double z, double tol) {
        long ix = index(x), iy = index(y), iz = index(z);
        int[] ox = offsets(x, ix, tol), oy = offsets(y, iy, tol), oz = offsets(z, iz, tol);
        nearCount = 0;
        nearNext = 0;
        for (int a : ox) {
            for (int b : oy) {
                for (int c : oz) {
                    int s = find(hash(ix + a, iy + b, iz + c));
                    if (s >= 0 && !seen(s)) {
                        near[nearCount++] = s;
                    }
                }
            }
        }
        return nextNear();
    }

    /** The next cell of the last {@link #firstNear} query, or {@link #END}. */
    int nextNear() {
        return nearNext < nearCount ? near[nearNext++] : END;
    }

    /** First point of the cell in slot {@code s} (-1 when empty). */
    int head(int s) { return head[s]; }

    /** The point after {@code g} in its cell (-1 at the end). */
    int chain(int g) { return chain[g]; }

    private boolean seen(int s) {
        for (int k = 0; k < nearCount; k++) {
            if (near[k] == s) {
                return true;
            }
        }
        return false;
    }

    private static final int[] OWN = {0}, BELOW = {0, -1}, ABOVE = {0, 1}, BOTH = {0, -1, 1};

    /** The cells along one axis that may hold a point within {@code tol}: its own, and a neighbour when near a face. */
    private int[] offsets(double v, long i, double tol) {
        double below = v - i * cell, above = (i + 1) * cell - v;
        boolean lo = below <= tol, hi = above <= tol;
        return lo ? (hi ? BOTH : BELOW) : hi ? ABOVE : OWN;
    }

    private long index(double v) {
        return (long) Math.floor(v / cell);
    }

    private static int hash(long ix, long iy, long iz) {
        long h = ix * 0x9E3779B97F4A7C15L + iy * 0xC2B2AE3D27D4EB4FL + iz * 0x165667B19E3779F9L;
        h ^= h >>> 29;
        h *= 0xBF58476D1CE4E5B9L;
        return (int) (h ^ (h >>> 32));
    }

    /** The slot of the cell hashed {@code h}: where it is, or the empty slot where it goes. */
    private int slot(int h) {
        int s = h & mask;
        while (head[s] >= 0 && key[s] != h) {
            s = (s + 1) & mask;
        }
        return s;
    }

    /** The slot holding the cell hashed {@code h}, or -1. */
    private int find(int h) {
        int s = slot(h);
        return head[s] >= 0 ? s : -1;
    }
}
