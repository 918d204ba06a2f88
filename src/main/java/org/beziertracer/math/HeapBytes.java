package org.beziertracer.math;

/**
 * Heap bytes of arrays as a 64-bit HotSpot JVM with compressed class pointers lays them out: a
 * 16-byte header, then the elements, rounded up to 8 bytes. Used by the data structures that
 * report what they hold ({@code bytes()}), not for allocation decisions. Stateless.
 */
public final class HeapBytes {
    private HeapBytes() {}

    /** Array header (mark word, class pointer, length, padding). */
    public static final long ARRAY_HEADER = 16;

    /** Bytes of an array of {@code length} elements of {@code elementBytes} each. */
    public static long array(long length, int elementBytes) {
        return (ARRAY_HEADER + length * elementBytes + 7) & ~7L;
    }

    /** Bytes of {@code a}, 0 for null. */
    public static long of(double[] a) { return a == null ? 0 : array(a.length, 8); }

    /** Bytes of {@code a}, 0 for null. */
    public static long of(float[] a) { return a == null ? 0 : array(a.length, 4); }

    /** Bytes of {@code a}, 0 for null. */
    public static long of(int[] a) { return a == null ? 0 : array(a.length, 4); }

    /** Bytes of {@code a}, 0 for null. */
    public static long of(byte[] a) { return a == null ? 0 : array(a.length, 1); }

    /** Bytes of {@code a}, 0 for null. */
    public static long of(boolean[] a) { return a == null ? 0 : array(a.length, 1); }
}
