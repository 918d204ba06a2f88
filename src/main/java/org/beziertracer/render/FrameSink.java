package org.beziertracer.render;

/**
 * Receives a render's output; the renderer knows nothing of AWT or Swing.
 *
 * <p><b>Threads:</b> both methods are called from render worker threads (several at once for
 * {@link #tileDone}); an implementation must be thread-safe and return quickly; a Swing sink copies
 * the pixels and marshals to the event thread itself. Calls may still arrive for a generation that
 * was just superseded; compare {@code generation} with the newest one and drop stale calls.
 */
public interface FrameSink {

    /**
     * A finished tile: pixel {@code (x0 + i, y0 + j)} of the image is
     * {@code argb[j * stride + i]}, sRGB-encoded, alpha 255, for {@code 0 ≤ i < w, 0 ≤ j < h}.
     * The array belongs to the worker and is reused after the call returns: copy what you keep.
     */
    void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride);

    /**
     * Pass {@code pass} (0-based) of {@code passCount} is complete for the whole image;
     * {@code stats} counts the rays of this render so far. The last call of a generation has
     * {@code pass == passCount - 1} (a cancelled render never gets it).
     */
    void passDone(int generation, int pass, int passCount, FrameStats stats);

    /**
     * False when the sink ignores {@link #tileDone}: the workers then skip encoding the finished
     * tiles (sRGB and the copy), which only a sink that shows or stores them needs. The final
     * image is in the render's film either way.
     */
    default boolean wantsTiles() { return true; }

    /** A sink that ignores everything (for benchmarks and {@link Renderer#renderOnce}). */
    FrameSink NONE = new FrameSink() {
        @Override
        public void tileDone(int generation, int x0, int y0, int w, int h, int[] argb, int stride) {}

        @Override
        public void passDone(int generation, int pass, int passCount, FrameStats stats) {}

        @Override
        public boolean wantsTiles() { return false; }
    };
}
