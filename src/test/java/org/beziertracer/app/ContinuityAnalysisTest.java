package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.beziertracer.app.ContinuityAnalysis.Continuity;
import org.beziertracer.app.ContinuityAnalysis.Row;
import org.beziertracer.geometry.Patches;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** {@link ContinuityAnalysis} and the border finding it rests on ({@link SharedBorders}). */
class ContinuityAnalysisTest {

    /** A bumpy graph over the unit square: a regular bicubic surface. */
    private static BezierPatch graph(long seed) {
        Random rnd = new Random(seed);
        double[] net = new double[16 * 3];
        for (int k = 0; k < 16; k++) {
            net[3 * k] = (k % 4) / 3.0;
            net[3 * k + 1] = (k / 4) / 3.0;
            net[3 * k + 2] = 0.3 * rnd.nextGaussian();
        }
        return new BezierPatch(3, 3, net);
    }

    /** {@code P'_ij = P_{j, m−i}}: u and v swapped and the new u reversed. */
    private static BezierPatch transposedReversed(BezierPatch p) {
        int n = p.degreeU(), m = p.degreeV();
        double[] net = new double[p.pointCount() * 3];
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= m; i++) {
                for (int c = 0; c < 3; c++) {
                    net[3 * (j * (m + 1) + i) + c] = p.get(j, m - i, c);
                }
            }
        }
        return new BezierPatch(m, n, net);
    }

    private static ContinuityAnalysis.Result analyze(BezierPatch... patches) {
        Scene scene = new Scene(List.of(patches));
        return ContinuityAnalysis.analyze(scene, ContinuityAnalysis.Tolerances.defaults(scene));
    }

    @Test
    void aSplitPatchTurnedAroundIsOneG2Border() {
        BezierPatch[] halves = Patches.splitU(graph(1), 0.35);
        BezierPatch b = transposedReversed(halves[1]); // its old u=0 side is now v=0, running backwards
        ContinuityAnalysis.Result r = analyze(halves[0], b);
        assertEquals(1, r.rows().size(), r.rows().toString());
        Row row = r.rows().get(0);
        assertEquals(new SharedBorders.Border(0, 1, 1, 2, true), row.border());
        assertEquals(Continuity.G2, row.continuity(), row.toString());
        assertTrue(row.report().g0().bound() <= 1e-12 * r.size(), row.toString());
        assertTrue(row.report().g2().bound() * r.size() <= 1e-12, row.toString());
    }

    @Test
    void innerBorderPointsMovedApartAreAGapOfThreeQuartersTheirDistance() {
        BezierPatch[] halves = Patches.splitU(graph(2), 0.5);
        double[] net = halves[1].copyNet();
        for (int j = 1; j <= 2; j++) {
            net[halves[1].index(0, j, 2)] += 0.01;
            net[halves[1].index(1, j, 2)] += 0.01;
        }
        ContinuityAnalysis.Result r = analyze(halves[0], halves[1].withNet(net));
        assertEquals(1, r.rows().size(), "the corners are still welded: " + r.rows());
        Row row = r.rows().get(0);
        assertEquals(Continuity.GAP, row.continuity());
        assertEquals(0.0075, row.report().g0().bound(), 1e-9 * 0.0075, row.toString());
        assertEquals(1, r.count(Continuity.GAP));
    }

    @Test
    void cornersWeldedWithinTheEditorsToleranceMakeABorderAndFartherOnesDoNot() {
        BezierPatch[] halves = Patches.splitU(graph(3), 0.5);
        double size = new Scene(List.of(halves)).controlBounds().diagonal();
        for (double moved : new double[] {0.1, 10}) {
            double[] net = halves[1].copyNet();
            net[halves[1].index(0, 0, 0)] += moved * WeldIndex.RELATIVE_TOLERANCE * size;
            ContinuityAnalysis.Result r = analyze(halves[0], halves[1].withNet(net));
            assertEquals(moved < 1 ? 1 : 0, r.rows().size(), "corner moved by " + moved + " weld tolerances");
        }
    }

    @Test
    void twoHalfCirclesClosingATubeAreArcsOfOneLoopNotABorder() {
        double k = 4.0 / 3;
        // upper and lower half of a circle of radius 1 in the plane x = 0, extruded along x
        double[] upper = new double[8 * 3], lower = new double[8 * 3];
        double[][] up = {{0, -1, 0}, {0, -1, k}, {0, 1, k}, {0, 1, 0}};
        for (int j = 0; j <= 1; j++) {
            for (int i = 0; i <= 3; i++) {
                int q = 3 * (j * 4 + i);
                upper[q] = j;
                upper[q + 1] = up[i][1];
                upper[q + 2] = up[i][2];
                lower[q] = j;
                lower[q + 1] = up[i][1];
                lower[q + 2] = -up[i][2];
            }
        }
        ContinuityAnalysis.Result r = analyze(new BezierPatch(3, 1, upper), new BezierPatch(3, 1, lower));
        assertEquals(2, r.arcPairs(), "both rims: " + r.rows());
        assertEquals(2, r.rows().size(), "the two straight seams are borders: " + r.rows());
    }

    @Test
    void theTeapotsBodyIsTangentContinuousAndItsRowsAreSortedWorstFirst() {
        Scene teapot = Models.teapot();
        ContinuityAnalysis.Result r = ContinuityAnalysis.analyze(teapot, ContinuityAnalysis.Tolerances.defaults(teapot));
        List<Integer> body = List.of(0, 1, 2, 3, 6, 7, 8, 9); // patches 1-4 and 7-10
        int bodyBorders = 0;
        for (Row row : r.rows()) {
            if (body.contains(row.border().a()) && body.contains(row.border().b())) {
                bodyBorders++;
                assertTrue(row.continuity().compareTo(Continuity.G1) <= 0 && row.g1Degrees() <= 0.5, row.toString());
            }
        }
        assertEquals(12, bodyBorders, "8 around and 4 between the lower and upper rings");
        for (int k = 1; k < r.rows().size(); k++) {
            assertTrue(r.rows().get(k - 1).continuity().compareTo(r.rows().get(k).continuity()) >= 0,
                    "sorted worst class first at row " + k);
        }
    }
}
