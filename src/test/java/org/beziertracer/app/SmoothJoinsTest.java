package org.beziertracer.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/** "Keep tangent continuity": the cross-border control rows stay straight, with their ratios, under moves. */
class SmoothJoinsTest {

    /** The teapot's body: the eight patches below the rim (z from 0 to 90). */
    static final int[] BODY = {0, 1, 2, 3, 6, 7, 8, 9};
    /** How straight a row must stay: the sine of its bend. */
    static final double STRAIGHT = 1e-9;

    /** The positions of join {@code t}'s nodes A, B, C in {@code scene}. */
    private static double[][] row(Scene scene, WeldIndex welds, SmoothJoins joins, int t) {
        double[][] out = new double[3][3];
        for (int r = 0; r < 3; r++) {
            PointRef p = welds.ref(joins.node(t, r), scene);
            for (int c = 0; c < 3; c++) {
                out[r][c] = scene.patches().get(p.patch()).get(p.i(), p.j(), c);
            }
        }
        return out;
    }

    private static double ratio(double[][] row) {
        return dist(row[2], row[1]) / dist(row[0], row[1]);
    }

    private static double dist(double[] a, double[] b) {
        return Math.sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
    }

    /** The joins of {@code scene} that hold (are tangent-continuous). */
    private static List<Integer> holding(Scene scene, Topology t) {
        List<Integer> out = new ArrayList<>();
        for (int k = 0; k < t.joins().count(); k++) {
            double[][] r = row(scene, t.welds(), t.joins(), k);
            if (SmoothJoins.holds(r[0], r[1], r[2], t.welds().tolerance())) {
                out.add(k);
            }
        }
        return out;
    }

    @Test
    void theTeapotBodyIsTangentContinuousAcrossItsBorders() {
        Scene teapot = Models.teapot();
        Topology t = Topology.of(teapot, true);
        List<Integer> held = holding(teapot, t);
        assertTrue(t.joins().count() >= 100, "joins found: " + t.joins().count());
        int body = 0;
        for (int k : held) {
            PointRef b = t.welds().ref(t.joins().node(k, 1), teapot);
            body += java.util.Arrays.stream(BODY).anyMatch(p -> p == b.patch()) ? 1 : 0;
        }
        assertTrue(body >= 40, "tangent-continuous joins on the body: " + body);
    }

    @Test
    void afterRandomMovesOfTheBodyTheCrossBorderRowsStayStraightWithTheirRatios() {
        Scene scene = Models.teapot();
        Topology first = Topology.of(scene, true);
        List<Integer> held = holding(scene, first);
        double[] ratios = held.stream().mapToDouble(k -> ratio(row(Models.teapot(), first.welds(), first.joins(), k))).toArray();
        int welded = first.welds().weldedPointCount();
        Random rnd = new Random(12);
        int followed = 0;
        for (int move = 0; move < 200; move++) {
            Topology t = Topology.of(scene, true); // as the app has it after each edit lands
            int p = BODY[rnd.nextInt(BODY.length)];
            PointRef grabbed = new PointRef(p, rnd.nextInt(4), rnd.nextInt(4));
            Selection s = Selection.ofHandles(List.of(t.handle(grabbed, scene)));
            double[] d = {8 * rnd.nextGaussian(), 8 * rnd.nextGaussian(), 8 * rnd.nextGaussian()};
            Scene next = SelectionMove.apply(scene, s, d, t, true);
            followed += changedPatches(scene, next) > s.size() ? 1 : 0;
            scene = next;
            for (int i = 0; i < held.size(); i++) {
                double[][] r = row(scene, first.welds(), first.joins(), held.get(i));
                String where = "move " + move + " (" + grabbed + " by " + java.util.Arrays.toString(d) + "), join "
                        + held.get(i);
                assertTrue(SmoothJoins.sine(r[0], r[1], r[2]) <= STRAIGHT, "the row bends: sine "
                        + SmoothJoins.sine(r[0], r[1], r[2]) + " at " + where);
                assertEquals(ratios[i], ratio(r), 1e-9 * ratios[i], "the ratio changed at " + where);
            }
        }
        assertEquals(welded, WeldIndex.build(scene).weldedPointCount(), "every weld survives");
        assertTrue(followed > 100, "points across the borders followed in " + followed + " of 200 moves");
    }

    private static int changedPatches(Scene a, Scene b) {
        int n = 0;
        for (int k = 0; k < a.patchCount(); k++) {
            n += a.patches().get(k) != b.patches().get(k) ? 1 : 0;
        }
        return n;
    }

    /** The handle of node {@code role} (0 = A, 1 = B, 2 = C) of join {@code k}, selected. */
    private static Selection nodeOf(Scene scene, Topology t, int k, int role) {
        return Selection.ofHandles(List.of(t.handle(t.welds().ref(t.joins().node(k, role), scene), scene)));
    }

    @Test
    void withoutTheOptionAMovedInnerPointBendsTheRow() {
        Scene teapot = Models.teapot();
        Topology t = Topology.of(teapot, true);
        int k = holding(teapot, t).get(0);
        Selection s = nodeOf(teapot, t, k, 0);
        double[] d = {5, 7, -3};
        double[][] plain = row(SelectionMove.apply(teapot, s, d, t, false), t.welds(), t.joins(), k);
        assertTrue(SmoothJoins.sine(plain[0], plain[1], plain[2]) > 1e-3, "a plain move bends the row");
        double[][] smooth = row(SelectionMove.apply(teapot, s, d, t, true), t.welds(), t.joins(), k);
        assertTrue(SmoothJoins.sine(smooth[0], smooth[1], smooth[2]) <= STRAIGHT, "with the option the mirror follows");
        double[][] before = row(teapot, t.welds(), t.joins(), k);
        assertEquals(dist(before[1], smooth[1]), 0, 1e-12, "the border point stays");
        assertEquals(ratio(before), ratio(smooth), 1e-9, "with the ratio it had");
    }

    @Test
    void aMovedBorderPointCarriesItsNeighboursOnBothSides() {
        Scene teapot = Models.teapot();
        Topology t = Topology.of(teapot, true);
        int k = holding(teapot, t).get(0);
        Selection s = nodeOf(teapot, t, k, 1);
        double[] d = {2, -4, 6};
        Scene moved = SelectionMove.apply(teapot, s, d, t, true);
        double[][] before = row(teapot, t.welds(), t.joins(), k), after = row(moved, t.welds(), t.joins(), k);
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                assertEquals(before[r][c] + d[c], after[r][c], 1e-9, "point " + "ABC".charAt(r) + " moved with B");
            }
        }
    }

    @Test
    void rowsThatWereNotStraightAreLeftAlone() {
        Scene teapot = Models.teapot();
        Topology t = Topology.of(teapot, true);
        int k = holding(teapot, t).get(0);
        PointRef c = t.welds().ref(t.joins().node(k, 2), teapot);
        // Bend the row first (without the option), then move its A with the option on: C stays
        Scene bent = SelectionMove.apply(teapot, nodeOf(teapot, t, k, 2), new double[] {9, 9, 9}, t, false);
        Scene moved = SelectionMove.apply(bent, nodeOf(bent, t, k, 0), new double[] {1, 2, 3}, Topology.of(bent, true), true);
        BezierPatch before = bent.patches().get(c.patch()), after = moved.patches().get(c.patch());
        for (int q = 0; q < 3; q++) {
            assertEquals(before.get(c.i(), c.j(), q), after.get(c.i(), c.j(), q), "C is not pulled back into line");
        }
    }
}
