package org.beziertracer.render;

/** Blocking one-shot rendering, for the command line and tests. */
public final class Renderer {
    private Renderer() {}

    /**
     * Renders {@code job} on {@code job.options().threads()} new threads and waits for the result.
     * The passes follow {@code job.options().progressive()}; the final image is the same either way.
     */
    public static RenderResult renderOnce(RenderJob job) {
        return renderOnce(job, FrameSink.NONE);
    }

    /** As {@link #renderOnce(RenderJob)}, also feeding {@code sink}. */
    public static RenderResult renderOnce(RenderJob job, FrameSink sink) {
        try (RenderSession session = new RenderSession(job.options().threads(), sink)) {
            return session.render(job);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while rendering", e);
        }
    }
}
