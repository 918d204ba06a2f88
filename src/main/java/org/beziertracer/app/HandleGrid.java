package org.beziertracer.app;

import java.util.Arrays;

/**
 * Thins control-point handles by screen-space density: the picture (plus a margin) is cut into
 * square cells about one handle wide, and each cell keeps the one point nearest to the eye (the
 * first offered on a tie). When more cells are occupied than the budget allows, 2×2 cells merge
 * until it fits. Points further apart than a cell's diagonal therefore always keep their own
 * handle: zoomed in far enough, every point is drawn. Memory and the result grow with the
 * picture's area, not with the model. Not thread-safe (one per build).
 */
final class HandleGrid {

    private final double cell;
    private final double margin;
    private final int columns;
    private final int rows;
    private final float[] depth;
    private final float[] xy;
    private final int[] patch;
    private final int[] point;
    private long offered;

    /**
     * @param width  picture width in pixels
     * @param height picture height in pixels
     * @param cell   cell side in pixels (at least 1)
     * @param margin pixels outside the picture whose points still count (half-visible handles)
     */
    HandleGrid(int width, int height, double cell, double margin) {
        this.cell = Math.max(1, cell);
        this.margin = margin;
        columns = (int) Math.ceil((width + 2 * margin) / this.cell);
        rows = (int) Math.ceil((height + 2 * margin) / this.cell);
        int cells = columns * rows;
        depth = new float[cells];
        Arrays.fill(depth, Float.POSITIVE_INFINITY);
        xy = new float[2 * cells];
        patch = new int[cells];
        Arrays.fill(patch, -1);
        point = new int[cells];
    }

    /** Offers point {@code pointIndex} of patch {@code patchIndex} at pixel {@code (x, y)}. */
    void offer(double x, double y, double z, int patchIndex, int pointIndex) {
        int cx = (int) Math.floor((x + margin) / cell), cy = (int) Math.floor((y + margin) / cell);
        if (cx < 0 || cy < 0 || cx >= columns || cy >= rows) {
            return;
        }
        offered++;
        int c = cy * columns + cx;
        if (z < depth[c]) {
            depth[c] = (float) z;
            xy[2 * c] = (float) x;
            xy[2 * c + 1] = (float) y;
            patch[c] = patchIndex;
            point[c] = pointIndex;
        }
    }

    /** Points offered within the picture and margin. */
    long offered() { return offered; }

    /** The kept handles, at most {@code budget} of them, as a {@link Kept}. */
    Kept collect(int budget) {
        int[] cells = occupied(patch);
        float[] d = depth, p2 = xy;
        int[] pa = patch, po = point;
        int cols = columns, rws = rows;
        while (cells.length > budget && (cols > 1 || rws > 1)) {
            // Merge 2×2 cells, keeping the nearest point (the first offered on a tie)
            int nc = (cols + 1) / 2, nr = (rws + 1) / 2;
            float[] d2 = new float[nc * nr];
            Arrays.fill(d2, Float.POSITIVE_INFINITY);
            float[] xy2 = new float[2 * nc * nr];
            int[] pa2 = new int[nc * nr], po2 = new int[nc * nr];
            Arrays.fill(pa2, -1);
            for (int c : cells) {
                int t = (c / cols / 2) * nc + (c % cols) / 2;
                boolean first = pa2[t] < 0 || pa[c] < pa2[t] || (pa[c] == pa2[t] && po[c] < po2[t]);
                if (d[c] < d2[t] || (d[c] == d2[t] && first)) {
                    d2[t] = d[c];
                    xy2[2 * t] = p2[2 * c];
                    xy2[2 * t + 1] = p2[2 * c + 1];
                    pa2[t] = pa[c];
                    po2[t] = po[c];
                }
            }
            d = d2;
            p2 = xy2;
            pa = pa2;
            po = po2;
            cols = nc;
            rws = nr;
            cells = occupied(pa);
        }
        int n = cells.length;
        Kept out = new Kept(new float[2 * n], new float[n], new int[n], new int[n], offered > n);
        for (int k = 0; k < n; k++) {
            int c = cells[k];
            out.xy[2 * k] = p2[2 * c];
            out.xy[2 * k + 1] = p2[2 * c + 1];
            out.depth[k] = d[c];
            out.patch[k] = pa[c];
            out.point[k] = po[c];
        }
        return out;
    }

    private static int[] occupied(int[] patchOfCell) {
        int n = 0;
        for (int p : patchOfCell) {
            n += p >= 0 ? 1 : 0;
        }
        int[] cells = new int[n];
        for (int c = 0, k = 0; c < patchOfCell.length; c++) {
            if (patchOfCell[c] >= 0) {
                cells[k++] = c;
            }
        }
        return cells;
    }

    /** The handles kept: parallel arrays in cell order; {@code thinned} when some offered point was dropped. */
    record Kept(float[] xy, float[] depth, int[] patch, int[] point, boolean thinned) {
        int count() { return depth.length; }
    }
}
