package org.beziertracer.intersect;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DegreeElevation;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;

/** Seeded random test patches. */
final class RandomPatches {
    private RandomPatches() {}

    /**
     * A wavy height field over {@code [-size/2, size/2]²}: a jittered grid in x and y, random
     * heights up to {@code relief·size}. Does not fold over itself seen from above.
     */
    static BezierPatch heightField(Random rnd, int n, int m, double size, double relief) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                net[k] = size * ((double) i / n - 0.5) + 0.1 * size / n * (rnd.nextDouble() - 0.5);
                net[k + 1] = size * ((double) j / m - 0.5) + 0.1 * size / m * (rnd.nextDouble() - 0.5);
                net[k + 2] = relief * size * (rnd.nextDouble() - 0.5);
            }
        }
        return new BezierPatch(n, m, net);
    }

    /** A patch with every control point random in a cube: may fold, twist and self-intersect. */
    static BezierPatch wild(Random rnd, int n, int m, double size) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int k = 0; k < net.length; k++) {
            net[k] = size * (rnd.nextDouble() - 0.5);
        }
        return new BezierPatch(n, m, net);
    }

    /**
     * A 3×3 quilt of bicubic patches over {@code [0,3]²} (one random height grid of 10×10 control
     * points, so neighbours share their border control points and meet exactly), whose centre
     * patch is replaced by a degree-6×6 patch: the centre raised to degree 6 in both directions
     * (the same surface, {@link DegreeElevation}) with its interior control points lifted at
     * random. Its borders stay the neighbours' cubic borders, described with seven points
     * instead of four: the model of the dense border test with a degree-6 neighbour.
     */
    static Scene mixedDegreeQuilt(Random rnd) {
        double[][] z = new double[10][10];
        for (double[] row : z) {
            for (int i = 0; i < row.length; i++) {
                row[i] = 0.6 * (rnd.nextDouble() - 0.5);
            }
        }
        List<BezierPatch> patches = new ArrayList<>();
        for (int pj = 0; pj < 3; pj++) {
            for (int pi = 0; pi < 3; pi++) {
                double[] net = new double[16 * 3];
                for (int j = 0; j <= 3; j++) {
                    for (int i = 0; i <= 3; i++) {
                        int k = 3 * (4 * j + i);
                        net[k] = pi + i / 3.0;
                        net[k + 1] = pj + j / 3.0;
                        net[k + 2] = z[3 * pj + j][3 * pi + i];
                    }
                }
                BezierPatch p = new BezierPatch(3, 3, net);
                patches.add(pi == 1 && pj == 1 ? liftedDegree6(p, rnd) : p);
            }
        }
        return new Scene(patches);
    }

    private static BezierPatch liftedDegree6(BezierPatch cubic, Random rnd) {
        BezierPatch p = cubic;
        for (int k = 0; k < 3; k++) {
            p = DegreeElevation.elevateV(DegreeElevation.elevateU(p));
        }
        double[] net = p.copyNet();
        for (int j = 1; j < 6; j++) {
            for (int i = 1; i < 6; i++) {
                net[3 * (7 * j + i) + 2] += 0.8 * (rnd.nextDouble() - 0.3);
            }
        }
        return new BezierPatch(6, 6, net);
    }

    /**
     * One random wavy height field and one folded net of every degree 1..15 in u (random degree
     * in v), then the teapot: the models the seeded tests of the solvers' shortcuts sweep.
     */
    static List<List<BezierPatch>> everyDegreeAndTheTeapot(Random rnd) {
        List<List<BezierPatch>> models = new ArrayList<>();
        for (int n = 1; n <= 15; n++) {
            models.add(List.of(heightField(rnd, n, 1 + rnd.nextInt(15), 4, 0.5)));
            models.add(List.of(wild(rnd, n, 1 + rnd.nextInt(15), 4)));
        }
        models.add(Models.teapot().patches());
        return models;
    }
}
