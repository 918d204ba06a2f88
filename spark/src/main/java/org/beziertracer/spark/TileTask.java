package org.beziertracer.spark;

import java.io.Serializable;
import java.util.Locale;

/**
 * One unit of work of a job on Spark: tile {@code i} of {@code n} (bands of rows,
 * {@link org.beziertracer.render.PixelWindow#tile}) of one frame.
 *
 * @param frame the frame number
 * @param i     the tile, 1..n
 * @param n     tiles per frame
 */
public record TileTask(int frame, int i, int n) implements Serializable {
    private static final long serialVersionUID = 1L;

    /** The tile's file name under the output's {@code tiles/} folder: job, frame and tile. */
    public String fileName(String job) {
        return String.format(Locale.ROOT, "%s-f%06d-t%04dof%04d.tile", job, frame, i, n);
    }
}
