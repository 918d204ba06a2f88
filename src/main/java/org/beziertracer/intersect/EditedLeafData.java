package org.beziertracer.intersect;

import java.util.Arrays;
import java.util.stream.IntStream;

import org.beziertracer.geometry.SubPatchTable;

/**
 * Per-leaf data of a table after an edit ({@link SubPatchTable#withPatches}): the records of the
 * patches the edit did not touch are the same leaves' records, shifted to their new place; only
 * the edited patches' leaves are computed. A drag on one patch of the teapot recomputes its 200-odd
 * leaves' {@link NewtonLeafRecords}, not all 6,468.
 */
final class EditedLeafData {
    private EditedLeafData() {}

    /** Computes the data of leaves {@code from .. to-1} of {@code table} into {@code out}. */
    @FunctionalInterface
    interface RangeFill {
        void fill(SubPatchTable table, float[] out, int from, int to);
    }

    /**
     * The data of {@code after}'s leaves, {@code stride} floats a leaf: copied from {@code old} (the
     * data of {@code before}) for every patch not in {@code edited}, filled by {@code fill} for the
     * edited ones. {@code after} differs from {@code before} only in the patches {@code edited}.
     */
    static float[] of(float[] old, SubPatchTable before, SubPatchTable after, int[] edited, int stride, RangeFill fill) {
        float[] out = new float[stride * after.count];
        int[] sorted = Arrays.stream(edited).distinct().sorted().toArray();
        int patch = 0;
        for (int k : sorted) {
            copy(old, before, after, patch, k, stride, out);
            fillParallel(after, out, after.firstOf[k], after.firstOf[k + 1], fill);
            patch = k + 1;
        }
        copy(old, before, after, patch, after.patchCount(), stride, out);
        return out;
    }

    /**
     * The data of every leaf of {@code table}, {@code stride} floats a leaf, filled by {@code fill}
     * in runs of {@link #BUILD_CHUNK} leaves on the common pool when there are several (a build).
     */
    static float[] built(SubPatchTable table, int stride, RangeFill fill) {
        float[] out = new float[stride * table.count];
        int chunks = (table.count + BUILD_CHUNK - 1) / BUILD_CHUNK;
        IntStream range = IntStream.range(0, chunks);
        (chunks > 1 ? range.parallel() : range).forEach(c -> fill.fill(table, out, c * BUILD_CHUNK,
                Math.min(table.count, (c + 1) * BUILD_CHUNK)));
        return out;
    }

    /** Leaves a task of {@link #built} fills. */
    static final int BUILD_CHUNK = 4096;

    /** Leaves a task fills: a degree-9 patch's 550 leaves take about a millisecond on one core. */
    static final int CHUNK = 128;

    /** {@code fill} over leaves {@code from .. to-1}, in chunks of {@link #CHUNK} on the common pool when there are several. */
    private static void fillParallel(SubPatchTable table, float[] out, int from, int to, RangeFill fill) {
        int chunks = (to - from + CHUNK - 1) / CHUNK;
        if (chunks <= 1) {
            fill.fill(table, out, from, to);
        } else {
            IntStream.range(0, chunks).parallel().forEach(c -> fill.fill(table, out, from + c * CHUNK,
                    Math.min(to, from + (c + 1) * CHUNK)));
        }
    }

    /** Copies the data of patches {@code from .. to-1}, unchanged by the edit, to their place in {@code after}. */
    private static void copy(float[] old, SubPatchTable before, SubPatchTable after, int from, int to, int stride,
                             float[] out) {
        int a = before.firstOf[from], n = before.firstOf[to] - a;
        System.arraycopy(old, stride * a, out, stride * after.firstOf[from], stride * n);
    }
}
