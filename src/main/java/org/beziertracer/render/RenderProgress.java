package org.beziertracer.render;

/**
 * Hears how far a render has got, for a progress bar: {@code done} of {@code total} planned
 * samples. The plan counts every sample of every pass; an adaptive pass counts the samples it may
 * trace (all pixels), and a tile counts as done when it is finished.
 *
 * <p><b>Threads:</b> called from render worker threads, one call at a time (the session
 * serialises them), once per finished tile; it must return quickly. Within a generation
 * {@code done} strictly increases and a render that completes ends with {@code done == total};
 * a cancelled or failed one stops short.
 */
@FunctionalInterface
public interface RenderProgress {

    /** {@code done} of {@code total} samples of render {@code generation} are traced (0 &lt; done ≤ total). */
    void progress(int generation, long done, long total);

    /** A listener that ignores everything. */
    RenderProgress NONE = (generation, done, total) -> { };
}
