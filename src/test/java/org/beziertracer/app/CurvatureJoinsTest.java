package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** "Keep curvature continuity": the five-point cross-border rows stay C2, with their ratios, under moves. */
class CurvatureJoinsTest {

    /** How close to C2 a kept row must stay: its residual relative to the model's size. */
    static final double C2 = 1e-9;

    private static Scene twoByTwo() {
        return C2Models.cut(C2Models.randomPatch(3, 3, 7), new double[] {0.4}, new double[] {0.55});
    }

    private static double[] ratios(Scene scene, Topology t, List<Integer> kept) {
        return kept.stream().mapToDouble(k -> {
            double[][] r = CurvatureJoins.row(scene, t.welds(), t.joins(), k);
            return CurvatureJoins.ratio(r[1], r[2], r[3]);
        }).toArray();
    }

    @Test
    void aCurveCutByDeCasteljauAndOneHalfDegreeElevatedIsC2AtTheCut() {
        double[][] p = {{0, 0, 0}, {1, 2, 0.5}, {3, 2.5, -1}, {4, 0, 2}};
        double s = 0.35;
        double[][] left = new double[4][], right = new double[4][];
        double[][] w = Arrays.stream(p).map(double[]::clone).toArray(double[][]::new);
        for (int r = 0; r <= 3; r++) {
            left[r] = w[0].clone();
            right[3 - r] = w[3 - r].clone();
            for (int i = 0; i < 3 - r; i++) {
                for (int c = 0; c < 3; c++) {
                    w[i][c] = (1 - s) * w[i][c] + s * w[i + 1][c];
                }
            }
        }
        // Degree-elevate the right half to 4: Q_i = i/4 R_{i-1} + (1 - i/4) R_i
        double[][] q = new double[5][3];
        for (int i = 0; i <= 4; i++) {
            for (int c = 0; c < 3; c++) {
                q[i][c] = (i > 0 ? i / 4.0 * right[i - 1][c] : 0) + (i < 4 ? (1 - i / 4.0) * right[i][c] : 0);
            }
        }
        double res = CurvatureJoins.residual(left[1], left[2], left[3], q[1], q[2], 3, 4);
        assertEquals(0, res, 1e-12, "a cut curve is C2 at the cut, degrees 3 and 4");
        double[] solved = new double[3];
        CurvatureJoins.solveOuter(left[1], left[2], left[3], q[1], CurvatureJoins.ratio(left[2], left[3], q[1]), 3, 4, solved);
        for (int c = 0; c < 3; c++) {
            assertEquals(q[2][c], solved[c], 1e-12, "C2 solved from A2, A, B, C");
        }
        CurvatureJoins.solveOuter(q[2], q[1], left[3], left[2], CurvatureJoins.ratio(q[1], left[3], left[2]), 4, 3, solved);
        for (int c = 0; c < 3; c++) {
            assertEquals(left[1][c], solved[c], 1e-12, "A2 solved from the other side");
        }
        q[2][1] += 0.01;
        assertTrue(CurvatureJoins.residual(left[1], left[2], left[3], q[1], q[2], 3, 4) > 0.005, "a moved C2 breaks it");
    }

    @Test
    void aBicubicCutInFourIsCurvatureContinuousAcrossEveryBorder() {
        Scene scene = twoByTwo();
        Topology t = Topology.of(scene, true);
        assertEquals(16, t.joins().count(), "four borders of four rows each");
        assertEquals(0, t.joins().shortBorderCount());
        assertEquals(16, CurvatureJoins.holding(scene, t.welds(), t.joins()).size());
        assertTrue(CurvatureJoins.worstResidual(scene) < 1e-13, "residual " + CurvatureJoins.worstResidual(scene));
    }

    /** {@code count} random drags of random handles of {@code scene} with the keep on; every kept row checked after each. */
    private static void randomDrags(Scene scene, int count, long seed, int minKept) {
        Topology first = Topology.of(scene, true);
        List<Integer> kept = CurvatureJoins.holding(scene, first.welds(), first.joins());
        assertTrue(kept.size() >= minKept, "rows kept: " + kept.size());
        double[] ratios = ratios(scene, first, kept);
        int welded = first.welds().weldedPointCount();
        double size = CurvatureJoins.size(scene);
        Random rnd = new Random(seed);
        int followed = 0;
        for (int move = 0; move < count; move++) {
            Topology t = Topology.of(scene, true); // as the app has it after each edit lands
            int p = rnd.nextInt(scene.patchCount());
            BezierPatch patch = scene.patches().get(p);
            PointRef grabbed = new PointRef(p, rnd.nextInt(patch.degreeU() + 1), rnd.nextInt(patch.degreeV() + 1));
            Selection s = Selection.ofHandles(List.of(t.handle(grabbed, scene)));
            double[] d = {0.02 * size * rnd.nextGaussian(), 0.02 * size * rnd.nextGaussian(), 0.02 * size * rnd.nextGaussian()};
            Scene next = SelectionMove.apply(scene, s, d, t, false, true);
            followed += changed(scene, next) > s.size() ? 1 : 0;
            scene = next;
            String where = "move " + move + " (" + grabbed + " by " + Arrays.toString(d) + ")";
            for (int i = 0; i < kept.size(); i++) {
                int k = kept.get(i);
                double res = CurvatureJoins.relativeResidual(scene, first.welds(), first.joins(), k);
                assertTrue(res <= C2, "join " + k + " is no longer C2 after " + where + ": residual " + res);
                double[][] r = CurvatureJoins.row(scene, first.welds(), first.joins(), k);
                assertEquals(ratios[i], CurvatureJoins.ratio(r[1], r[2], r[3]), 1e-9 * ratios[i], "ratio of join " + k
                        + " after " + where);
            }
        }
        assertTrue(CurvatureJoins.worstResidual(scene, first.welds(), first.joins(), kept) <= C2);
        assertEquals(welded, WeldIndex.build(scene).weldedPointCount(), "every weld survives");
        assertTrue(followed > count / 3, "points across the borders followed in " + followed + " of " + count + " moves");
    }

    private static int changed(Scene a, Scene b) {
        int n = 0;
        for (int p = 0; p < a.patchCount(); p++) {
            BezierPatch x = a.patches().get(p), y = b.patches().get(p);
            for (int k = 0; k < x.pointCount(); k++) {
                int i = k % (x.degreeU() + 1), j = k / (x.degreeU() + 1);
                n += x.get(i, j, 0) != y.get(i, j, 0) || x.get(i, j, 1) != y.get(i, j, 1) || x.get(i, j, 2) != y.get(i, j, 2) ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void afterFiveHundredRandomDragsOnABicubicTwoByTwoEveryKeptBorderIsStillC2() {
        randomDrags(twoByTwo(), 500, 33, 16);
    }

    @Test
    void chainsOfThreeBicubicsCoupleTheirBordersAndStayC2() {
        Scene scene = C2Models.cut(C2Models.randomPatch(3, 3, 11), new double[] {0.3, 0.7}, new double[] {0.5});
        randomDrags(scene, 200, 5, 7 * 4);
    }

    @Test
    void higherDegreesAcrossKeepTheirRowsC2Too() {
        Scene scene = C2Models.cut(C2Models.randomPatch(4, 5, 3), new double[] {0.6}, new double[] {0.45});
        randomDrags(scene, 200, 8, 5 + 6);
    }

    /** A drag of a second-row point A2 of a kept row (one row inward of A, away from the border). */
    private static Scene dragSecondRow(Scene scene, Topology t, int k, boolean smooth, boolean curvature) {
        PointRef a2 = t.welds().ref(t.joins().outer(k, 0), scene);
        Selection s = Selection.ofHandles(List.of(t.handle(a2, scene)));
        return SelectionMove.apply(scene, s, new double[] {0.1, -0.2, 0.3}, t, smooth, curvature);
    }

    @Test
    void withoutTheCurvatureKeepADragBreaksC2AndWithItC2Holds() {
        Scene scene = twoByTwo();
        Topology t = Topology.of(scene, true);
        for (int k = 0; k < t.joins().count(); k++) {
            double tangentOnly = CurvatureJoins.relativeResidual(dragSecondRow(scene, t, k, true, false), t.welds(), t.joins(), k);
            assertTrue(tangentOnly > 1e-3, "keeping tangent continuity only, a moved second row breaks C2 at join " + k
                    + ": residual " + tangentOnly);
            double kept = CurvatureJoins.relativeResidual(dragSecondRow(scene, t, k, false, true), t.welds(), t.joins(), k);
            assertTrue(kept <= C2, "keeping curvature continuity, join " + k + " stays C2: residual " + kept);
        }
        PointRef a = t.welds().ref(t.joins().node(0, 0), scene);
        Scene plain = SelectionMove.apply(scene, Selection.ofHandles(List.of(t.handle(a, scene))), new double[] {0.1, 0.1, 0.1},
                t, false, false);
        assertTrue(CurvatureJoins.worstResidual(plain) > 1e-3, "a plain drag of A breaks the row");
    }

    @Test
    void aMovedBorderPointCarriesBothRowsOnBothSides() {
        Scene scene = twoByTwo();
        Topology t = Topology.of(scene, true);
        int k = 1; // any join
        PointRef b = t.welds().ref(t.joins().node(k, 1), scene);
        double[] d = {0.05, 0.02, -0.07};
        Scene moved = SelectionMove.apply(scene, Selection.ofHandles(List.of(t.handle(b, scene))), d, t, false, true);
        double[][] before = CurvatureJoins.row(scene, t.welds(), t.joins(), k), after = CurvatureJoins.row(moved, t.welds(), t.joins(), k);
        for (int r = 0; r < 5; r++) {
            for (int c = 0; c < 3; c++) {
                assertEquals(before[r][c] + d[c], after[r][c], 1e-12, "point " + r + " of the row moved with B");
            }
        }
    }

    @Test
    void bordersOfDegreeBelowThreeAcrossAreCountedAndKeepTangentContinuityOnly() {
        assertEquals(1, shortBorders(1, 1), "two bilinear patches");
        assertEquals(1, shortBorders(2, 2), "two biquadratic patches");
        assertEquals(2 * 3, shortBorders(3, 2, new double[] {0.3, 0.6}, new double[] {0.5, 0.8}),
                "biquadratic across v, bicubic across u, 3 × 3 pieces: the 6 borders across v");
        assertEquals(0, shortBorders(3, 3));
        // Degree 2 across: the G2 keep changes nothing beyond tangent continuity
        Scene quadratic = C2Models.cut(C2Models.randomPatch(2, 2, 4), new double[] {0.5}, new double[] {});
        Topology t = Topology.of(quadratic, true);
        assertTrue(CurvatureJoins.holding(quadratic, t.welds(), t.joins()).isEmpty(), "no join has second rows");
        PointRef a = t.welds().ref(t.joins().node(0, 0), quadratic);
        Selection s = Selection.ofHandles(List.of(t.handle(a, quadratic)));
        double[] d = {0.1, 0.2, 0.3};
        assertEquals(SelectionMove.apply(quadratic, s, d, t, true, false).patches(),
                SelectionMove.apply(quadratic, s, d, t, false, true).patches());
    }

    private static int shortBorders(int n, int m) {
        return shortBorders(n, m, new double[] {0.5}, new double[] {});
    }

    private static int shortBorders(int n, int m, double[] us, double[] vs) {
        Scene scene = C2Models.cut(C2Models.randomPatch(n, m, 1), us, vs);
        return Topology.of(scene, true).joins().shortBorderCount();
    }

    @Test
    void withTheCurvatureKeepTheTeapotKeepsItsTangentContinuity() {
        Scene scene = Models.teapot();
        Topology first = Topology.of(scene, true);
        assertEquals(0, first.joins().shortBorderCount(), "the teapot is bicubic");
        Random rnd = new Random(21);
        for (int move = 0; move < 60; move++) {
            Topology t = Topology.of(scene, true);
            PointRef grabbed = new PointRef(SmoothJoinsTest.BODY[rnd.nextInt(8)], rnd.nextInt(4), rnd.nextInt(4));
            double[] d = {3 * rnd.nextGaussian(), 3 * rnd.nextGaussian(), 3 * rnd.nextGaussian()};
            Scene g1 = SelectionMove.apply(scene, Selection.ofHandles(List.of(t.handle(grabbed, scene))), d, t, true, false);
            Scene g2 = SelectionMove.apply(scene, Selection.ofHandles(List.of(t.handle(grabbed, scene))), d, t, false, true);
            for (int k = 0; k < t.joins().count(); k++) {
                double[][] before = CurvatureJoinsTest.abc(scene, t, k), after1 = abc(g1, t, k), after2 = abc(g2, t, k);
                if (SmoothJoins.holds(before[0], before[1], before[2], t.welds().tolerance())) {
                    assertEquals(SmoothJoins.sine(after1[0], after1[1], after1[2]) <= 1e-9,
                            SmoothJoins.sine(after2[0], after2[1], after2[2]) <= 1e-9, "join " + k + " move " + move);
                }
            }
            scene = g2;
        }
    }

    static double[][] abc(Scene scene, Topology t, int k) {
        double[][] out = new double[3][3];
        for (int r = 0; r < 3; r++) {
            PointRef p = t.welds().ref(t.joins().node(k, r), scene);
            for (int c = 0; c < 3; c++) {
                out[r][c] = scene.patches().get(p.patch()).get(p.i(), p.j(), c);
            }
        }
        return out;
    }
}
