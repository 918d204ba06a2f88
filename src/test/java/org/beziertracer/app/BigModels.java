package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.BezierPatch;

/** Big models made in memory for tests: grids of bicubic patches, gently waved. */
public final class BigModels {
    private BigModels() {}

    /**
     * {@code count} bicubic patches, each one unit square, laid in rows of {@code ⌈√count⌉}; the
     * control points sit at multiples of 1/3 in x and y (shared borders coincide) with
     * {@code z = 0}.
     */
    public static List<BezierPatch> grid(int count) {
        int side = (int) Math.ceil(Math.sqrt(count));
        List<BezierPatch> patches = new ArrayList<>(count);
        for (int k = 0; k < count; k++) {
            int row = k / side, col = k % side;
            double[] net = new double[48];
            for (int j = 0; j < 4; j++) {
                for (int i = 0; i < 4; i++) {
                    int o = 3 * (4 * j + i);
                    net[o] = col + i / 3.0;
                    net[o + 1] = row + j / 3.0;
                }
            }
            patches.add(new BezierPatch(3, 3, net));
        }
        return patches;
    }
}
