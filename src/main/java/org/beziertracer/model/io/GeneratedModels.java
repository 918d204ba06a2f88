package org.beziertracer.model.io;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Generated models, the benchmark surfaces of the speed issue (one definition for the CLI, the
 * app and {@code bench/}'s {@code FrameBench}); {@link BuiltIns} offers {@code wavy6},
 * {@code wavy10} and {@code curved}:
 * <ul>
 *   <li>{@link #wavy wavy(N)}, {@code N = 2..16} — one patch of {@code N×N} control points
 *       (degree {@code N−1} in u and v) over the square of {@link Models#flatGrid}, lifted by the
 *       smooth, non-separable height {@link #height}; {@code wavy10} is the largest grid the
 *       toolbox offers (degree 9×9).</li>
 *   <li>{@link #curved()} — one strongly curved bicubic patch: an arch (a half-tube of height 1.5
 *       over {@code x ∈ [-1.5, 1.5]}) running along y, with a twist, seen from the side in the
 *       benchmarks.</li>
 * </ul>
 * Deterministic, stateless and thread-safe.
 */
public final class GeneratedModels {
    private GeneratedModels() {}

    /** The {@code points×points} wavy grid as a scene: {@link #wavyGrid}. */
    public static Scene wavy(int points) {
        return new Scene(List.of(wavyGrid(points)));
    }

    /** The curved bicubic as a scene: {@link #curvedPatch}. */
    public static Scene curved() {
        return new Scene(List.of(curvedPatch()));
    }

    /**
     * The height of the wavy grids at {@code (x, y)}:
     * {@code 0.5 sin(2.6x + 1.2y) cos(1.7y − 0.9x) + 0.25 sin(2xy)}, smooth and not a product
     * of a function of x and a function of y.
     */
    public static double height(double x, double y) {
        return 0.5 * Math.sin(2.6 * x + 1.2 * y) * Math.cos(1.7 * y - 0.9 * x) + 0.25 * Math.sin(2.0 * x * y);
    }

    /**
     * {@link Models#flatGrid flatGrid(points, points)} with every control point lifted to
     * {@code z = height(x, y)}.
     *
     * @param points control points along u and v, 2..16
     */
    public static BezierPatch wavyGrid(int points) {
        BezierPatch flat = Models.flatGrid(points, points);
        double[] net = flat.copyNet();
        for (int k = 0; k < net.length; k += 3) {
            net[k + 2] = height(net[k], net[k + 1]);
        }
        return new BezierPatch(points - 1, points - 1, net);
    }

    /**
     * The curved bicubic: along u the cubic arch {@code (-1.5,0), (-1.5,2), (1.5,2), (1.5,0)} in
     * (x, z), along v the rows at {@code y = -1.5 … 1.5}; row {@code j} is twisted by
     * {@code z += 0.35 (i − 1.5)(j − 1.5)} and its middle points pushed in y by
     * {@code 0.3 (j − 1.5)}, so the surface is curved in both directions.
     */
    public static BezierPatch curvedPatch() {
        double[] ax = {-1.5, -1.5, 1.5, 1.5};
        double[] az = {0, 2, 2, 0};
        double[] net = new double[48];
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                int k = 3 * (4 * j + i);
                net[k] = ax[i];
                net[k + 1] = -1.5 + j + (i == 1 || i == 2 ? 0.3 * (j - 1.5) : 0);
                net[k + 2] = az[i] + 0.35 * (i - 1.5) * (j - 1.5);
            }
        }
        return new BezierPatch(3, 3, net);
    }
}
