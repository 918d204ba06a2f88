package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * {@link SecondDerivatives} and {@link SurfaceCurvature}: second derivatives against finite
 * differences of the first (de Casteljau's), for random polynomial and rational nets of degree
 * 1..15; K and H against an independent formula (the second fundamental form from the
 * derivatives of the unit normal); and the closed forms of a sphere, a torus, a saddle and a
 * cylinder, at their poles too.
 */
class SurfaceCurvatureTest {

    private static final double[] SCRATCH = new double[Math.max(SurfaceCurvature.SCRATCH, 4096)];

    /** S, S_u, S_v by de Casteljau (Euclidean), the reference for the first derivatives. */
    private static void firstDerivatives(double[] net, int n, int m, int dim, double u, double v, double[] out) {
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH + 1024];
        if (dim == 4) {
            RationalDeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, out, 0, scratch, 0);
        } else {
            DeCasteljau.evaluateWithDerivatives(net, 0, n, m, 3, u, v, out, 0, scratch, 0);
        }
    }

    private static double[] randomHomogeneous(Random rnd, int n, int m) {
        double[] net = TestNets.randomNet(rnd, n, m, 4, 1);
        for (int k = 0; k < net.length; k += 4) {
            double w = 0.5 + 1.5 * rnd.nextDouble();
            for (int c = 0; c < 3; c++) {
                net[k + c] *= w;
            }
            net[k + 3] = w;
        }
        return net;
    }

    @Test
    void secondDerivativesMatchFiniteDifferencesOfTheFirstForEveryDegree() {
        Random rnd = new Random(33_001);
        double[] d = new double[SecondDerivatives.LENGTH], ref = new double[9], plus = new double[9], minus = new double[9];
        for (int trial = 0; trial < 300; trial++) {
            int n = TestNets.randomDegree(rnd), m = TestNets.randomDegree(rnd), dim = trial % 2 == 0 ? 3 : 4;
            double[] net = dim == 3 ? TestNets.randomNet(rnd, n, m, 3, 1) : randomHomogeneous(rnd, n, m);
            double u = 0.05 + 0.9 * rnd.nextDouble(), v = 0.05 + 0.9 * rnd.nextDouble();
            SecondDerivatives.evaluate(net, 0, n, m, dim, u, v, d, SCRATCH);
            firstDerivatives(net, n, m, dim, u, v, ref);
            String where = "degree " + n + "x" + m + (dim == 4 ? " rational" : "") + " at (" + u + ", " + v + ")";
            double firstScale = 1;
            for (int c = 0; c < 9; c++) {
                firstScale = Math.max(firstScale, Math.abs(ref[c]));
            }
            for (int c = 0; c < 9; c++) {
                assertEquals(ref[c], d[c], 1e-11 * firstScale, where + ": S/S_u/S_v component " + c);
            }
            // S_uu, S_uv from d/du of S_u and S_v; S_vv from d/dv of S_v: the best of a step sweep
            double[] best = new double[9];
            java.util.Arrays.fill(best, Double.POSITIVE_INFINITY);
            double secondScale = 1;
            for (int c = 9; c < 18; c++) {
                secondScale = Math.max(secondScale, Math.abs(d[c]));
            }
            for (double h : new double[] {1e-3, 3e-4, 1e-4, 3e-5, 1e-5}) {
                firstDerivatives(net, n, m, dim, u + h, v, plus);
                firstDerivatives(net, n, m, dim, u - h, v, minus);
                for (int c = 0; c < 3; c++) {
                    best[c] = Math.min(best[c], Math.abs((plus[3 + c] - minus[3 + c]) / (2 * h) - d[9 + c]));
                    best[3 + c] = Math.min(best[3 + c], Math.abs((plus[6 + c] - minus[6 + c]) / (2 * h) - d[12 + c]));
                }
                firstDerivatives(net, n, m, dim, u, v + h, plus);
                firstDerivatives(net, n, m, dim, u, v - h, minus);
                for (int c = 0; c < 3; c++) {
                    best[6 + c] = Math.min(best[6 + c], Math.abs((plus[6 + c] - minus[6 + c]) / (2 * h) - d[15 + c]));
                }
            }
            for (int c = 0; c < 9; c++) {
                assertTrue(best[c] <= 1e-6 * secondScale, where + ": second derivative " + c + " off by " + best[c]
                        + " (scale " + secondScale + ")");
            }
        }
    }

    @Test
    void gaussianAndMeanCurvatureAgreeWithTheDerivativesOfTheUnitNormal() {
        Random rnd = new Random(33_002);
        double[] out = new double[SurfaceCurvature.LENGTH], d = new double[9];
        double[] nup = new double[3], num = new double[3], nvp = new double[3], nvm = new double[3];
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int checked = 0;
        for (int trial = 0; trial < 200; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            double[] net = TestNets.randomNet(rnd, n, m, 3, 1);
            double u = 0.1 + 0.8 * rnd.nextDouble(), v = 0.1 + 0.8 * rnd.nextDouble(), h = 1e-5;
            DeCasteljau.evaluateWithDerivatives(net, 0, n, m, 3, u, v, d, 0, scratch, 0);
            double ux = d[3], uy = d[4], uz = d[5], vx = d[6], vy = d[7], vz = d[8];
            double cross = Math.sqrt(Math.pow(uy * vz - uz * vy, 2) + Math.pow(uz * vx - ux * vz, 2) + Math.pow(ux * vy - uy * vx, 2));
            if (cross < 1e-2) {
                continue; // near-degenerate: finite differences of the normal are not a fair reference
            }
            SurfaceCurvature.at(net, 0, n, m, 3, u, v, out, SCRATCH);
            PatchNormals.unitNormal(net, 0, n, m, u + h, v, nup, 0, scratch);
            PatchNormals.unitNormal(net, 0, n, m, u - h, v, num, 0, scratch);
            PatchNormals.unitNormal(net, 0, n, m, u, v + h, nvp, 0, scratch);
            PatchNormals.unitNormal(net, 0, n, m, u, v - h, nvm, 0, scratch);
            double l = 0, mm = 0, nn = 0;
            for (int c = 0; c < 3; c++) {
                double nu = (nup[c] - num[c]) / (2 * h), nv = (nvp[c] - nvm[c]) / (2 * h);
                l -= d[3 + c] * nu;
                mm -= 0.5 * (d[3 + c] * nv + d[6 + c] * nu);
                nn -= d[6 + c] * nv;
            }
            double e = ux * ux + uy * uy + uz * uz, f = ux * vx + uy * vy + uz * vz, g = vx * vx + vy * vy + vz * vz;
            double det = e * g - f * f;
            double k = (l * nn - mm * mm) / det, hm = (e * nn - 2 * f * mm + g * l) / (2 * det);
            double scale = 1 + Math.abs(out[SurfaceCurvature.K1]) + Math.abs(out[SurfaceCurvature.K2]);
            String where = "degree " + n + "x" + m + " at (" + u + ", " + v + ")";
            assertEquals(k, out[SurfaceCurvature.GAUSSIAN], 1e-4 * scale * scale, where + ": K");
            assertEquals(hm, out[SurfaceCurvature.MEAN], 1e-4 * scale, where + ": H");
            assertEquals(out[SurfaceCurvature.GAUSSIAN], out[SurfaceCurvature.K1] * out[SurfaceCurvature.K2],
                    1e-9 * scale * scale, where + ": K = k1 k2");
            assertTrue(out[SurfaceCurvature.K1] >= out[SurfaceCurvature.K2], where + ": k1 ≥ k2");
            assertPrincipalFrame(out, where);
            checked++;
        }
        assertTrue(checked > 100, "enough well-conditioned points: " + checked);
    }

    /** d1, d2, n orthonormal. */
    static void assertPrincipalFrame(double[] out, String where) {
        int[] at = {SurfaceCurvature.D1, SurfaceCurvature.D2, SurfaceCurvature.NORMAL};
        for (int a = 0; a < 3; a++) {
            for (int b = a; b < 3; b++) {
                double dot = 0;
                for (int c = 0; c < 3; c++) {
                    dot += out[at[a] + c] * out[at[b] + c];
                }
                assertEquals(a == b ? 1 : 0, dot, 1e-9, where + ": frame vectors " + a + "·" + b);
            }
        }
    }

    private static double[] curvatureOf(BezierPatch p, double u, double v) {
        double[] net = Patches.workingNet(p), out = new double[SurfaceCurvature.LENGTH];
        SurfaceCurvature.at(net, 0, p.degreeU(), p.degreeV(), Patches.dim(p), u, v, out, SCRATCH);
        return out;
    }

    /** Parameters checked on each piece: its edges (the sphere's poles), near them, inside. */
    private static final double[] PARAMS = {0, 1e-6, 0.1, 0.37, 0.5, 0.81, 1 - 1e-6, 1};

    @Test
    void theUnitSphereHasKOneAndHMinusOneEverywhereItsPolesIncluded() {
        List<BezierPatch> sphere = Models.sphere().patches();
        for (int k = 0; k < sphere.size(); k++) {
            for (double u : PARAMS) {
                for (double v : PARAMS) {
                    double[] c = curvatureOf(sphere.get(k), u, v);
                    String where = "piece " + k + " at (" + u + ", " + v + ")";
                    assertEquals(1, c[SurfaceCurvature.GAUSSIAN], 1e-9, where + ": K");
                    assertEquals(1, Math.abs(c[SurfaceCurvature.MEAN]), 1e-9, where + ": |H|");
                    assertEquals(c[SurfaceCurvature.K1], c[SurfaceCurvature.K2], 1e-9, where + ": umbilic");
                    assertPrincipalFrame(c, where);
                }
            }
        }
    }

    @Test
    void theTorusHasItsClosedFormGaussianCurvature() {
        double big = 1, small = 0.35;
        double[] e = new double[4], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (BezierPatch p : Models.torus().patches()) {
            double[] net = Patches.workingNet(p);
            for (double u : PARAMS) {
                for (double v : PARAMS) {
                    DeCasteljau.evaluate(net, 0, p.degreeU(), p.degreeV(), 4, u, v, e, 0, scratch);
                    double x = e[0] / e[3], y = e[1] / e[3];
                    double rho = Math.hypot(x, y);
                    // K = cos φ / (r (R + r cos φ)), with R + r cos φ = ρ
                    double expected = (rho - big) / (small * small * rho);
                    double[] c = curvatureOf(p, u, v);
                    assertEquals(expected, c[SurfaceCurvature.GAUSSIAN], 1e-9 * (1 + Math.abs(expected)),
                            "torus at (" + u + ", " + v + ")");
                }
            }
        }
    }

    @Test
    void theSaddleZEqualsXyHasKMinusOneAtTheOrigin() {
        BezierPatch saddle = new BezierPatch(1, 1, new double[] {-1, -1, 1, 1, -1, -1, -1, 1, -1, 1, 1, 1});
        double[] c = curvatureOf(saddle, 0.5, 0.5);
        assertEquals(-1, c[SurfaceCurvature.GAUSSIAN], 1e-12);
        assertEquals(0, c[SurfaceCurvature.MEAN], 1e-12);
        assertEquals(1, c[SurfaceCurvature.K1], 1e-12);
        assertEquals(-1, c[SurfaceCurvature.K2], 1e-12);
        // away from the origin K = −1 / (1 + x² + y²)²; at (u, v) = (0.75, 0.25): x = 0.5, y = −0.5
        assertEquals(-1 / Math.pow(1.5, 2), curvatureOf(saddle, 0.75, 0.25)[SurfaceCurvature.GAUSSIAN], 1e-12);
    }

    @Test
    void aCylinderOfRadiusTwoHasKZeroAndHOneQuarter() {
        double r = 2, hw = Math.sqrt(0.5);
        // a quarter circle (rational quadratic) in u, a straight line of height 3 in v
        double[] net = {r, 0, 0, r, r, 0, 0, r, 0, r, 0, 3, r, r, 3, 0, r, 3};
        double[] weights = {1, hw, 1, 1, hw, 1};
        BezierPatch cylinder = new BezierPatch(2, 1, net, weights, null, null);
        for (double u : PARAMS) {
            for (double v : PARAMS) {
                double[] c = curvatureOf(cylinder, u, v);
                String where = "cylinder at (" + u + ", " + v + ")";
                assertEquals(0, c[SurfaceCurvature.GAUSSIAN], 1e-12, where + ": K");
                assertEquals(1 / (2 * r), Math.abs(c[SurfaceCurvature.MEAN]), 1e-12, where + ": |H|");
                // the bending direction is around the axis: d of the non-zero curvature ⊥ z
                int bent = Math.abs(c[SurfaceCurvature.K1]) > Math.abs(c[SurfaceCurvature.K2]) ? SurfaceCurvature.D1
                        : SurfaceCurvature.D2;
                assertEquals(0, c[bent + 2], 1e-9, where + ": the curved direction runs around the axis");
            }
        }
    }
}
