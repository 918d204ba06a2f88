package org.beziertracer.model.io;

import java.util.Arrays;

/**
 * The control points a writer has numbered, so that a point two patches share is written once and
 * named twice (an OBJ {@code v} line each, as the modelling tools that made the file wrote it).
 * Points are the same when their coordinates and weight have the same bits ({@code 0.0} and
 * {@code -0.0} stay apart, so a read gives back the exact values). Open addressing over flat
 * arrays: 40 bytes a point, no object each.
 */
final class SharedVertices {
    private long[] bits = new long[4 * 256];
    private int[] slots = new int[1024]; // 0: empty, else the point's 1-based number
    private int count;

    /** How many points are numbered. */
    int count() { return count; }

    /**
     * The 1-based number of point {@code (x, y, z, w)}: positive when it was numbered before,
     * negative ({@code −number}) when this call numbered it, so the caller writes it.
     */
    int intern(double x, double y, double z, double w) {
        long bx = Double.doubleToRawLongBits(x), by = Double.doubleToRawLongBits(y);
        long bz = Double.doubleToRawLongBits(z), bw = Double.doubleToRawLongBits(w);
        int mask = slots.length - 1;
        for (int s = hash(bx, by, bz, bw) & mask; ; s = (s + 1) & mask) {
            int number = slots[s];
            if (number == 0) {
                if (4 * (count + 1) > bits.length) {
                    bits = Arrays.copyOf(bits, 2 * bits.length);
                }
                int k = 4 * count;
                bits[k] = bx;
                bits[k + 1] = by;
                bits[k + 2] = bz;
                bits[k + 3] = bw;
                count++;
                slots[s] = count;
                if (2 * count > slots.length) {
                    grow();
                }
                return -count;
            }
            int k = 4 * (number - 1);
            if (bits[k] == bx && bits[k + 1] == by && bits[k + 2] == bz && bits[k + 3] == bw) {
                return number;
            }
        }
    }

    private void grow() {
        slots = new int[2 * slots.length];
        int mask = slots.length - 1;
        for (int number = 1; number <= count; number++) {
            int k = 4 * (number - 1);
            int s = hash(bits[k], bits[k + 1], bits[k + 2], bits[k + 3]) & mask;
            while (slots[s] != 0) {
                s = (s + 1) & mask;
            }
            slots[s] = number;
        }
    }

    private static int hash(long x, long y, long z, long w) {
        long h = x * 0x9E3779B97F4A7C15L;
        h = (h ^ (h >>> 29) ^ y) * 0xBF58476D1CE4E5B9L;
        h = (h ^ (h >>> 31) ^ z) * 0x94D049BB133111EBL;
        h = (h ^ (h >>> 29) ^ w) * 0x9E3779B97F4A7C15L;
        return (int) (h ^ (h >>> 32));
    }
}
