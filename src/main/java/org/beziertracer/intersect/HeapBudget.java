package org.beziertracer.intersect;

import org.beziertracer.accel.Bvh;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.HeapRoom;
import org.beziertracer.model.Scene;

/**
 * Refuses work that would not fit in the heap before it allocates, in one line that says what,
 * how much and what to do: {@code big.obj: 600000 patches need about 12 GB of heap; this JVM
 * allows 1 GB (run java -Xmx16g …)}. The estimates live beside the data they measure
 * ({@link SubPatchTable#estimateBytes}, {@link Bvh#estimateBytes}, {@link TriangleMesh#estimateBytes}, and
 * each method's leaves, {@link Method#solverBytes});
 * this class adds them up for a build and compares with what the JVM can still give.
 *
 * <p>{@link SceneIntersector#build} checks every build; the command line and the app check first
 * with the file's name, so the message names it. Stateless and thread-safe.
 */
public final class HeapBudget {
    private HeapBudget() {}

    private static final long MB = 1L << 20;
    private static final long GB = 1L << 30;

    /** {@link HeapRoom#GC_HEADROOM}. */
    static final double GC_HEADROOM = HeapRoom.GC_HEADROOM;

    /** About the most heap {@link SceneIntersector#build} holds at once for {@code scene}, in bytes. */
    public static long estimateBytes(Scene scene, IntersectOptions options) {
        long vertices = 0, triangles = 0;
        for (var mesh : scene.meshes()) {
            vertices += mesh.vertexCount();
            triangles += mesh.triangleCount();
        }
        long others = triangles + scene.spheres().size();
        long meshes = triangles == 0 ? 0 : MeshLeaves.estimateBytes(vertices, triangles) + 6 * 8 * others
                + Bvh.estimateBytes(others);
        return patchBytes(scene, options) + meshes;
    }

    /** {@link #estimateBytes} of the patches' leaves alone. */
    private static long patchBytes(Scene scene, IntersectOptions options) {
        var patches = scene.patches();
        if (options.tessellated()) {
            long triangles = 2L * options.tessellate() * options.tessellate() * patches.size();
            return TriangleMesh.estimateBytes(patches.size(), options.tessellate()) + 6 * 8 * triangles
                    + Bvh.estimateBytes(triangles);
        }
        SubPatchTable.Estimate table = SubPatchTable.estimate(patches, options.effectiveSplit());
        long solverBytes = options.method().solverBytes(patches, table.leaves());
        // The table, the leaves' boxes handed to the BVH build, the build itself and the method's per-leaf data
        return table.bytes() + 6 * 8 * table.leaves() + Bvh.estimateBytes(table.leaves()) + solverBytes;
    }

    /**
     * Throws when building {@code scene} with {@code options} would not fit in the heap.
     *
     * @param source the file or built-in name the message starts with, or null for none
     * @throws IllegalArgumentException one line: what, about how much, the JVM's limit, the fix
     */
    public static void require(String source, Scene scene, IntersectOptions options) {
        int n = scene.patchCount();
        String what = n + (n == 1 ? " patch" : " patches") + (options.tessellated() ? " tessellated "
                + options.tessellate() + "x" + options.tessellate() + " (" + 2L * options.tessellate()
                * options.tessellate() * n + " triangles)" : "");
        require(source, what, estimateBytes(scene, options));
    }

    /**
     * Throws when {@code estimate} bytes more (and {@link #GC_HEADROOM}) would not fit in the
     * heap, even after a collection.
     *
     * @param source null, or the name the message starts with
     * @param what   what needs the memory, the subject of "need about …" ({@code 32 patches})
     */
    public static void require(String source, String what, long estimate) {
        String shortfall = HeapRoom.shortfall(what, estimate);
        if (shortfall != null) {
            throw new IllegalArgumentException((source == null ? "" : source + ": ") + shortfall);
        }
    }

    /** The message for an {@link OutOfMemoryError} that escaped every estimate. */
    public static String outOfMemory() {
        return outOfMemory(0);
    }

    /**
     * The message for an {@link OutOfMemoryError} while working on input that needs at least
     * {@code estimate} bytes ({@code model.io.HeapEstimates}; 0 when unknown): the suggested heap
     * is twice this JVM's, or the estimate when that is more.
     */
    public static String outOfMemory(long estimate) {
        long max = Runtime.getRuntime().maxMemory();
        return "out of memory: " + limit(max, 0, Math.max(max, (long) (estimate * HeapRoom.GC_HEADROOM)));
    }

    /** {@link HeapRoom#limit}. */
    static String limit(long max, long used, long bytes) {
        return HeapRoom.limit(max, used, bytes);
    }

    /** {@link HeapRoom#suggestion}. */
    static String suggestion(long bytes) {
        return HeapRoom.suggestion(bytes);
    }

    /** {@link HeapRoom#size}. */
    static String size(long bytes) {
        return HeapRoom.size(bytes);
    }
}
