package org.beziertracer.render;

import java.util.List;

/**
 * Counts the planned samples of one render as its tiles finish and tells a {@link RenderProgress}.
 * A pass traces {@code sampleTo - sampleFrom} samples at each pixel on its {@code block} grid that
 * is not on its {@code skipGrid}; the total is that sum over all passes and tiles, so the last tile
 * of the last pass brings {@code done} to {@code total} exactly.
 */
final class ProgressCounter {
    private final RenderProgress listener;
    private final int generation;
    private final long total;
    private long done;

    ProgressCounter(RenderProgress listener, int generation, List<PassPlan.Pass> passes, List<int[]> tiles) {
        this.listener = listener;
        this.generation = generation;
        long sum = 0;
        for (PassPlan.Pass pass : passes) {
            for (int[] tile : tiles) {
                sum += samples(pass, tile);
            }
        }
        this.total = sum;
    }

    long total() { return total; }

    /** Called by a worker after it finished {@code tile} (x0, y0, w, h) of {@code pass}. */
    void tileDone(PassPlan.Pass pass, int[] tile) {
        long n = samples(pass, tile);
        if (n == 0 || listener == RenderProgress.NONE) {
            return;
        }
        synchronized (this) {
            done += n;
            listener.progress(generation, done, total);
        }
    }

    /** Samples {@code pass} plans inside {@code tile}. */
    static long samples(PassPlan.Pass pass, int[] tile) {
        long pixels = onGrid(tile, pass.block());
        if (pass.skipGrid() > 0) {
            pixels -= onGrid(tile, pass.skipGrid());
        }
        return pixels * (pass.sampleTo() - pass.sampleFrom());
    }

    /** Pixels of the tile whose x and y are both multiples of {@code grid}. */
    private static long onGrid(int[] tile, int grid) {
        return multiples(tile[0], tile[2], grid) * multiples(tile[1], tile[3], grid);
    }

    /** How many of {@code from, …, from + length - 1} (from ≥ 0) are multiples of {@code grid}. */
    private static long multiples(int from, int length, int grid) {
        return Math.floorDiv(from + length - 1, grid) - Math.floorDiv(from - 1, grid);
    }
}
