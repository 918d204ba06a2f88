package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.LeafCriterion;

/**
 * Newton's own refinement criterion (experimental): a sub-patch may be a leaf only when Newton,
 * from the leaf's start, converges to the aimed point for probe rays.
 */
final class NewtonRefinement implements LeafCriterion {

    static double TILT_DEG = 60;
    static final double[] SAMPLES = {0.1, 0.5, 0.9};

    private static final ThreadLocal<TraceContext> CONTEXT = ThreadLocal.withInitial(TraceContext::new);

    static double NU = 0;

    static int FLAT_DEPTH = 6;
    static double FLATNESS = 0.05;

    @Override
    public boolean accepts(double[] net, int n, int m, double size, int depth) {
        if (FLAT_DEPTH > 0 && depth < FLAT_DEPTH
                && org.beziertracer.geometry.NetMeasures.flatness(net, 0, n, m) > FLATNESS * size) {
            return false;
        }
        TraceContext ctx = CONTEXT.get();
        double[] rec = new double[NewtonSolver.STRIDE];
        rec[NewtonSolver.DU] = 1;
        rec[NewtonSolver.DV] = 1;
        NewtonSolver.leafFrame(net, 0, n, m, rec, 0);
        if (NU > 0) {
            int a = NewtonSolver.A, b = NewtonSolver.B;
            double la = Math.sqrt(rec[a] * rec[a] + rec[a + 1] * rec[a + 1] + rec[a + 2] * rec[a + 2]);
            double lb = Math.sqrt(rec[b] * rec[b] + rec[b + 1] * rec[b + 1] + rec[b + 2] * rec[b + 2]);
            double cx = rec[a + 1] * rec[b + 2] - rec[a + 2] * rec[b + 1], cy = rec[a + 2] * rec[b] - rec[a] * rec[b + 2];
            double cz = rec[a] * rec[b + 1] - rec[a + 1] * rec[b];
            double sin = Math.sqrt(cx * cx + cy * cy + cz * cz) / (la * lb);
            double nu = (rec[NewtonSolver.RA] / la + rec[NewtonSolver.RB] / lb) / sin;
            if (!(nu <= NU)) {
                return false;
            }
        }
        double[] e = new double[9];
        double[] box = ctx.entryBoxes;
        box[6] = Double.NaN;
        double tilt = Math.toRadians(TILT_DEG);
        for (double s : SAMPLES) {
            for (double t : SAMPLES) {
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, s, t, e, ctx.scratch);
                double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
                double nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
                double ul = Math.sqrt(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]);
                double vl = Math.sqrt(e[6] * e[6] + e[7] * e[7] + e[8] * e[8]);
                if (!(nl > 0) || !(ul > 0) || !(vl > 0)) {
                    continue; // a degenerate point (collapsed edge): no normal to aim along
                }
                for (int dir = 0; dir < 5; dir++) {
                    double c = dir == 0 ? 1 : Math.cos(tilt), w = dir == 0 ? 0 : Math.sin(tilt) * (dir < 3 ? 1 : -1);
                    double tx = (dir & 1) == 1 ? e[3] / ul : e[6] / vl, ty = (dir & 1) == 1 ? e[4] / ul : e[7] / vl;
                    double tz = (dir & 1) == 1 ? e[5] / ul : e[8] / vl;
                    double dx = -c * nx / nl + w * tx, dy = -c * ny / nl + w * ty, dz = -c * nz / nl + w * tz;
                    ctx.setRay(e[0] - size * dx, e[1] - size * dy, e[2] - size * dz, dx, dy, dz);
                    if (NewtonSolver.start(ctx, rec, 0, 0, Double.POSITIVE_INFINITY, 0) == NewtonSolver.MISS) {
                        return false;
                    }
                    box[0] = -NewtonSolver.WANDER; box[1] = 1 + NewtonSolver.WANDER;
                    box[2] = -NewtonSolver.WANDER; box[3] = 1 + NewtonSolver.WANDER;
                    box[4] = 0; box[5] = Double.POSITIVE_INFINITY;
                    double tol = 1e-12 * size;
                    if (NewtonSolver.iterate0(ctx, net, 0, n, m, ctx.clip[0], ctx.clip[1], box, tol)
                            != NewtonSolver.CONVERGED
                            || Math.abs(ctx.rootU - s) > 1e-6 || Math.abs(ctx.rootV - t) > 1e-6) {
                        return false;
                    }
                }
            }
        }
        return true;
    }
}
