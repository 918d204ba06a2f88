package org.beziertracer.intersect;

import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.math.LaneKernel;

/**
 * {@link RayPatchNewton#solve} for several lanes of a {@link RayBatch} on the same patch at once:
 * every round evaluates the power form at all the lanes' iterates together ({@link
 * LaneKernel#powerForm}, SIMD registers with the vector kernel), then takes each lane's Newton step
 * alone. Toth, "On ray tracing parametric surfaces", SIGGRAPH 1985; the lanes after Geimer and
 * Abert, "Interactive ray tracing of trimmed bicubic Bézier surfaces without triangulation", WSCG
 * 2005 (Newton on packets of rays).
 *
 * <p>Each lane runs exactly the scalar solve's sequence of operations — the same evaluations (the
 * kernels give the scalar bits), the same steps, tests and extrapolation, in the same order — so
 * its outcome, root, last evaluation and residuals are the scalar solve's to the bit, and so is the
 * count of evaluations; only the order in which lanes are evaluated differs. Not for a solve whose
 * first iterate is the point a shadow ray leaves (the scalar solve's {@code fromOrigin},
 * {@link RayPatchNewton#startsAtOrigin}): such a lane is solved alone.
 *
 * <h2>Layout</h2>
 * Slot {@code j} (the {@code j}-th lane handed in): {@code lane[j]} its lane of the batch,
 * {@code nextU[j], nextV[j]} its start, {@code eval[9j .. 9j+9)} the last evaluation (S, Su, Sv) at
 * the iterate {@code u[j], v[j]}, {@code status[j]}; per-thread scratch, grown to the
 * largest batch, nothing allocated per ray.
 */
final class NewtonLanes {

    /** Lane states while solving (the outcomes are {@link RayPatchNewton}'s codes). */
    private static final int STEPPING = -1, FINAL = -2;

    int capacity;
    int[] lane = new int[0], status = new int[0], step = new int[0];
    /** What {@link BezierClipper#afterNewton} needs of slot {@code j}'s leaf ({@link #keepPending}). */
    boolean[] own = new boolean[0], windingFirst = new boolean[0], polynomial = new boolean[0];
    /** The last evaluated iterate (the root so far), and the next point to evaluate (the start, then each step's). */
    double[] u = new double[0], v = new double[0], nextU = new double[0], nextV = new double[0], eval = new double[0];
    double[] residual1 = new double[0], residual2 = new double[0], rootT = new double[0];
    double[] escapeU = new double[0], escapeV = new double[0];
    /** Newton's last steps taken without an evaluation ({@link #extrapolate}), cumulative: a work counter. */
    long extrapolations;
    /** The slots to evaluate this round, their points, and the kernel's output (component-major). */
    private int[] due = new int[0];
    private double[] dueU = new double[0], dueV = new double[0], out = new double[0];

    void ensure(int n) {
        if (capacity >= n) {
            return;
        }
        // whole SIMD registers past the last lane (LaneKernel's scratch lanes): a multiple of 16
        int c = (Math.max(n, 2 * capacity) + 15) & ~15;
        lane = new int[c]; status = new int[c]; step = new int[c]; due = new int[c];
        own = new boolean[c]; windingFirst = new boolean[c]; polynomial = new boolean[c];
        u = new double[c]; v = new double[c]; nextU = new double[c]; nextV = new double[c]; eval = new double[9 * c];
        residual1 = new double[c]; residual2 = new double[c]; rootT = new double[c];
        escapeU = new double[c]; escapeV = new double[c];
        dueU = new double[c]; dueV = new double[c]; out = new double[9 * c];
        capacity = c;
    }

    /**
     * Newton on polynomial patch {@code k} (which has a power form) for the {@code count} slots
     * whose lane and start {@code (nextU[j], nextV[j])} are set, iterates confined to
     * {@code [uLo,uHi]×[vLo,vHi]}; leaves each slot's outcome in {@code status[j]}
     * ({@link RayPatchNewton#CONVERGED}, {@code SINGULAR} or {@code DIVERGED}) and its last iterate,
     * evaluation, residuals and t. The evaluations are counted in {@code ctx.evaluations}.
     */
    void solve(TraceContext ctx, LaneKernel kernel, RayBatch batch, SubPatchTable table, int k, int count,
               int maxSteps, double uLo, double uHi, double vLo, double vHi, double tolerance) {
        double curvature = table.patchCurvature[k];
        int power = table.patchPowerOffset[k], n = table.patchDegreeU[k], m = table.patchDegreeV[k];
        for (int j = 0; j < count; j++) {
            status[j] = STEPPING;
            step[j] = 0;
            escapeU[j] = Double.NaN;
        }
        int dueCount = count;
        for (int j = 0; j < count; j++) {
            due[j] = j;
        }
        while (dueCount > 0) {
            // Evaluate every due iterate together
            for (int q = 0; q < dueCount; q++) {
                int j = due[q];
                dueU[q] = u[j] = nextU[j];
                dueV[q] = v[j] = nextV[j];
            }
            kernel.powerForm(table.nets, power, n, m, dueU, dueV, dueCount, out, capacity);
            ctx.evaluations += dueCount;
            ctx.laneEvaluations += dueCount;
            int next = 0;
            for (int q = 0; q < dueCount; q++) {
                int j = due[q];
                for (int c = 0, e = 9 * j; c < 9; c++) {
                    eval[e + c] = out[c * capacity + q];
                }
                takeIterate(batch, j);
                if (status[j] == FINAL) {
                    status[j] = Math.abs(residual1[j]) <= tolerance && Math.abs(residual2[j]) <= tolerance
                            ? RayPatchNewton.CONVERGED : RayPatchNewton.DIVERGED;
                } else if (advance(batch, j, maxSteps, curvature, uLo, uHi, vLo, vHi, tolerance)) {
                    due[next++] = j;
                }
            }
            dueCount = next;
        }
    }

    /**
     * The scalar solve's loop body after an evaluation at step {@code step[j]}: true when slot
     * {@code j} needs another evaluation (at its new iterate), false when it has an outcome.
     */
    private boolean advance(RayBatch batch, int j, int maxSteps, double curvature, double uLo, double uHi,
                            double vLo, double vHi, double tolerance) {
        double f1 = residual1[j], f2 = residual2[j];
        if (Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance && step[j] > 0) {
            status[j] = RayPatchNewton.CONVERGED;
            return false;
        }
        if (step[j] == maxSteps) {
            status[j] = RayPatchNewton.DIVERGED;
            return false;
        }
        int f = RayBatch.FRAME * lane[j], e = 9 * j;
        double[] fr = batch.frame, ev = eval;
        double n1x = fr[f + 3], n1y = fr[f + 4], n1z = fr[f + 5], n2x = fr[f + 6], n2y = fr[f + 7], n2z = fr[f + 8];
        double a = n1x * ev[e + 3] + n1y * ev[e + 4] + n1z * ev[e + 5];
        double b = n1x * ev[e + 6] + n1y * ev[e + 7] + n1z * ev[e + 8];
        double c = n2x * ev[e + 3] + n2y * ev[e + 4] + n2z * ev[e + 5];
        double d = n2x * ev[e + 6] + n2y * ev[e + 7] + n2z * ev[e + 8];
        double det = a * d - b * c;
        double scale = Math.abs(a * d) + Math.abs(b * c);
        if (!(Math.abs(det) > 1e-300) || Math.abs(det) <= 1e-14 * scale) {
            status[j] = Math.abs(f1) <= tolerance && Math.abs(f2) <= tolerance
                    ? RayPatchNewton.CONVERGED : RayPatchNewton.SINGULAR;
            return false;
        }
        double du = (b * f2 - d * f1) / det;
        double dv = (c * f1 - a * f2) / det;
        if (extrapolate(batch, j, curvature, du, dv, tolerance, uLo, uHi, vLo, vHi)) {
            status[j] = RayPatchNewton.CONVERGED;
            return false;
        }
        if (Math.abs(du) < 1e-15 && Math.abs(dv) < 1e-15
                && Math.max(Math.abs(f1), Math.abs(f2)) <= 1e-3 * tolerance) {
            status[j] = RayPatchNewton.CONVERGED;
            return false;
        }
        double nu = u[j] + du, nv = v[j] + dv;
        nextU[j] = nu;
        nextV[j] = nv;
        if (!(nu >= uLo && nu <= uHi && nv >= vLo && nv <= vHi)) {
            escapeU[j] = nu;
            escapeV[j] = nv;
            status[j] = RayPatchNewton.DIVERGED;
            return false;
        }
        if (Math.abs(du) < 1e-15 && Math.abs(dv) < 1e-15) {
            status[j] = FINAL; // one more evaluation at the final iterate for t
            return true;
        }
        step[j]++;
        return true;
    }

    /** {@link RayPatchNewton}'s takeIterate for slot {@code j}: residuals and t of the point in {@code eval}. */
    private void takeIterate(RayBatch batch, int j) {
        int f = RayBatch.FRAME * lane[j], o = 6 * lane[j], e = 9 * j;
        double[] fr = batch.frame, t = batch.traversal, ev = eval;
        double qx = ev[e] - t[o], qy = ev[e + 1] - t[o + 1], qz = ev[e + 2] - t[o + 2];
        residual1[j] = fr[f + 3] * qx + fr[f + 4] * qy + fr[f + 5] * qz;
        residual2[j] = fr[f + 6] * qx + fr[f + 7] * qy + fr[f + 8] * qz;
        rootT[j] = (fr[f + 9] * qx + fr[f + 10] * qy + fr[f + 11] * qz) * fr[f + 12];
    }

    /** {@link RayPatchNewton#extrapolate} for slot {@code j}. */
    private boolean extrapolate(RayBatch batch, int j, double curvature, double du, double dv, double tolerance,
                                double uLo, double uHi, double vLo, double vHi) {
        double reach = Math.abs(du) + Math.abs(dv), remainder = 0.5 * curvature * reach * reach;
        if (!(remainder <= RayPatchNewton.EXTRAPOLATED * tolerance)) {
            return false;
        }
        double nu = u[j] + du, nv = v[j] + dv;
        if (!(nu >= uLo && nu <= uHi && nv >= vLo && nv <= vHi)) {
            return false;
        }
        int f = RayBatch.FRAME * lane[j], o = 6 * lane[j], e = 9 * j;
        double[] fr = batch.frame, t = batch.traversal, ev = eval;
        double px = ev[e] + ev[e + 3] * du + ev[e + 6] * dv, py = ev[e + 1] + ev[e + 4] * du + ev[e + 7] * dv,
                pz = ev[e + 2] + ev[e + 5] * du + ev[e + 8] * dv;
        double qx = px - t[o], qy = py - t[o + 1], qz = pz - t[o + 2];
        double r1 = fr[f + 3] * qx + fr[f + 4] * qy + fr[f + 5] * qz, r2 = fr[f + 6] * qx + fr[f + 7] * qy + fr[f + 8] * qz;
        if (!(Math.max(Math.abs(r1), Math.abs(r2)) + remainder <= RayPatchNewton.EXTRAPOLATED * tolerance)) {
            return false;
        }
        ev[e] = px;
        ev[e + 1] = py;
        ev[e + 2] = pz;
        u[j] = nu;
        v[j] = nv;
        takeIterate(batch, j);
        extrapolations++;
        return true;
    }

    /** Keeps what {@link BezierClipper#begin} left in {@code ctx.pending*} (but the start) in slot {@code j}. */
    void keepPending(TraceContext ctx, int j) {
        own[j] = ctx.pendingOwn;
        windingFirst[j] = ctx.pendingWindingFirst;
        polynomial[j] = ctx.pendingPolynomial;
    }

    /**
     * Puts slot {@code j}'s last iterate into {@code ctx} as the scalar solve leaves it: the root so
     * far ({@code rootU/V/T}), the evaluation there ({@code eval}, {@code evalPatch = k}), its
     * residuals and, after a divergence, where it left the box; and its leaf's {@code pending*}. {@code ctx} must hold the slot's lane
     * ({@link RayBatch#load}).
     */
    void toContext(TraceContext ctx, int j, int k) {
        System.arraycopy(eval, 9 * j, ctx.eval, 0, 9);
        ctx.evalPatch = k;
        ctx.rootU = ctx.evalU = u[j];
        ctx.rootV = ctx.evalV = v[j];
        ctx.rootT = rootT[j];
        ctx.pendingOwn = own[j];
        ctx.pendingWindingFirst = windingFirst[j];
        ctx.pendingPolynomial = polynomial[j];
        ctx.residual1 = residual1[j];
        ctx.residual2 = residual2[j];
        if (!Double.isNaN(escapeU[j])) { // it left the box there
            ctx.escapeU = escapeU[j];
            ctx.escapeV = escapeV[j];
        }
    }
}
