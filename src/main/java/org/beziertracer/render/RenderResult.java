package org.beziertracer.render;

/** A finished render: the linear float film and the statistics of the whole frame. */
public record RenderResult(Film film, FrameStats stats) {

    /** The image as sRGB-encoded opaque ARGB, row-major. */
    public int[] argb() { return film.toArgb(); }
}
