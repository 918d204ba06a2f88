package org.beziertracer.intersect;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SubPatchTable;

/**
 * Ray–patch intersection by Newton iteration (experimental v3: compact leaf records).
 */
final class NewtonSolver {
    private NewtonSolver() {}

    static int MAX_STEPS = 10;
    static double OVERLAP = 1;
    static double WANDER = 1;
    static int STARTS = 6;
    static double TOL_SCALE = 1;
    static boolean LEGACY = false;
    static int MODE = 1;
    static boolean SAME_ABORT = !Boolean.getBoolean("nosame");
    static boolean T_ABORT = !Boolean.getBoolean("notabort");
    static final boolean STATS = Boolean.getBoolean("stats");
    static double LOOSE = 1e5;
    static final double PATCH_SLACK = 1e-9;
    static final double[] EXTRA = {0.5, 0.5, 0.1, 0.1, 0.9, 0.1, 0.1, 0.9, 0.9, 0.9};
    static long NON_UNIQUE, RUNS, EVALS, FAILED_EVALS, FAILED_RUNS, CONV_RUNS;
    static long[] STEPS_HIST = new long[12];

    static final int CONVERGED = 0, FAILED = 1;

    /** Doubles per leaf record. */
    static final int STRIDE = 16;
    static final int U0 = 0, DU = 1, V0 = 2, DV = 3, C = 4, A = 7, B = 10, RA = 13, RB = 14, R = 15;

    private static final java.util.Map<SubPatchTable, double[]> CACHE =
            java.util.Collections.synchronizedMap(new java.util.IdentityHashMap<>());

    private static SubPatchTable lastTab;
    private static double[] lastRec;

    static double[] records(SubPatchTable tab) {
        if (tab == lastTab) {
            return lastRec;
        }
        double[] r = CACHE.computeIfAbsent(tab, NewtonSolver::buildRecords);
        lastRec = r;
        lastTab = tab;
        return r;
    }

    static double[] buildRecords(SubPatchTable tab) {
        double[] rec = new double[STRIDE * tab.count];
        for (int s = 0; s < tab.count; s++) {
            int o = STRIDE * s;
            rec[o + U0] = tab.boxes[4 * s];
            rec[o + DU] = tab.boxes[4 * s + 1] - tab.boxes[4 * s];
            rec[o + V0] = tab.boxes[4 * s + 2];
            rec[o + DV] = tab.boxes[4 * s + 3] - tab.boxes[4 * s + 2];
            leafFrame(tab.nets, tab.netOffset[s], tab.degreeU[s], tab.degreeV[s], rec, o);
        }
        return rec;
    }

    /**
     * Writes the corner parallelogram of a net (centre C, axes A, B), the radii RA, RB of balls
     * around A and B holding Su and Sv, and R, the bound on |S(s,t) − P(s,t)| to rec[o+C..o+R].
     */
    static void leafFrame(double[] net, int off, int n, int m, double[] rec, int o) {
        int row = 3 * (n + 1);
        int p00 = off, pn0 = off + 3 * n, p0m = off + row * m, pnm = p0m + 3 * n;
        // Axes: centres of the boxes of the scaled hodograph control points (smallest balls' centres)
        for (int c = 0; c < 3; c++) {
            double loA = Double.POSITIVE_INFINITY, hiA = Double.NEGATIVE_INFINITY;
            double loB = Double.POSITIVE_INFINITY, hiB = Double.NEGATIVE_INFINITY;
            for (int j = 0; j <= m; j++) {
                for (int i = 0; i <= n; i++) {
                    int p = off + j * row + 3 * i + c;
                    if (i < n) {
                        double d = n * (net[p + 3] - net[p]);
                        loA = Math.min(loA, d);
                        hiA = Math.max(hiA, d);
                    }
                    if (j < m) {
                        double d = m * (net[p + row] - net[p]);
                        loB = Math.min(loB, d);
                        hiB = Math.max(hiB, d);
                    }
                }
            }
            rec[o + A + c] = 0.5 * (loA + hiA);
            rec[o + B + c] = 0.5 * (loB + hiB);
            rec[o + C + c] = 0.25 * (net[p00 + c] + net[pn0 + c] + net[p0m + c] + net[pnm + c]);
        }
        double ra = 0, rb = 0;
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int p = off + j * row + 3 * i;
                if (i < n) {
                    ra = Math.max(ra, deviation(net, p, p + 3, n, rec, o + A));
                }
                if (j < m) {
                    rb = Math.max(rb, deviation(net, p, p + row, m, rec, o + B));
                }
            }
        }
        // S(s,t) lies within s·ra + t·rb of P00 + s·A + t·B, so within R of C + (s-½)A + (t-½)B
        double ex = rec[o + C] - 0.5 * (rec[o + A] + rec[o + B]) - net[p00];
        double ey = rec[o + C + 1] - 0.5 * (rec[o + A + 1] + rec[o + B + 1]) - net[p00 + 1];
        double ez = rec[o + C + 2] - 0.5 * (rec[o + A + 2] + rec[o + B + 2]) - net[p00 + 2];
        rec[o + RA] = ra;
        rec[o + RB] = rb;
        rec[o + R] = Math.sqrt(ex * ex + ey * ey + ez * ez) + ra + rb;
    }

    /** |deg·(net[q] − net[p]) − axis|. */
    private static double deviation(double[] net, int p, int q, int deg, double[] rec, int axis) {
        double x = deg * (net[q] - net[p]) - rec[axis], y = deg * (net[q + 1] - net[p + 1]) - rec[axis + 1];
        double z = deg * (net[q + 2] - net[p + 2]) - rec[axis + 2];
        return Math.sqrt(x * x + y * y + z * z);
    }

    static boolean intersect(TraceContext ctx, SubPatchTable tab, int s, double tMin, double tMax,
                             double tolerance) {
        if (LEGACY) {
            return NewtonSolverLegacy.intersect(ctx, tab, s, tMin, tMax, tolerance);
        }
        double[] rec = records(tab);
        int o = STRIDE * s;
        int r = start(ctx, rec, o, tMin, tMax, tolerance);
        if (r == MISS) {
            return false;
        }
        boolean unique = r == UNIQUE;
        if (STATS && !unique) NON_UNIQUE++;
        return solve(ctx, tab, s, rec, o, ctx.clip[0], ctx.clip[1], unique, tMin, tMax, tolerance);
    }

    static final int MISS = 0, UNIQUE = 1, MAYBE_SEVERAL = 2;
    static double LEAF_DET, LAST_DET;
    static long[] IMPROVE = new long[8];
    static boolean FIRST_SIGN_SAME;
    static long UNIQ_SECOND_RUNS, UNIQ_SECOND_FOUND;

    /**
     * Meets the ray with the leaf's thick parallelogram: MISS when the leaf provably does not
     * meet the ray in (tMin, tMax); else the start (s,t) in ctx.clip and whether the leaf
     * provably holds at most one root.
     */
    static int start(TraceContext ctx, double[] rec, int o, double tMin, double tMax, double tolerance) {
        double cx = rec[o + C] - ctx.ox, cy = rec[o + C + 1] - ctx.oy, cz = rec[o + C + 2] - ctx.oz;
        double x0 = ctx.n1x * cx + ctx.n1y * cy + ctx.n1z * cz;
        double y0 = ctx.n2x * cx + ctx.n2y * cy + ctx.n2z * cz;
        double z0 = ctx.n3x * cx + ctx.n3y * cy + ctx.n3z * cz;
        double ax = rec[o + A], ay = rec[o + A + 1], az = rec[o + A + 2];
        double bx = rec[o + B], by = rec[o + B + 1], bz = rec[o + B + 2];
        double xa = ctx.n1x * ax + ctx.n1y * ay + ctx.n1z * az, ya = ctx.n2x * ax + ctx.n2y * ay + ctx.n2z * az;
        double za = ctx.n3x * ax + ctx.n3y * ay + ctx.n3z * az;
        double xb = ctx.n1x * bx + ctx.n1y * by + ctx.n1z * bz, yb = ctx.n2x * bx + ctx.n2y * by + ctx.n2z * bz;
        double zb = ctx.n3x * bx + ctx.n3y * by + ctx.n3z * bz;
        double r = rec[o + R] + tolerance;
        double zSpan = 0.5 * (Math.abs(za) + Math.abs(zb)) + r;
        if ((z0 - zSpan) * ctx.invLength >= tMax || (z0 + zSpan) * ctx.invLength <= tMin) {
            return MISS;
        }
        double det = xa * yb - ya * xb;
        double la = Math.sqrt(xa * xa + ya * ya), lb = Math.sqrt(xb * xb + yb * yb);
        double[] st = ctx.clip;
        st[0] = 0.5;
        st[1] = 0.5;
        if (Math.abs(det) > 1e-9 * la * lb) {
            double ss = (-x0 * yb + y0 * xb) / det, tt = (-xa * y0 + ya * x0) / det;
            double gs = r * lb / Math.abs(det), gt = r * la / Math.abs(det);
            if (ss < -0.5 - gs || ss > 0.5 + gs || tt < -0.5 - gt || tt > 0.5 + gt) {
                return MISS;
            }
            st[0] = Math.min(1, Math.max(0, ss + 0.5));
            st[1] = Math.min(1, Math.max(0, tt + 0.5));
        } else {
            double xs = 0.5 * (Math.abs(xa) + Math.abs(xb)) + r, ys = 0.5 * (Math.abs(ya) + Math.abs(yb)) + r;
            if (x0 - xs > 0 || x0 + xs < 0 || y0 - ys > 0 || y0 + ys < 0) {
                return MISS;
            }
        }
        double ra = rec[o + RA], rb = rec[o + RB];
        double bound = rb * (Math.abs(xa) + Math.abs(ya)) + ra * (Math.abs(xb) + Math.abs(yb)) + 2 * ra * rb
                + 1e-10 * (la + ra) * (lb + rb);
        return Math.abs(det) > bound ? UNIQUE : MAYBE_SEVERAL;
    }

    static boolean solve(TraceContext ctx, SubPatchTable tab, int s, double[] rec, int o, double su, double sv,
                         boolean unique, double tMin, double tMax, double tolerance) {
        double u0 = rec[o + U0], du = rec[o + DU], v0 = rec[o + V0], dv = rec[o + DV];
        double uLo = Math.max(-PATCH_SLACK, u0 - OVERLAP * du), uHi = Math.min(1 + PATCH_SLACK, u0 + (1 + OVERLAP) * du);
        double vLo = Math.max(-PATCH_SLACK, v0 - OVERLAP * dv), vHi = Math.min(1 + PATCH_SLACK, v0 + (1 + OVERLAP) * dv);
        double[] box = ctx.entryBoxes;
        box[6] = Double.NaN;
        box[8] = du;
        box[9] = dv;
        box[0] = u0 - WANDER * du; box[1] = u0 + (1 + WANDER) * du; box[2] = v0 - WANDER * dv; box[3] = v0 + (1 + WANDER) * dv;
        int k = tab.parent[s];
        double[] net = tab.patchNets;
        int off = tab.patchNetOffset[k], n = tab.patchDegreeU[k], m = tab.patchDegreeV[k];
        boolean found = false;
        double bestT = tMax, bestU = 0, bestV = 0;
        double s0 = su, t0 = sv;
        for (int attempt = 0; attempt < STARTS; attempt++) {
            if (attempt >= 1) {
                if (found && unique || attempt >= 2 && (unique || !found)) {
                    break;
                }
                if (MODE == 1 && attempt >= 2) {
                    // reflections of the best root: through the first start, through the centre
                    double ru = (bestU - u0) / du, rv = (bestV - v0) / dv;
                    if (attempt == 2) { su = 2 * s0 - ru; sv = 2 * t0 - rv; }
                    else if (attempt == 3) { su = 1 - ru; sv = 1 - rv; }
                    else break;
                    su = Math.min(1, Math.max(0, su)); sv = Math.min(1, Math.max(0, sv));
                } else {
                    su = EXTRA[2 * attempt - 2];
                    sv = EXTRA[2 * attempt - 1];
                }
            }
            box[4] = tMin;
            box[5] = bestT;
            if (STATS && attempt == 1 && unique) UNIQ_SECOND_RUNS++;
            if (iterate(ctx, net, off, n, m, u0 + su * du, v0 + sv * dv, box, tolerance * TOL_SCALE) == CONVERGED) {
                double u = ctx.rootU, v = ctx.rootV;
                if (u >= uLo && u <= uHi && v >= vLo && v <= vHi && ctx.rootT > tMin && ctx.rootT < bestT) {
                    if (STATS && found && ctx.rootT < bestT - 1e-6 * Math.abs(bestT)) {
                        IMPROVE[attempt] += 1;
                        IMPROVE[4 + (FIRST_SIGN_SAME ? 1 : 0)] += 1;
                    }
                    if (STATS && !found && attempt == 1 && unique) UNIQ_SECOND_FOUND++;
                    if (STATS && !found) { FIRST_SIGN_SAME = (LAST_DET > 0) == (LEAF_DET > 0); if (!unique) IMPROVE[6 + (FIRST_SIGN_SAME ? 1 : 0)]++; }
                    bestT = ctx.rootT;
                    bestU = u;
                    bestV = v;
                    found = true;
                    if (SAME_ABORT) {
                        box[6] = u;
                        box[7] = v;
                    }
                }
            }
        }
        if (!found) {
            return false;
        }
        ctx.evalPatch = ctx.rootT == bestT && ctx.rootU == bestU && ctx.rootV == bestV ? k : -1;
        ctx.rootT = bestT;
        ctx.rootU = Math.min(1, Math.max(0, bestU));
        ctx.rootV = Math.min(1, Math.max(0, bestV));
        return true;
    }

    static int iterate(TraceContext ctx, double[] net, int off, int n, int m, double u, double v, double[] box,
                       double tolerance) {
        if (!STATS) return iterate0(ctx, net, off, n, m, u, v, box, tolerance);
        long before = EVALS;
        int r = iterate0(ctx, net, off, n, m, u, v, box, tolerance);
        RUNS++;
        if (r == FAILED) { FAILED_EVALS += EVALS - before; FAILED_RUNS++; } else { CONV_RUNS++; STEPS_HIST[(int) Math.min(11, EVALS - before)]++; }
        return r;
    }

    /** Newton iterations from (u,v) on the net; the last iterate in ctx.root*, its evaluation in ctx.eval. */
    static int iterate0(TraceContext ctx, double[] net, int off, int n, int m, double u, double v, double[] box,
                        double tolerance) {
        double[] e = ctx.eval;
        for (int step = 0; step <= MAX_STEPS; step++) {
            if (STATS) EVALS++;
            DeCasteljau.evaluateWithDerivatives(net, off, n, m, u, v, e, ctx.scratch);
            double qx = e[0] - ctx.ox, qy = e[1] - ctx.oy, qz = e[2] - ctx.oz;
            double f1 = ctx.n1x * qx + ctx.n1y * qy + ctx.n1z * qz;
            double f2 = ctx.n2x * qx + ctx.n2y * qy + ctx.n2z * qz;
            ctx.rootU = u;
            ctx.rootV = v;
            ctx.evalU = u;
            ctx.evalV = v;
            ctx.rootT = (ctx.n3x * qx + ctx.n3y * qy + ctx.n3z * qz) * ctx.invLength;
            double residual = Math.max(Math.abs(f1), Math.abs(f2));
            if (residual <= tolerance) {
                if (STATS) {
                    LAST_DET = (ctx.n1x * e[3] + ctx.n1y * e[4] + ctx.n1z * e[5]) * (ctx.n2x * e[6] + ctx.n2y * e[7] + ctx.n2z * e[8])
                            - (ctx.n1x * e[6] + ctx.n1y * e[7] + ctx.n1z * e[8]) * (ctx.n2x * e[3] + ctx.n2y * e[4] + ctx.n2z * e[5]);
                }
                return CONVERGED;
            }
            if (step == MAX_STEPS) {
                break;
            }
            double a = ctx.n1x * e[3] + ctx.n1y * e[4] + ctx.n1z * e[5];
            double b = ctx.n1x * e[6] + ctx.n1y * e[7] + ctx.n1z * e[8];
            double c = ctx.n2x * e[3] + ctx.n2y * e[4] + ctx.n2z * e[5];
            double d = ctx.n2x * e[6] + ctx.n2y * e[7] + ctx.n2z * e[8];
            double det = a * d - b * c;
            if (!(Math.abs(det) > 1e-300) || Math.abs(det) <= 1e-14 * (Math.abs(a * d) + Math.abs(b * c))) {
                return FAILED;
            }
            double du = (b * f2 - d * f1) / det, dv = (c * f1 - a * f2) / det;
            if (STATS) LAST_DET = det;
            if (residual <= LOOSE * tolerance) {
                // Close enough that Newton squares the error: the last step needs no evaluation
                // (t follows to first order, exact to the square of this step)
                double g3 = ctx.n3x * (e[3] * du + e[6] * dv) + ctx.n3y * (e[4] * du + e[7] * dv)
                        + ctx.n3z * (e[5] * du + e[8] * dv);
                ctx.rootU = u + du;
                ctx.rootV = v + dv;
                ctx.rootT += g3 * ctx.invLength;
                return CONVERGED;
            }
            if (box[6] == box[6] && Math.abs(u + du - box[6]) < 1e-3 * box[8] && Math.abs(v + dv - box[7]) < 1e-3 * box[9]) {
                return FAILED; // heading back to the root already found
            }
            if (T_ABORT && step > 0) {
                // In the quadratic regime the remaining steps move less than this one: a root
                // whose t stays beyond (tMin, tMax) by more than this step is not wanted
                double sx = e[3] * du + e[6] * dv, sy = e[4] * du + e[7] * dv, sz = e[5] * du + e[8] * dv;
                double move = Math.sqrt(sx * sx + sy * sy + sz * sz) * ctx.invLength;
                if (ctx.rootT - move > box[5] || ctx.rootT + move < box[4]) {
                    return FAILED;
                }
            }
            u += du;
            v += dv;
            if (!(u >= box[0] && u <= box[1] && v >= box[2] && v <= box[3])) {
                return FAILED;
            }
        }
        return FAILED;
    }
}
