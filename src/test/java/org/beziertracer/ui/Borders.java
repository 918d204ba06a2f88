package org.beziertracer.ui;

import org.beziertracer.app.Handle;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Cross-border control rows of a model, found the simple way for GUI tests: a border point B of
 * one patch (not a corner) that another patch shares on its border, with the inner neighbours A
 * and C beside it in each; and whether such a row is straight.
 */
final class Borders {
    private Borders() {}

    /**
     * A straight cross-border row of the teapot's body whose inner point A the overlay draws as a
     * handle of its own (so the mouse can grab it): {@code {pA, iA, jA, pB, iB, jB, pC, iC, jC}}.
     */
    static int[] visibleRow(GuiDriver d, Scene scene) {
        for (int p = 0; p < 12; p++) {
            for (int q = 0; q < 12; q++) {
                if (p == q) {
                    continue;
                }
                for (int k = 0; k < 16; k++) {
                    int[] row = row(scene, p, k % 4, k / 4, q);
                    if (row != null && bend(scene, row) < 1e-9 && pickable(d, row)) {
                        return row;
                    }
                }
            }
        }
        throw new AssertionError("no straight cross-border row with a visible inner point");
    }

    /** The row through border point (i, j) of patch p into patch q, or null. */
    private static int[] row(Scene scene, int p, int i, int j, int q) {
        boolean edgeI = i == 0 || i == 3, edgeJ = j == 0 || j == 3;
        if (edgeI == edgeJ) {
            return null; // inside, or a corner
        }
        int ai = edgeI ? (i == 0 ? 1 : 2) : i, aj = edgeI ? j : (j == 0 ? 1 : 2);
        BezierPatch other = scene.patches().get(q);
        for (int k = 0; k < 16; k++) {
            int bi = k % 4, bj = k / 4;
            boolean oi = bi == 0 || bi == 3, oj = bj == 0 || bj == 3;
            if (oi != oj && same(scene.patches().get(p), i, j, other, bi, bj)) {
                int ci = oi ? (bi == 0 ? 1 : 2) : bi, cj = oi ? bj : (bj == 0 ? 1 : 2);
                return new int[] {p, ai, aj, p, i, j, q, ci, cj};
            }
        }
        return null;
    }

    private static boolean same(BezierPatch a, int i, int j, BezierPatch b, int k, int l) {
        for (int c = 0; c < 3; c++) {
            if (Math.abs(a.get(i, j, c) - b.get(k, l, c)) > 1e-9) {
                return false;
            }
        }
        return true;
    }

    private static boolean pickable(GuiDriver d, int[] row) {
        return GuiDriver.onEdt(() -> {
            BezierPatch a = d.app.document().scene().patches().get(row[0]);
            double[] at = new double[3];
            if (!d.app.view().projector().project(a.get(row[1], row[2], 0), a.get(row[1], row[2], 1),
                    a.get(row[1], row[2], 2), at) || at[0] < 40 || at[1] < 40 || at[0] > d.app.view().width() - 60
                    || at[1] > d.app.view().height() - 60) {
                return false;
            }
            Handle h = d.app.overlay().geometry().pick(at[0], at[1], 1);
            return h != null && h.ref().patch() == row[0] && h.ref().i() == row[1] && h.ref().j() == row[2];
        });
    }

    private static double[] point(Scene s, int[] row, int r) {
        BezierPatch p = s.patches().get(row[3 * r]);
        return new double[] {p.get(row[3 * r + 1], row[3 * r + 2], 0), p.get(row[3 * r + 1], row[3 * r + 2], 1),
                p.get(row[3 * r + 1], row[3 * r + 2], 2)};
    }

    /** Sine of the bend of the row at B (0: straight). */
    static double bend(Scene s, int[] row) {
        double[] a = point(s, row, 0), b = point(s, row, 1), c = point(s, row, 2);
        double ax = a[0] - b[0], ay = a[1] - b[1], az = a[2] - b[2], cx = c[0] - b[0], cy = c[1] - b[1], cz = c[2] - b[2];
        double x = ay * cz - az * cy, y = az * cx - ax * cz, z = ax * cy - ay * cx;
        return Math.sqrt(x * x + y * y + z * z) / Math.sqrt((ax * ax + ay * ay + az * az) * (cx * cx + cy * cy + cz * cz));
    }

    /** True when C of the row moved between the two scenes. */
    static boolean moved(Scene before, Scene after, int[] row) {
        double[] c0 = point(before, row, 2), c1 = point(after, row, 2);
        return Math.abs(c0[0] - c1[0]) + Math.abs(c0[1] - c1[1]) + Math.abs(c0[2] - c1[2]) > 1e-6;
    }
}
