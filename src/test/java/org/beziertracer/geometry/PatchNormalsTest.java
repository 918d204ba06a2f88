package org.beziertracer.geometry;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

class PatchNormalsTest {

    /** Minimum cosine between a normal and those of its regular neighbours. */
    private static final double NEIGHBOUR_COS = 0.9;
    /** Parameter distance of the "neighbouring regular points". */
    private static final double NEIGHBOUR_STEP = 0.02;
    /** Finer neighbour distance for the whole-teapot grid (the spout tip is sharply curved). */
    private static final double FINE_NEIGHBOUR_STEP = 0.005;
    /** Agreement with the plain normalised cross product at regular points. */
    private static final double REGULAR_TOL = 1e-14;
    /** Cosine the teapot lid-top normal must reach with the vertical. */
    private static final double APEX_COS = 1 - 1e-9;

    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];

    private double[] normal(double[] net, int n, int m, double u, double v) {
        double[] out = new double[3];
        PatchNormals.unitNormal(net, 0, n, m, u, v, out, 0, scratch);
        return out;
    }

    /** Plain normalised S_u × S_v (NaN where it vanishes). */
    private double[] crossNormal(double[] net, int n, int m, double u, double v) {
        double[] d = new double[9];
        DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, d, scratch);
        double x = d[4] * d[8] - d[5] * d[7], y = d[5] * d[6] - d[3] * d[8], z = d[3] * d[7] - d[4] * d[6];
        double len = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / len, y / len, z / len};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static void assertFiniteUnit(double[] nrm, String where) {
        assertTrue(Double.isFinite(nrm[0]) && Double.isFinite(nrm[1]) && Double.isFinite(nrm[2]),
                where + ": not finite " + Arrays.toString(nrm));
        assertEquals(1, Math.sqrt(dot(nrm, nrm)), ROUNDING, where + ": not unit " + Arrays.toString(nrm));
    }

    /**
     * The normal at (u,v) is finite, unit, and within {@link #NEIGHBOUR_COS} of the plain
     * normals at regular points a step inward in u, in v and diagonally.
     */
    private void assertConsistentWithNeighbours(double[] net, int n, int m, double u, double v, String what) {
        assertConsistentWithNeighbours(net, n, m, u, v, NEIGHBOUR_STEP, what);
    }

    private void assertConsistentWithNeighbours(double[] net, int n, int m, double u, double v, double step,
                                                String what) {
        double[] nrm = normal(net, n, m, u, v);
        String where = what + " at (" + u + "," + v + ")";
        assertFiniteUnit(nrm, where);
        double du = u < 0.5 ? step : -step, dv = v < 0.5 ? step : -step;
        double[][] near = {{u + du, v + dv}, {u, v + dv}, {u + du, v}};
        for (double[] q : near) {
            double[] ref = crossNormal(net, n, m, q[0], q[1]);
            if (!Double.isFinite(ref[0])) {
                continue;   // the neighbour lies on the degenerate edge too
            }
            double cos = dot(nrm, ref);
            assertTrue(cos > NEIGHBOUR_COS, where + ": normal " + Arrays.toString(nrm) + " vs neighbour ("
                    + q[0] + "," + q[1] + ") " + Arrays.toString(ref) + ", cos " + cos);
        }
    }

    /** Flat unit square in the xy plane, u along +x, v along +y, degree n×m. */
    private static double[] flatSquare(int n, int m) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                net[k] = (double) i / n;
                net[k + 1] = (double) j / m;
            }
        }
        return net;
    }

    @Test
    void aFlatSquareHasNormalPlusZOrientedAsDpduCrossDpdv() {
        double[] net = flatSquare(3, 2);
        assertEquals(1, normal(net, 3, 2, 0.3, 0.6)[2], ROUNDING);
        // Reversing u reverses dS/du and so the normal
        double[] mirrored = net.clone();
        for (int k = 0; k < mirrored.length; k += 3) {
            mirrored[k] = 1 - mirrored[k];
        }
        assertEquals(-1, normal(mirrored, 3, 2, 0.3, 0.6)[2], ROUNDING);
    }

    @Test
    void atRegularPointsTheNormalIsTheNormalisedCrossProduct() {
        Random rnd = new Random(21);
        for (int trial = 0; trial < 200; trial++) {
            int n = TestNets.randomDegree(rnd), m = TestNets.randomDegree(rnd);
            double[] net = TestNets.randomNet(rnd, n, m, 3, 10);
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            double[] expected = crossNormal(net, n, m, u, v), actual = normal(net, n, m, u, v);
            double err = TestNets.maxDiff(expected, actual);
            assertTrue(err <= REGULAR_TOL * 1e3 || !Double.isFinite(expected[0]),
                    "degree " + n + "x" + m + " at (" + u + "," + v + "): " + Arrays.toString(expected) + " vs "
                            + Arrays.toString(actual));
        }
    }

    @Test
    void theTeapotLidTopHasAVerticalNormalAgreeingWithItsNeighbours() {
        List<BezierPatch> teapot = TestNets.teapot();
        int collapsedEdges = 0;
        for (int p = 0; p < teapot.size(); p++) {
            BezierPatch patch = teapot.get(p);
            int n = patch.degreeU(), m = patch.degreeV();
            double[] net = patch.copyNet();
            // Rows v=0 and v=1, columns u=0 and u=1 that collapse to a single point
            for (int edge = 0; edge < 4; edge++) {
                if (!edgeCollapses(net, n, m, edge)) {
                    continue;
                }
                collapsedEdges++;
                for (int s = 0; s <= 16; s++) {
                    double t = s / 16.0;
                    double u = edge < 2 ? t : edge - 2, v = edge < 2 ? edge : t;
                    assertConsistentWithNeighbours(net, n, m, u, v, "teapot patch " + p + " edge " + edge);
                    double[] nrm = normal(net, n, m, u, v);
                    // The lid top is a smooth pole: the limit normal is vertical
                    assertTrue(Math.abs(nrm[2]) > APEX_COS, "teapot patch " + p + " apex normal at (" + u + "," + v
                            + ") not vertical: " + Arrays.toString(nrm));
                }
            }
        }
        assertEquals(4, collapsedEdges, "the four lid-top patches (28-31) collapse one edge each to (0,0,120)");
    }

    @Test
    void everyTeapotNormalIsFiniteUnitAndAgreesWithItsNeighbours() {
        // Covers the lid knob, whose control row at z=108 collapses to a point, the spout tip
        // and the handle, on a fine grid including all four edges
        List<BezierPatch> teapot = TestNets.teapot();
        for (int p = 0; p < teapot.size(); p++) {
            BezierPatch patch = teapot.get(p);
            double[] net = patch.copyNet();
            for (int b = 0; b <= 20; b++) {
                for (int a = 0; a <= 20; a++) {
                    assertConsistentWithNeighbours(net, patch.degreeU(), patch.degreeV(), a / 20.0, b / 20.0,
                            FINE_NEIGHBOUR_STEP, "teapot patch " + p);
                }
            }
        }
    }

    private static boolean edgeCollapses(double[] net, int n, int m, int edge) {
        int count = edge < 2 ? n + 1 : m + 1;
        int first = index(n, m, edge, 0);
        for (int k = 1; k < count; k++) {
            int q = index(n, m, edge, k);
            for (int c = 0; c < 3; c++) {
                if (net[q + c] != net[first + c]) {
                    return false;
                }
            }
        }
        return true;
    }

    /** Offset of the k-th control point on edge 0 (v=0), 1 (v=1), 2 (u=0) or 3 (u=1). */
    private static int index(int n, int m, int edge, int k) {
        int i = edge == 2 ? 0 : edge == 3 ? n : k, j = edge == 0 ? 0 : edge == 1 ? m : k;
        return 3 * (j * (n + 1) + i);
    }

    /**
     * A wavy height-field sector over the quarter disc: row j=0 collapses to the apex, rows
     * j≥1 lie on arcs of radius j/m; heights are small random bumps.
     */
    private static double[] collapsedSector(Random rnd, int n, int m) {
        double[] net = new double[(n + 1) * (m + 1) * 3];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                double theta = 0.5 * Math.PI * i / n, r = (double) j / m;
                net[k] = r * Math.cos(theta);
                net[k + 1] = r * Math.sin(theta);
                net[k + 2] = j == 0 ? 0.3 : 0.3 + 0.1 * (2 * rnd.nextDouble() - 1) * r;
            }
        }
        return net;
    }

    @Test
    void aPatchWithAnEdgeCollapsedToAPointGetsTheLimitNormal() {
        Random rnd = new Random(22);
        for (int trial = 0; trial < 30; trial++) {
            int n = 2 + rnd.nextInt(8), m = 2 + rnd.nextInt(8);
            double[] net = collapsedSector(rnd, n, m);
            for (int s = 0; s <= 10; s++) {
                assertConsistentWithNeighbours(net, n, m, s / 10.0, 0, "collapsed sector " + n + "x" + m + " trial " + trial);
            }
        }
    }

    @Test
    void aPatchWithAVanishingTangentAlongAnEdgeGetsFiniteConsistentNormals() {
        Random rnd = new Random(23);
        for (int trial = 0; trial < 30; trial++) {
            int n = 2 + rnd.nextInt(8), m = 1 + rnd.nextInt(8);
            double[] net = flatSquare(n, m);
            for (int k = 2; k < net.length; k += 3) {
                net[k] = 0.05 * (2 * rnd.nextDouble() - 1);
            }
            // P_1j = P_0j for every j: dS/du vanishes along the whole edge u = 0
            for (int j = 0; j <= m; j++) {
                System.arraycopy(net, 3 * (j * (n + 1)), net, 3 * (j * (n + 1) + 1), 3);
            }
            for (int s = 0; s <= 10; s++) {
                String what = "vanishing-tangent patch " + n + "x" + m + " trial " + trial;
                assertConsistentWithNeighbours(net, n, m, 0, s / 10.0, what);
                assertTrue(normal(net, n, m, 0, s / 10.0)[2] > 0, what + ": normal should point up, like dS/du x dS/dv");
            }
        }
    }

    @Test
    void aPatchCollapsedToALineOrAPointStillGetsAFiniteUnitNormal() {
        double[] point = new double[4 * 4 * 3];
        Arrays.fill(point, 2.5);
        assertFiniteUnit(normal(point, 3, 3, 0.5, 0.5), "patch collapsed to a point");
        double[] line = new double[3 * 2 * 3];
        for (int k = 0; k < 6; k++) {
            line[3 * k] = k % 3;   // all points on the x axis
        }
        assertFiniteUnit(normal(line, 2, 1, 0, 1), "patch collapsed to a line");
        assertFiniteUnit(normal(line, 2, 1, 0.5, 0.5), "patch collapsed to a line, centre");
    }

    @Test
    void theOverloadTakingDerivativesAgreesWithTheEvaluatingOne() {
        java.util.Random rnd = new java.util.Random(77);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH], e = new double[9], a = new double[3], b = new double[3];
        for (int trial = 0; trial < 200; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            double[] net = new double[(n + 1) * (m + 1) * 3];
            for (int k = 0; k < net.length; k++) {
                net[k] = rnd.nextDouble();
            }
            if (trial % 4 == 0) { // collapse the v=0 edge to a point
                for (int i = 1; i <= n; i++) {
                    System.arraycopy(net, 0, net, 3 * i, 3);
                }
            }
            double u = trial % 4 == 0 ? rnd.nextDouble() : rnd.nextDouble(), v = trial % 4 == 0 ? 0 : rnd.nextDouble();
            DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, e, scratch);
            PatchNormals.unitNormal(net, 0, n, m, u, v, a, 0, scratch);
            PatchNormals.unitNormal(net, 0, n, m, u, v, e, b, 0, scratch);
            for (int c = 0; c < 3; c++) {
                assertEquals(a[c], b[c], ROUNDING, "trial " + trial + " degree " + n + "x" + m + " (u,v)=(" + u + "," + v + ")");
            }
        }
    }

    @Test
    void squaredExtentIsTheLargestSideOfTheControlBoxSquared() {
        Random rnd = new Random(91);
        for (int trial = 0; trial < 100; trial++) {
            int n = 1 + rnd.nextInt(7), m = 1 + rnd.nextInt(7), off = 3 * rnd.nextInt(3);
            double[] net = new double[off + (n + 1) * (m + 1) * 3 + 6];
            Arrays.fill(net, 1e6);   // padding that must not count
            double[] side = {rnd.nextDouble() * 4, rnd.nextDouble() * 4, rnd.nextDouble() * 4};
            double[] lo = new double[3], hi = new double[3];
            Arrays.fill(lo, Double.POSITIVE_INFINITY);
            Arrays.fill(hi, Double.NEGATIVE_INFINITY);
            for (int k = 0; k < (n + 1) * (m + 1); k++) {
                for (int c = 0; c < 3; c++) {
                    double x = side[c] * (2 * rnd.nextDouble() - 1) - 5;
                    net[off + 3 * k + c] = x;
                    lo[c] = Math.min(lo[c], x);
                    hi[c] = Math.max(hi[c], x);
                }
            }
            double ext = Math.max(hi[0] - lo[0], Math.max(hi[1] - lo[1], hi[2] - lo[2]));
            assertEquals(ext * ext, PatchNormals.squaredExtent(net, off, n, m), ROUNDING * ext * ext,
                    "degree " + n + "x" + m + " offset " + off);
        }
    }

    @Test
    void theLastFallbackIsTheNormalOfTheNetDiagonalsElsePlusZ() {
        Random rnd = new Random(92);
        for (int trial = 0; trial < 50; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6), off = 3 * rnd.nextInt(4);
            double[] net = new double[off + (n + 1) * (m + 1) * 3];
            for (int k = off; k < net.length; k++) {
                net[k] = 2 * rnd.nextDouble() - 1;
            }
            int p00 = off, pn0 = off + 3 * n, p0m = off + 3 * m * (n + 1), pnm = p0m + 3 * n;
            double[] a = new double[3], b = new double[3];
            for (int c = 0; c < 3; c++) {
                a[c] = net[pnm + c] - net[p00 + c];
                b[c] = net[p0m + c] - net[pn0 + c];
            }
            double[] cross = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
            double len = Math.sqrt(dot(cross, cross));
            double[] out = new double[5];
            PatchNormals.netNormal(net, off, n, m, out, 2);
            for (int c = 0; c < 3; c++) {
                assertEquals(cross[c] / len, out[2 + c], ROUNDING, "degree " + n + "x" + m + " offset " + off);
            }
        }
        double[] line = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};   // 1x1 net on the x axis: diagonals parallel
        double[] out = new double[3];
        PatchNormals.netNormal(line, 0, 1, 1, out, 0);
        assertArrayEquals(new double[] {0, 0, 1}, out, 0);
    }

    @Test
    void aCrossProductBelowTheDegreeScaledThresholdCountsAsDegenerate() {
        // Flat unit square, bicubic, but its v=0 row is squeezed to the point (0.5,0,0) and then
        // fanned out along z by eps, all scaled by 2: at v=0 the cross product lies between
        // DEGENERATE_RELATIVE·L² and DEGENERATE_RELATIVE·n·m·L², and points along x.
        double eps = 1.25e-10;
        double[] net = flatSquare(3, 3);
        for (int i = 0; i <= 3; i++) {
            net[3 * i] = 0.5;
            net[3 * i + 2] = eps * i;
        }
        for (int k = 0; k < net.length; k++) {
            net[k] *= 2;   // extent 2, so that the threshold's L² is not 1
        }
        double[] d = new double[9], viaDerivatives = new double[3];
        DeCasteljau.evaluateWithDerivatives(net, 0, 3, 3, 0.3, 0, d, scratch);
        double[] crossAtEdge = {d[4] * d[8] - d[5] * d[7], d[5] * d[6] - d[3] * d[8], d[3] * d[7] - d[4] * d[6]};
        double len = Math.sqrt(dot(crossAtEdge, crossAtEdge));
        double ext2 = PatchNormals.squaredExtent(net, 0, 3, 3);
        assertTrue(len > PatchNormals.DEGENERATE_RELATIVE * ext2 && len < PatchNormals.DEGENERATE_RELATIVE * 9 * ext2,
                "set-up: |cross| = " + len);
        double[] nrm = normal(net, 3, 3, 0.3, 0);
        assertTrue(nrm[2] > 0.99, "the limit normal of the squeezed edge is +z, got " + Arrays.toString(nrm));
        PatchNormals.unitNormal(net, 0, 3, 3, 0.3, 0, d, viaDerivatives, 0, scratch);
        assertArrayEquals(nrm, viaDerivatives, ROUNDING, "overload taking the derivatives");
    }

    @Test
    void aDegenerateCentreStepsTowardAnInteriorPointNotTheDiagonalFallback() {
        // S(u,v) = (x(u), v, z(v)) with x' = 3(1-2u)^2: S_u vanishes on the line u = 1/2 only.
        double[] xs = {0, 1, 0, 1}, zs = {0, 0.3, 0.1, 0.5};
        double[] net = new double[16 * 3];
        for (int j = 0; j <= 3; j++) {
            for (int i = 0; i <= 3; i++) {
                int k = 3 * (j * 4 + i);
                net[k] = xs[i];
                net[k + 1] = j / 3.0;
                net[k + 2] = zs[j];
            }
        }
        double dz = 3 * (0.25 * 0.3 + 0.5 * -0.2 + 0.25 * 0.4);   // z'(1/2); y' = 1
        double len = Math.sqrt(1 + dz * dz);
        double[] expected = {0, -dz / len, 1 / len};
        double[] nrm = normal(net, 3, 3, 0.5, 0.5);
        assertArrayEquals(expected, nrm, 1e-3, "limit normal at the centre, got " + Arrays.toString(nrm));
    }

    @Test
    void anEdgeCollapsedOnAnyOfTheFourSidesGetsTheNormalOfItsInnerNeighbours() {
        Random rnd = new Random(93);
        for (int trial = 0; trial < 24; trial++) {
            int n = 2 + rnd.nextInt(5), m = 2 + rnd.nextInt(5), edge = trial % 4;
            double[] net = flatSquare(n, m);
            for (int k = 2; k < net.length; k += 3) {
                net[k] = 0.05 * (2 * rnd.nextDouble() - 1);
            }
            int count = edge < 2 ? n : m;
            int apex = index(n, m, edge, count / 2);
            for (int k = 0; k <= count; k++) {
                System.arraycopy(net, apex, net, index(n, m, edge, k), 3);
            }
            for (int s = 1; s < 10; s++) {
                double t = s / 10.0;
                double u = edge == 2 ? 0 : edge == 3 ? 1 : t, v = edge == 0 ? 0 : edge == 1 ? 1 : t;
                double iu = edge == 2 ? 1e-3 : edge == 3 ? 1 - 1e-3 : t, iv = edge == 0 ? 1e-3 : edge == 1 ? 1 - 1e-3 : t;
                double[] nrm = normal(net, n, m, u, v), inner = crossNormal(net, n, m, iu, iv);
                String what = "edge " + edge + " of " + n + "x" + m + " at (" + u + "," + v + ")";
                assertTrue(dot(nrm, inner) > 0.99, what + ": " + Arrays.toString(nrm) + " vs " + Arrays.toString(inner));
            }
        }
    }
}
