package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.beziertracer.Tolerances.SUBDIVISION_T;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.SplitOptions;
import org.beziertracer.geometry.SubPatchTable;
import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link SubdivisionSolver}: exact where its control-mesh approximation is exact (a flat,
 * uniformly parametrised patch at any degree), within its stated error on curved patches of any
 * scale, nearest root first, open interval ends; its triangle test on its own.
 */
class SubdivisionSolverTest {

    /** The parallelogram {@code O + u·U + v·V} as a degree n×m patch: control points on a regular grid. */
    static BezierPatch flat(int n, int m, double[] o, double[] uu, double[] vv) {
        double[] net = new double[3 * (n + 1) * (m + 1)];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                for (int c = 0; c < 3; c++) {
                    net[3 * (j * (n + 1) + i) + c] = o[c] + uu[c] * i / n + vv[c] * j / m;
                }
            }
        }
        return new BezierPatch(n, m, net);
    }

    private static double[] gaussian(Random rnd, double scale) {
        return new double[] {scale * rnd.nextGaussian(), scale * rnd.nextGaussian(), scale * rnd.nextGaussian()};
    }

    @Test
    void aFlatUniformPatchIsHitExactly() {
        Random rnd = new Random(1980);
        TraceContext ctx = new TraceContext();
        int hits = 0;
        for (int trial = 0; trial < 400; trial++) {
            int n = 1 + rnd.nextInt(6), m = 1 + rnd.nextInt(6);
            double size = Math.pow(10, rnd.nextInt(7) - 3);
            double[] o = gaussian(rnd, size), uu = gaussian(rnd, size), vv = gaussian(rnd, size);
            double[] normal = {uu[1] * vv[2] - uu[2] * vv[1], uu[2] * vv[0] - uu[0] * vv[2], uu[0] * vv[1] - uu[1] * vv[0]};
            double area = Math.sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
            if (area < 0.3 * size * size) {
                continue; // a sliver
            }
            SubPatchTable tab = SubPatchTable.build(List.of(flat(n, m, o, uu, vv)), SplitOptions.wholePatches());
            double us = 0.05 + 0.9 * rnd.nextDouble(), vs = 0.05 + 0.9 * rnd.nextDouble();
            double[] s = new double[3];
            for (int c = 0; c < 3; c++) {
                s[c] = o[c] + us * uu[c] + vs * vv[c];
            }
            // from the side of the normal, not grazing; direction of any length
            double lift = (0.5 + rnd.nextDouble()) * size / area;
            double[] origin = new double[3];
            for (int c = 0; c < 3; c++) {
                origin[c] = s[c] + lift * normal[c] + 0.3 * size * rnd.nextGaussian();
            }
            double k = Math.pow(10, rnd.nextInt(5) - 2);
            ctx.setRay(origin[0], origin[1], origin[2], k * (s[0] - origin[0]), k * (s[1] - origin[1]), k * (s[2] - origin[2]));
            String where = "trial " + trial + " degree " + n + "x" + m + " size " + size + " (u*,v*)=(" + us + "," + vs + ")";
            assertTrue(SubdivisionSolver.intersect(ctx, tab, 0, 0, Double.POSITIVE_INFINITY, 1e-12 * size), where);
            hits++;
            assertEquals(1 / k, ctx.rootT, 1e-9 / k, "t " + where);
            assertEquals(us, ctx.rootU, 1e-9, "u " + where);
            assertEquals(vs, ctx.rootV, 1e-9, "v " + where);
            // the interval cuts it out
            assertFalse(SubdivisionSolver.intersect(ctx, tab, 0, 0, 0.9 / k, 1e-12 * size), "tMax " + where);
            assertFalse(SubdivisionSolver.intersect(ctx, tab, 0, 1.1 / k, Double.POSITIVE_INFINITY, 1e-12 * size),
                    "tMin " + where);
        }
        assertTrue(hits > 250, "rays " + hits);
    }

    /** Curved height fields of sizes 1e-3 to 1e3: the hit is within the stated error of the exact root. */
    @Test
    void aCurvedPatchIsHitWithinTheStatedErrorAtAnyScale() {
        Random rnd = new Random(1981);
        TraceContext ctx = new TraceContext();
        double[] s = new double[3], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        int judged = 0;
        for (int trial = 0; trial < 300; trial++) {
            int n = 2 + rnd.nextInt(5), m = 2 + rnd.nextInt(5);
            double size = Math.pow(10, rnd.nextInt(7) - 3);
            BezierPatch patch = RandomPatches.heightField(rnd, n, m, size, 0.3);
            SubPatchTable tab = SubPatchTable.build(List.of(patch), SplitOptions.wholePatches());
            double us = 0.1 + 0.8 * rnd.nextDouble(), vs = 0.1 + 0.8 * rnd.nextDouble();
            DeCasteljau.evaluate(patch.copyNet(), 0, n, m, 3, us, vs, s, 0, scratch);
            double ox = s[0] + 0.2 * size * rnd.nextGaussian(), oy = s[1] + 0.2 * size * rnd.nextGaussian(), oz = 2 * size;
            double[] exact = ReferenceIntersector.nearest(patch, ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz, 0,
                    Double.POSITIVE_INFINITY, 24);
            if (exact == null) {
                continue;
            }
            ctx.setRay(ox, oy, oz, s[0] - ox, s[1] - oy, s[2] - oz);
            String where = "trial " + trial + " degree " + n + "x" + m + " size " + size;
            assertTrue(SubdivisionSolver.intersect(ctx, tab, 0, 0, Double.POSITIVE_INFINITY, 1e-12 * size), where);
            double length = Math.sqrt((s[0] - ox) * (s[0] - ox) + (s[1] - oy) * (s[1] - oy) + (s[2] - oz) * (s[2] - oz));
            assertEquals(exact[0], ctx.rootT, SUBDIVISION_T * size / length, "t " + where);
            assertEquals(exact[1], ctx.rootU, 0.02, "u " + where);
            assertEquals(exact[2], ctx.rootV, 0.02, "v " + where);
            judged++;
        }
        assertTrue(judged > 250, "judged " + judged);
    }

    /**
     * The trough seen along its x axis: the ends of its rows line up along the ray, so only the
     * whole control polygons show the u direction's extent (measured by the end chords alone, the
     * solver halved v until the pieces degenerated, and missed; {@link PatchExtents}).
     */
    @Test
    void theNearestOfTwoRootsAndOpenEnds() {
        SubPatchTable tab = SubPatchTable.build(List.of(ClippingStepsTest.trough()), SplitOptions.wholePatches());
        TraceContext ctx = new TraceContext();
        for (double k : new double[] {1, 1e-3, 1e3}) {
            ctx.setRay(-1, 0.5, 0.09, k, 0, 0);
            assertTrue(SubdivisionSolver.intersect(ctx, tab, 0, 0, Double.POSITIVE_INFINITY, 1e-12));
            assertEquals(1.2 / k, ctx.rootT, SUBDIVISION_T / k);
            assertEquals(0.2, ctx.rootU, 0.01);
            double t = ctx.rootT;
            // open ends: the same t is never returned again (neighbouring control-mesh triangles may
            // meet the ray a hair apart, so another hit may come back, but strictly inside)
            if (SubdivisionSolver.intersect(ctx, tab, 0, t, Double.POSITIVE_INFINITY, 1e-12)) {
                assertTrue(ctx.rootT > t, "tMin = t: " + ctx.rootT);
            }
            if (SubdivisionSolver.intersect(ctx, tab, 0, 0, t, 1e-12)) {
                assertTrue(ctx.rootT < t, "tMax = t: " + ctx.rootT);
            }
            assertTrue(SubdivisionSolver.intersect(ctx, tab, 0, 1.5 / k, Double.POSITIVE_INFINITY, 1e-12), "the farther root");
            assertEquals(1.8 / k, ctx.rootT, SUBDIVISION_T / k);
            assertEquals(0.8, ctx.rootU, 0.01);
            assertFalse(SubdivisionSolver.intersect(ctx, tab, 0, 1.9 / k, Double.POSITIVE_INFINITY, 1e-12), "nothing beyond");
            assertTrue(SubdivisionSolver.intersect(ctx, tab, 0, 0, 1.7 / k, 1e-12));
            assertEquals(t, ctx.rootT, 0, "the same nearer root");
            assertFalse(SubdivisionSolver.intersect(ctx, tab, 0, 1.3 / k, 1.7 / k, 1e-12), "between the roots");
        }
    }

    @Test
    void theTriangleTestGivesBarycentricWeightsWithinItsSlack() {
        // a = (1, 1), b = (-3, 1), c = (1, -3) in ray space: the origin has weights wb = wc = 1/4
        double[] p = {1, 1, 0, -3, 1, 0, 1, -3, 0};
        double[] w = new double[2];
        assertTrue(SubdivisionSolver.triangle(p, 0, 3, 6, w));
        assertArrayEquals(new double[] {0.25, 0.25}, w, ROUNDING);
        // moved so that wb = wc = 0.6 (outside: wb + wc = 1.2)
        double[] q = shifted(p, 0.6, 0.6);
        w[0] = w[1] = -7;
        assertFalse(SubdivisionSolver.triangle(q, 0, 3, 6, w));
        assertArrayEquals(new double[] {-7, -7}, w, 0, "no weights for a miss");
        // just outside an edge, within the slack: wb = -0.01, and wb + wc = 1.01
        assertTrue(SubdivisionSolver.triangle(shifted(p, -0.01, 0.5), 0, 3, 6, w));
        assertArrayEquals(new double[] {-0.01, 0.5}, w, ROUNDING);
        assertTrue(SubdivisionSolver.triangle(shifted(p, 0.5, -0.01), 0, 3, 6, w));
        assertTrue(SubdivisionSolver.triangle(shifted(p, 0.5, 0.51), 0, 3, 6, w));
        // beyond the slack
        assertFalse(SubdivisionSolver.triangle(shifted(p, -0.03, 0.5), 0, 3, 6, w));
        assertFalse(SubdivisionSolver.triangle(shifted(p, 0.5, -0.03), 0, 3, 6, w));
        assertFalse(SubdivisionSolver.triangle(shifted(p, 0.5, 0.53), 0, 3, 6, w));
        // a degenerate (collinear) triangle is never hit
        w[0] = w[1] = -7;
        assertFalse(SubdivisionSolver.triangle(new double[] {-1, -1, 0, 1, 1, 0, 2, 2, 0}, 0, 3, 6, w));
        assertArrayEquals(new double[] {-7, -7}, w, 0);
    }

    @Test
    void extentsAreTheEndPolygonLengths() {
        Random rnd = new Random(1982);
        for (int trial = 0; trial < 500; trial++) {
            int n = 1 + rnd.nextInt(7), m = 1 + rnd.nextInt(7), base = 3 * rnd.nextInt(10);
            double[] net = new double[base + 3 * (n + 1) * (m + 1) + 6];
            for (int k = 0; k < net.length; k++) {
                net[k] = rnd.nextGaussian();
            }
            double lu = 0, lv = 0;
            for (int j : new int[] {0, m}) {
                for (int i = 0; i < n; i++) {
                    int p = base + 3 * (j * (n + 1) + i);
                    lu += Math.hypot(net[p + 3] - net[p], net[p + 4] - net[p + 1]);
                }
            }
            for (int i : new int[] {0, n}) {
                for (int j = 0; j < m; j++) {
                    int p = base + 3 * (j * (n + 1) + i), q = p + 3 * (n + 1);
                    lv += Math.hypot(net[q] - net[p], net[q + 1] - net[p + 1]);
                }
            }
            String where = "trial " + trial + " degree " + n + "x" + m;
            assertEquals(lu, PatchExtents.rayLengthU(net, base, n, m), ROUNDING * lu, where);
            assertEquals(lv, PatchExtents.rayLengthV(net, base, n, m), ROUNDING * lv, where);
        }
    }

    /** The triangle {@code p} moved so that the origin has barycentric weights {@code (wb, wc)}. */
    private static double[] shifted(double[] p, double wb, double wc) {
        double wa = 1 - wb - wc;
        double x = wa * p[0] + wb * p[3] + wc * p[6], y = wa * p[1] + wb * p[4] + wc * p[7];
        double[] q = p.clone();
        for (int k = 0; k < 9; k += 3) {
            q[k] -= x;
            q[k + 1] -= y;
        }
        return q;
    }
}
