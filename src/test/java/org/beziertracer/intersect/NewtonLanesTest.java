package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.Kernels;
import org.beziertracer.math.LaneKernel;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link NewtonLanes} runs {@link RayPatchNewton#solve} for many lanes at once and gives each lane
 * the scalar solve's outcome to the bit: status, iterate, t, evaluation, residuals, where it left
 * the box, and the number of evaluations; with both kernels, on height fields and wild patches of
 * degree 1..9, from starts near a root, far from it and outside the patch's box (converged,
 * diverged, singular and extrapolated outcomes all occur).
 */
class NewtonLanesTest {

    private static final double TOLERANCE = 1e-12;

    @Test
    void everyLaneEndsAsTheScalarSolveEnds() {
        Random rnd = new Random(3203);
        double[] s = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int[] outcomes = new int[3];
        for (LaneKernel kernel : new LaneKernel[] {Kernels.scalar(), Kernels.named("simd")}) {
            TraceContext alone = new TraceContext(kernel), together = new TraceContext(kernel);
            NewtonLanes lanes = together.newtonLanes;
            RayBatch batch = together.batch;
            for (int trial = 0; trial < 400; trial++) {
                int n = 1 + rnd.nextInt(9), m = 1 + rnd.nextInt(9);
                BezierPatch patch = trial % 3 == 0 ? RandomPatches.wild(rnd, n, m, 4)
                        : RandomPatches.heightField(rnd, n, m, 4, 0.3);
                SubPatchTable tab = SubPatchTable.build(List.of(patch), SplitOptions.wholePatches());
                assertTrue(tab.patchPowerOffset[0] >= 0, "degree " + n + "x" + m + " has a power form");
                int count = 1 + rnd.nextInt(20);
                double[] rays = new double[6 * count], starts = new double[2 * count];
                for (int i = 0; i < count; i++) {
                    double us = rnd.nextDouble(), vs = rnd.nextDouble();
                    DeCasteljau.evaluate(tab.patchNets, 0, n, m, 3, us, vs, s, 0, scratch);
                    double ox = s[0] + rnd.nextGaussian(), oy = s[1] + rnd.nextGaussian(), oz = 6 + rnd.nextDouble();
                    rays[6 * i] = ox; rays[6 * i + 1] = oy; rays[6 * i + 2] = oz;
                    rays[6 * i + 3] = s[0] - ox; rays[6 * i + 4] = s[1] - oy; rays[6 * i + 5] = s[2] - oz;
                    double spread = i % 3 == 0 ? 0.02 : i % 3 == 1 ? 0.3 : 1.5;
                    starts[2 * i] = us + spread * (rnd.nextDouble() - 0.5);
                    starts[2 * i + 1] = vs + spread * (rnd.nextDouble() - 0.5);
                }
                double uLo = -0.05, uHi = 1.05, vLo = -0.05, vHi = 1.05;
                int steps = 1 + rnd.nextInt(10);
                batch.set(together, rays, count, 0, Double.POSITIVE_INFINITY);
                lanes.ensure(count);
                for (int i = 0; i < count; i++) {
                    batch.loadRay(together, i); // the lane's frame
                    lanes.lane[i] = i;
                    lanes.nextU[i] = starts[2 * i];
                    lanes.nextV[i] = starts[2 * i + 1];
                }
                long before = together.evaluations;
                lanes.solve(together, kernel, batch, tab, 0, count, steps, uLo, uHi, vLo, vHi, TOLERANCE);
                long laneEvaluations = together.evaluations - before;
                long scalarEvaluations = 0;
                for (int i = 0; i < count; i++) {
                    int o = 6 * i;
                    alone.setRay(rays[o], rays[o + 1], rays[o + 2], rays[o + 3], rays[o + 4], rays[o + 5]);
                    alone.escapeU = alone.escapeV = Double.NaN;
                    long e0 = alone.evaluations;
                    int status = RayPatchNewton.solve(alone, tab, 0, starts[2 * i], starts[2 * i + 1], steps,
                            uLo, uHi, vLo, vHi, TOLERANCE);
                    scalarEvaluations += alone.evaluations - e0;
                    outcomes[status]++;
                    batch.loadRay(together, i);
                    together.escapeU = together.escapeV = Double.NaN;
                    lanes.toContext(together, i, 0);
                    String where = kernel.description() + ", degree " + n + "x" + m + ", lane " + i + " of " + count
                            + ", " + steps + " steps";
                    assertEquals(status, lanes.status[i], where + ": status");
                    assertEquals(alone.rootU, together.rootU, 0, where + ": u");
                    assertEquals(alone.rootV, together.rootV, 0, where + ": v");
                    assertEquals(alone.rootT, together.rootT, 0, where + ": t");
                    assertEquals(alone.residual1, together.residual1, 0, where + ": residual 1");
                    assertEquals(alone.residual2, together.residual2, 0, where + ": residual 2");
                    assertEquals(alone.escapeU, together.escapeU, 0, where + ": escape u");
                    assertEquals(alone.escapeV, together.escapeV, 0, where + ": escape v");
                    assertEquals(alone.evalU, together.evalU, 0, where + ": evaluated at u");
                    for (int c = 0; c < 9; c++) {
                        assertEquals(alone.eval[c], together.eval[c], 0, where + ": evaluation component " + c);
                    }
                }
                assertEquals(scalarEvaluations, laneEvaluations, "evaluations, degree " + n + "x" + m);
            }
        }
        assertTrue(outcomes[RayPatchNewton.CONVERGED] > 1000, "converged " + outcomes[RayPatchNewton.CONVERGED]);
        assertTrue(outcomes[RayPatchNewton.DIVERGED] > 200, "diverged " + outcomes[RayPatchNewton.DIVERGED]);
    }
}
