package org.beziertracer.spark;

import java.io.Serializable;

/**
 * What a tile task tells the driver: whether it rendered the tile (false: the tile was written already) and,
 * when it did, which executor rendered it, with which evaluation kernel, and how long that executor took to
 * load the job (once per executor JVM; the driver prints one line per executor).
 *
 * @param executor    Spark's executor id ({@code driver} on an embedded {@code local} master)
 * @param kernel      the kernel's description ({@link org.beziertracer.render.JobFrames#kernel}); null when not rendered
 * @param loadSeconds seconds the executor took to read the scene and build the intersector
 */
record TileDone(boolean rendered, String executor, String kernel, double loadSeconds) implements Serializable {
    private static final long serialVersionUID = 1L;

    /** A tile found already written. */
    static TileDone skipped(String executor) {
        return new TileDone(false, executor, null, 0);
    }
}
