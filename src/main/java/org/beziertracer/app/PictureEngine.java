package org.beziertracer.app;

import java.util.function.Consumer;

/**
 * Turns {@link RenderRequest}s into pictures off the UI thread.
 *
 * <p>{@link #submit} is called on the UI thread and returns at once; requests coalesce (only the
 * newest pending one is rendered) and each new request cancels the render in progress. Status
 * reports arrive on render threads.
 */
public interface PictureEngine extends AutoCloseable {

    void submit(RenderRequest request);

    /** Where status reports go (called from render threads). */
    void onStatus(Consumer<RenderStatus> listener);

    /**
     * Where a failed scene preparation or render is reported, as one line (called off the UI
     * thread). The engine stays usable; the picture keeps its last frame.
     */
    default void onError(Consumer<String> listener) {}

    /** The job of the picture being shown or made, or null (read from any thread). */
    default org.beziertracer.render.RenderJob lastJob() { return null; }

    /**
     * The exposure of the path-traced picture is now {@code stops} (UI thread, returns at once): the
     * picture shown is tone mapped again off the UI thread — the render in progress keeps its samples
     * and goes on — and later renders show this exposure too. Requests made after this call carry
     * the same exposure.
     */
    default void exposure(double stops) {}

    /** True while a render or a pending request is in progress (tests wait on this). */
    boolean busy();

    @Override
    void close();
}
