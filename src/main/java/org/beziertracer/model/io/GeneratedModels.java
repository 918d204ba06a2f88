package org.beziertracer.model.io;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Generated built-in models, the benchmark surfaces of the speed issue (one definition for the
 * CLI, the app and {@code bench/}'s {@code FrameBench}):
 * <ul>
 *   <li>{@code wavyN}, {@code N = 2..16} — one patch of {@code N×N} control points (degree
 *       {@code N−1} in u and v) over the square of {@link Models#flatGrid}, lifted by the smooth,
 *       non-separable height {@link #height}; {@code wavy10} is the largest grid the toolbox
 *       offers (degree 9×9), {@code wavy4} a bicubic.</li>
 *   <li>{@code curved} — one strongly curved bicubic patch: an arch (a half-tube of height 1.5
 *       over {@code x ∈ [-1.5, 1.5]}) running along y, with a twist, seen from the side in the
 *       benchmarks.</li>
 * </ul>
 * Deterministic, stateless and thread-safe.
 */
public final class GeneratedModels {
    private GeneratedModels() {}

    /** Prefix of the wavy grids' names. */
    public static final String WAVY = "wavy";
    /** Name of the curved bicubic patch. */
    public static final String CURVED = "curved";

    /**
     * The model called {@code name} ({@code wavy2} … {@code wavy16}, {@code curved};
     * lower case), or null when {@code name} is none of them.
     */
    static Scene builtIn(String name) {
        if (name.equals(CURVED)) {
            return new Scene(List.of(curvedPatch()));
        }
        if (name.startsWith(WAVY) && name.length() > WAVY.length() && name.length() <= WAVY.length() + 2
                && name.substring(WAVY.length()).chars().allMatch(Character::isDigit)) {
            int points = Integer.parseInt(name.substring(WAVY.length()));
            if (points >= 2 && points <= BezierPatch.MAX_DEGREE + 1) {
                return new Scene(List.of(wavyGrid(points)));
            }
        }
        return null;
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
