package org.beziertracer.model.io;

import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The models built in code, and loading a model by name or path.
 *
 * <ul>
 *   <li>{@link #patch()} — the default bicubic patch (the "reset" model): {@link #flatGrid(int, int)
 *       flatGrid(4, 4)}, a flat square of 4×4 control points at
 *       {@code x, y ∈ {-1.5, -0.5, 0.5, 1.5}}, {@code z = 0}.</li>
 *   <li>{@link #teapot()} — the 32-patch Utah teapot as built into Sunflow (z-up, bounding box
 *       {@code x[-120,141] y[-80,80] z[0,120]}), the built-in {@code teapot} of {@link BuiltIns};
 *       see {@code shared/models/README.md} for its provenance.</li>
 *   <li>{@link #sphere()}, {@link #torus()}, {@link #trimmedPlate()} — the rational B-spline and
 *       trimmed built-ins ({@link BuiltInSurfaces}); the teacup and the teaspoon are resources of
 *       {@link BuiltIns}.</li>
 * </ul>
 * The list of built-in names is {@link BuiltIns}; file formats are {@link FileFormats}.
 * Stateless and thread-safe.
 */
public final class Models {
    private Models() {}

    /** Half the side of the square spanned by {@link #flatGrid(int, int)}. */
    public static final double GRID_HALF_SIZE = 1.5;

    /** The default bicubic patch: {@code flatGrid(4, 4)}. */
    public static Scene patch() {
        return new Scene(List.of(flatGrid(4, 4)));
    }
    /**
     * A flat patch of {@code pointsU × pointsV} control points (degree {@code points − 1} in each
     * direction), evenly spaced over the square {@code [-1.5, 1.5]²} in the plane {@code z = 0}:
     * {@code P_ij = (-1.5 + 3i/(pointsU−1), -1.5 + 3j/(pointsV−1), 0)}. The square stays the same
     * size whatever the point count; u runs along +x, v along +y, so dS/du × dS/dv points to +z.
     *
     * @param pointsU control points along u, 2..16
     * @param pointsV control points along v, 2..16
     */
    public static BezierPatch flatGrid(int pointsU, int pointsV) {
        checkPoints("u", pointsU);
        checkPoints("v", pointsV);
        double[] net = new double[pointsU * pointsV * 3];
        double size = 2 * GRID_HALF_SIZE;
        for (int j = 0; j < pointsV; j++) {
            for (int i = 0; i < pointsU; i++) {
                int k = 3 * (j * pointsU + i);
                net[k] = -GRID_HALF_SIZE + size * i / (pointsU - 1);
                net[k + 1] = -GRID_HALF_SIZE + size * j / (pointsV - 1);
            }
        }
        return new BezierPatch(pointsU - 1, pointsV - 1, net);
    }

    private static void checkPoints(String direction, int points) {
        int max = BezierPatch.MAX_DEGREE + 1;
        if (points < 2 || points > max) {
            throw new IllegalArgumentException("control points along " + direction + " must be 2.." + max
                    + ", got " + points);
        }
    }

    /** The built-in {@code sphere} ({@link BuiltInSurfaces}); a new scene each call. */
    public static Scene sphere() {
        return new Scene(BuiltInSurfaces.sphere());
    }

    /** The built-in {@code torus} ({@link BuiltInSurfaces}); a new scene each call. */
    public static Scene torus() {
        return new Scene(BuiltInSurfaces.torus());
    }

    /** The built-in {@code trimmed-plate} ({@link BuiltInSurfaces}); a new scene each call. */
    public static Scene trimmedPlate() {
        return new Scene(BuiltInSurfaces.trimmedPlate());
    }

    /** The Utah teapot (32 bicubic patches): the built-in {@code teapot}, read once. */
    public static Scene teapot() {
        return BuiltIns.find("teapot").orElseThrow().load().scene();
    }

    /**
     * The scene of a built-in name or a file of any registered format ({@link SceneFiles#load}).
     *
     * @throws ModelFormatException one line naming the file, for any problem
     */
    public static Scene load(String nameOrPath) {
        return SceneFiles.load(nameOrPath).scene();
    }
}
