package org.beziertracer.render;

/**
 * A finished render: the linear float film, the statistics of the whole frame and the window of the
 * image that was asked for ({@link RenderJob#window()}; the film may hold a margin around it).
 */
public record RenderResult(Film film, FrameStats stats, PixelWindow window) {

    /** The result of a render of all the film's pixels. */
    public RenderResult(Film film, FrameStats stats) {
        this(film, stats, film.window());
    }

    /** The window as sRGB-encoded opaque ARGB, row-major, {@code window.width()} pixels a row. */
    public int[] argb() { return film.toArgb(window); }
}
