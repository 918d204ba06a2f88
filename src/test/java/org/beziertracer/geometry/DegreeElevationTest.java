package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

class DegreeElevationTest {

    private static final int TRIALS = 100;

    @Test
    void elevatingInUOrVLeavesTheSurfaceUnchanged() {
        Random rnd = new Random(41);
        for (int trial = 0; trial < TRIALS; trial++) {
            int n = 1 + rnd.nextInt(BezierPatch.MAX_DEGREE - 1), m = 1 + rnd.nextInt(BezierPatch.MAX_DEGREE - 1);
            BezierPatch p = new BezierPatch(n, m, TestNets.randomNet(rnd, n, m, 3, 20));
            boolean inU = trial % 2 == 0;
            BezierPatch q = inU ? DegreeElevation.elevateU(p) : DegreeElevation.elevateV(p);
            assertEquals(inU ? n + 1 : n, q.degreeU());
            assertEquals(inU ? m : m + 1, q.degreeV());
            double tol = ROUNDING * TestNets.size(p.copyNet(), 0, 3 * p.pointCount());
            for (int s = 0; s < 20; s++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                double err = TestNets.maxDiff(TestNets.eval(p.copyNet(), 0, n, m, 3, u, v),
                        TestNets.eval(q.copyNet(), 0, q.degreeU(), q.degreeV(), 3, u, v));
                assertTrue(err <= tol, (inU ? "elevateU " : "elevateV ") + n + "x" + m + " at (" + u + "," + v
                        + "): error " + err);
            }
        }
    }

    @Test
    void flatArrayElevationWorksForOneAndTwoDimensionalNets() {
        Random rnd = new Random(42);
        for (int dim = 1; dim <= 2; dim++) {
            int n = 4, m = 3;
            double[] net = TestNets.randomNet(rnd, n, m, dim, 1);
            double[] up = new double[(n + 2) * (m + 1) * dim], vp = new double[(n + 1) * (m + 2) * dim];
            DegreeElevation.elevateU(net, 0, n, m, dim, up, 0);
            DegreeElevation.elevateV(net, 0, n, m, dim, vp, 0);
            for (int s = 0; s < 20; s++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                double[] p = TestNets.eval(net, 0, n, m, dim, u, v);
                assertTrue(TestNets.maxDiff(p, TestNets.eval(up, 0, n + 1, m, dim, u, v)) <= ROUNDING, "u, dim " + dim);
                assertTrue(TestNets.maxDiff(p, TestNets.eval(vp, 0, n, m + 1, dim, u, v)) <= ROUNDING, "v, dim " + dim);
            }
        }
    }

    @Test
    void elevatingBeyondTheMaximumDegreeIsRejected() {
        int max = BezierPatch.MAX_DEGREE;
        BezierPatch p = new BezierPatch(max, 1, new double[(max + 1) * 2 * 3]);
        String e = UserMessages.of(IllegalArgumentException.class, () -> DegreeElevation.elevateU(p));
        assertTrue(e.contains("degree in u"), e);
    }
}
