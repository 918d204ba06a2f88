package org.beziertracer.model;

import java.util.Locale;

/**
 * How much heap this JVM can still give, and the words for "this will not fit": {@code this JVM
 * allows 1 GB (run java -Xmx16g …)}. Shared by the readers ({@code model.io}, which refuse a
 * file from its header or size before parsing it) and {@code intersect.HeapBudget} (which refuses
 * a build), so both speak alike. Stateless and thread-safe.
 */
public final class HeapRoom {
    private HeapRoom() {}

    private static final long MB = 1L << 20;
    private static final long GB = 1L << 30;

    /**
     * Room the collector needs beyond the live data: measured with G1 (JDK 17) on the teapot
     * tessellated 100×100, 200 degree-15 patches and 20,000 bicubic patches, the smallest
     * {@code -Xmx} that built was 1.0–1.1 × (estimate + heap in use before).
     */
    public static final double GC_HEADROOM = 1.1;

    /**
     * Null when {@code estimate} bytes more (and {@link #GC_HEADROOM}) fit in the heap, even after
     * a collection; else {@code WHAT need about 6 GB of heap; this JVM allows 64 MB (run java
     * -Xmx8g …)}.
     *
     * @param what what needs the memory, the subject of "need about …" ({@code 32 patches})
     */
    public static String shortfall(String what, long estimate) {
        long bytes = (long) (estimate * GC_HEADROOM);
        Runtime rt = Runtime.getRuntime();
        if (bytes <= rt.maxMemory() - used(rt)) {
            return null;
        }
        System.gc(); // garbage counts as used until collected; refuse only what truly does not fit
        long used = used(rt);
        if (bytes <= rt.maxMemory() - used) {
            return null;
        }
        return what + " need about " + size(bytes) + " of heap; " + limit(rt.maxMemory(), used, bytes);
    }

    /** {@code this JVM allows 1 GB (run java -Xmx16g …)}, naming the memory in use when it matters. */
    public static String limit(long max, long used, long bytes) {
        String inUse = used > max / 4 ? ", " + size(used) + " of it in use" : "";
        return "this JVM allows " + size(max) + inUse + " (run java -Xmx" + suggestion(used + bytes) + " …)";
    }

    /** A heap size with room to spare: 1.25 × {@code bytes}, rounded up to a power of two. */
    public static String suggestion(long bytes) {
        long mb = Math.max(64, Long.highestOneBit((long) (bytes * 1.25 / MB)) << 1);
        return mb >= 1024 ? mb / 1024 + "g" : mb + "m";
    }

    /** {@code 640 MB}, {@code 3.2 GB}, {@code 12 GB}. */
    public static String size(long bytes) {
        if (bytes >= 10 * GB) {
            return Math.round((double) bytes / GB) + " GB";
        }
        if (bytes >= GB) {
            return String.format(Locale.ROOT, "%.1f GB", (double) bytes / GB).replace(".0 ", " ");
        }
        return Math.max(1, Math.round((double) bytes / MB)) + " MB";
    }

    /** Heap in use now (garbage included until collected). */
    public static long used() {
        return used(Runtime.getRuntime());
    }

    private static long used(Runtime rt) {
        return rt.totalMemory() - rt.freeMemory();
    }
}
