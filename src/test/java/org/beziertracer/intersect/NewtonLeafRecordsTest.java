package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.RationalDeCasteljau;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link NewtonLeafRecords}' enclosure R, the bound {@link NewtonSolver#start} rejects leaves
 * with, checked against the surface itself (the slow reference: points evaluated on the parent
 * patch) on the Newton method's own leaves of random patches of degree 1..15 (height fields,
 * folded "wild" nets, rational nets) and of the teapot, sampled up to the leaves' borders (so along
 * every border two teapot patches share): every point of a leaf lies within R of its
 * parallelogram, and a ray through any such point, from any direction down to grazing, is never
 * rejected. R is also no larger than the bound from the derivatives' balls, and several times
 * smaller on the teapot (what makes the start test reject more leaves).
 */
class NewtonLeafRecordsTest {

    /** Samples per leaf side, borders included. */
    private static final int GRID = 7;

    @Test
    void everyLeafPointLiesWithinROfItsParallelogramAndNoRayThroughItIsRejected() {
        Random rnd = new Random(20261202);
        int leaves = 0;
        for (List<BezierPatch> patches : models(rnd)) {
            SubPatchTable table = SubPatchTable.build(patches, NewtonRefinement.SPLIT);
            double tolerance = PatchLeaves.RELATIVE_TOLERANCE * new Scene(patches).controlBounds().diagonal();
            leaves += checkLeaves(table, NewtonLeafRecords.build(table), tolerance, rnd);
        }
        assertTrue(leaves > 3000, "leaves checked: " + leaves);
    }

    @Test
    void rIsNeverAboveTheBallBoundAndFarBelowItOnTheTeapot() {
        SubPatchTable table = SubPatchTable.build(Models.teapot().patches(), NewtonRefinement.SPLIT);
        double[] frame = new double[NewtonLeafRecords.STRIDE];
        double sumR = 0, sumBall = 0;
        for (int s = 0; s < table.count; s++) {
            NewtonLeafRecords.frame(table.nets, table.netOffset[s], table.degreeU[s], table.degreeV[s], false,
                    frame, 0);
            double ball = ballBound(frame, table.nets, table.netOffset[s]), r = frame[NewtonLeafRecords.R];
            assertTrue(r <= ball, "leaf " + s + ": R " + r + ", ball bound " + ball);
            sumR += r;
            sumBall += ball;
        }
        assertTrue(sumR < 0.5 * sumBall, "mean R " + sumR / table.count + " vs ball bound " + sumBall / table.count);
    }

    @Test
    void theFrameIsItsDefinitionToTheBit() {
        // A and B the middles of the ranges of the scaled control-point differences, RA and RB
        // the largest distances of those differences from them, R the control points' largest
        // distance from the parallelogram (or the ball bound, the smaller), computed the plain
        // way (Math.min / Math.max, a square root per point) on random nets of degree 1..15
        Random rnd = new Random(20261203);
        double[] frame = new double[NewtonLeafRecords.STRIDE];
        for (int trial = 0; trial < 300; trial++) {
            int n = 1 + rnd.nextInt(15), m = 1 + rnd.nextInt(15), row = 3 * (n + 1);
            double[] net = RandomPatches.wild(rnd, n, m, 1 + 10 * rnd.nextDouble()).copyNet();
            NewtonLeafRecords.frame(net, 0, n, m, false, frame, 0);
            double[] a = new double[3], b = new double[3];
            for (int c = 0; c < 3; c++) {
                double ulo = Double.POSITIVE_INFINITY, uhi = Double.NEGATIVE_INFINITY, vlo = ulo, vhi = uhi;
                for (int j = 0; j <= m; j++) {
                    for (int i = 0; i <= n; i++) {
                        int p = j * row + 3 * i + c;
                        if (i < n) {
                            ulo = Math.min(ulo, n * (net[p + 3] - net[p]));
                            uhi = Math.max(uhi, n * (net[p + 3] - net[p]));
                        }
                        if (j < m) {
                            vlo = Math.min(vlo, m * (net[p + row] - net[p]));
                            vhi = Math.max(vhi, m * (net[p + row] - net[p]));
                        }
                    }
                }
                a[c] = 0.5 * (ulo + uhi);
                b[c] = 0.5 * (vlo + vhi);
            }
            double ra = 0, rb = 0, hull = 0;
            for (int j = 0; j <= m; j++) {
                for (int i = 0; i <= n; i++) {
                    int p = j * row + 3 * i;
                    double su = 0, sv = 0, sh = 0;
                    for (int c = 0; c < 3; c++) {
                        double du = i < n ? n * (net[p + 3 + c] - net[p + c]) - a[c] : 0;
                        double dv = j < m ? m * (net[p + row + c] - net[p + c]) - b[c] : 0;
                        double dh = net[p + c] - (frame[NewtonLeafRecords.C + c] + ((double) i / n - 0.5) * a[c]
                                + ((double) j / m - 0.5) * b[c]);
                        su += du * du;
                        sv += dv * dv;
                        sh += dh * dh;
                    }
                    ra = Math.max(ra, Math.sqrt(su));
                    rb = Math.max(rb, Math.sqrt(sv));
                    hull = Math.max(hull, Math.sqrt(sh));
                }
            }
            String net_ = "net " + trial + " (" + n + "x" + m + ")";
            for (int c = 0; c < 3; c++) {
                assertEquals(a[c], frame[NewtonLeafRecords.A + c], 0, net_);
                assertEquals(b[c], frame[NewtonLeafRecords.B + c], 0, net_);
            }
            assertEquals(ra, frame[NewtonLeafRecords.RA], 0, net_);
            assertEquals(rb, frame[NewtonLeafRecords.RB], 0, net_);
            assertEquals(Math.min(hull, ballBound(frame, net, 0)), frame[NewtonLeafRecords.R], 0, net_);
        }
    }

    /** The bound from the derivative balls alone: |C − (A+B)/2 − P00| + RA + RB. */
    private static double ballBound(double[] frame, double[] net, int off) {
        double sq = 0;
        for (int c = 0; c < 3; c++) {
            double e = frame[NewtonLeafRecords.C + c]
                    - 0.5 * (frame[NewtonLeafRecords.A + c] + frame[NewtonLeafRecords.B + c]) - net[off + c];
            sq += e * e;
        }
        return Math.sqrt(sq) + frame[NewtonLeafRecords.RA] + frame[NewtonLeafRecords.RB];
    }

    /** The teapot, then per degree 1..15 a height field, a folded net and a rational folded net. */
    private static List<List<BezierPatch>> models(Random rnd) {
        List<List<BezierPatch>> models = new ArrayList<>();
        models.add(Models.teapot().patches());
        for (int degree = 1; degree <= 15; degree++) {
            models.add(List.of(RandomPatches.heightField(rnd, degree, degree, 4, 0.8)));
            models.add(List.of(RandomPatches.wild(rnd, degree, Math.max(1, degree - 1), 2)));
            BezierPatch wild = RandomPatches.wild(rnd, degree, degree, 2);
            double[] weights = new double[(degree + 1) * (degree + 1)];
            for (int i = 0; i < weights.length; i++) {
                weights[i] = 0.2 + 4 * rnd.nextDouble();
            }
            models.add(List.of(new BezierPatch(degree, degree, wild.copyNet(), weights, null, null)));
        }
        return models;
    }

    /** Checks every leaf of {@code table} on a grid of its points; returns the number of leaves. */
    private static int checkLeaves(SubPatchTable table, float[] rec, double tolerance, Random rnd) {
        TraceContext ctx = new TraceContext();
        double[] e = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int s = 0; s < table.count; s++) {
            int o = NewtonLeafRecords.STRIDE * s, k = table.parent[s];
            double r = rec[o + NewtonLeafRecords.R];
            for (int a = 0; a < GRID; a++) {
                for (int b = 0; b < GRID; b++) {
                    double u = rec[o + NewtonLeafRecords.U0] + rec[o + NewtonLeafRecords.DU] * a / (GRID - 1);
                    double v = rec[o + NewtonLeafRecords.V0] + rec[o + NewtonLeafRecords.DV] * b / (GRID - 1);
                    RationalDeCasteljau.pointAndDerivatives(table.patchNets, table.patchNetOffset[k],
                            table.patchDegreeU[k], table.patchDegreeV[k], table.patchDim[k], u, v, e, scratch);
                    double d = distanceToParallelogram(e, rec, o);
                    assertTrue(d <= r, "leaf " + s + " point (" + u + ", " + v + ") " + d
                            + " from its parallelogram, R " + r);
                    for (int ray = 0; ray < 3; ray++) {
                        aimThrough(ctx, e, rnd); // the point is at t = 1
                        int kind = NewtonSolver.start(ctx, rec, o, 1 - 1e-9, 1 + 1e-9, tolerance);
                        assertNotEquals(NewtonSolver.MISS, kind,
                                "leaf " + s + " rejected a ray through its point (" + u + ", " + v + ")");
                    }
                }
            }
        }
        return table.count;
    }

    /**
     * A ray through the point of {@code e} (S, Su, Sv): the normal tilted by up to 89.99° toward
     * a random tangent direction, or a random direction, starting a distance 1..100 before it.
     */
    private static void aimThrough(TraceContext ctx, double[] e, Random rnd) {
        double nx = e[4] * e[8] - e[5] * e[7], ny = e[5] * e[6] - e[3] * e[8], nz = e[3] * e[7] - e[4] * e[6];
        double nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double dx, dy, dz;
        if (nl > 0 && rnd.nextBoolean()) {
            double a = rnd.nextDouble(), b = rnd.nextDouble() - 0.5;
            double tx = a * e[3] + b * e[6], ty = a * e[4] + b * e[7], tz = a * e[5] + b * e[8];
            double tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
            double tilt = Math.toRadians(89.99) * Math.sqrt(rnd.nextDouble());
            double c = Math.cos(tilt), w = tl > 0 ? Math.sin(tilt) / tl : 0;
            dx = c * nx / nl + w * tx;
            dy = c * ny / nl + w * ty;
            dz = c * nz / nl + w * tz;
        } else {
            dx = rnd.nextGaussian();
            dy = rnd.nextGaussian();
            dz = rnd.nextGaussian();
        }
        double scale = 1 + 99 * rnd.nextDouble();
        ctx.setRay(e[0] - scale * dx, e[1] - scale * dy, e[2] - scale * dz, scale * dx, scale * dy, scale * dz);
    }

    /** Distance from {@code p[0..3)} to the parallelogram C + (s−½)A + (t−½)B, s, t in [0,1], of record o. */
    static double distanceToParallelogram(double[] p, float[] rec, int o) {
        double[] c = new double[3], a = new double[3], b = new double[3], q = new double[3];
        for (int i = 0; i < 3; i++) {
            a[i] = rec[o + NewtonLeafRecords.A + i];
            b[i] = rec[o + NewtonLeafRecords.B + i];
            c[i] = rec[o + NewtonLeafRecords.C + i] - 0.5 * (a[i] + b[i]); // corner (0,0)
            q[i] = p[i] - c[i];
        }
        double aa = dot(a, a), ab = dot(a, b), bb = dot(b, b), qa = dot(q, a), qb = dot(q, b);
        double det = aa * bb - ab * ab, best = Double.POSITIVE_INFINITY;
        if (det > 1e-12 * aa * bb) {
            double s = (qa * bb - qb * ab) / det, t = (qb * aa - qa * ab) / det;
            if (s >= 0 && s <= 1 && t >= 0 && t <= 1) {
                best = distance(q, a, b, s, t);
            }
        }
        // the nearest point of each edge
        for (int edge = 0; edge < 4; edge++) {
            boolean alongA = edge < 2;
            double fixed = edge % 2;
            double[] dir = alongA ? a : b, other = alongA ? b : a;
            double len2 = dot(dir, dir), x = 0;
            if (len2 > 0) {
                double[] r = new double[3];
                for (int i = 0; i < 3; i++) {
                    r[i] = q[i] - fixed * other[i];
                }
                x = Math.min(1, Math.max(0, dot(r, dir) / len2));
            }
            best = Math.min(best, alongA ? distance(q, a, b, x, fixed) : distance(q, a, b, fixed, x));
        }
        return best;
    }

    private static double distance(double[] q, double[] a, double[] b, double s, double t) {
        double sq = 0;
        for (int i = 0; i < 3; i++) {
            double d = q[i] - s * a[i] - t * b[i];
            sq += d * d;
        }
        return Math.sqrt(sq);
    }

    private static double dot(double[] x, double[] y) {
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    }
}
