package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Test models that are curvature-continuous across their borders by construction: one random
 * Bézier patch cut by de Casteljau's algorithm (an oracle independent of the code under test), so
 * each piece is the same polynomial surface and every cross-border row is C2 with the ratio of the
 * cut (Farin, §7.2). Public for the GUI tests.
 */
public final class C2Models {
    private C2Models() {}

    /** A random patch of degree {@code n × m} over roughly {@code [-1.5, 1.5]²} with z in {@code [-1, 1]} (seeded). */
    public static BezierPatch randomPatch(int n, int m, long seed) {
        Random rnd = new Random(seed);
        double[] net = new double[3 * (n + 1) * (m + 1)];
        for (int j = 0, k = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++, k += 3) {
                net[k] = -1.5 + 3.0 * i / n + 0.2 * rnd.nextGaussian();
                net[k + 1] = -1.5 + 3.0 * j / m + 0.2 * rnd.nextGaussian();
                net[k + 2] = 2 * rnd.nextDouble() - 1;
            }
        }
        return new BezierPatch(n, m, net);
    }

    /** {@code p} cut at the u values {@code us} and v values {@code vs} (each increasing in (0, 1)), pieces u fastest. */
    public static Scene cut(BezierPatch p, double[] us, double[] vs) {
        List<BezierPatch> columns = new ArrayList<>();
        BezierPatch rest = p;
        double done = 0;
        for (double u : us) {
            BezierPatch[] two = splitU(rest, (u - done) / (1 - done));
            columns.add(two[0]);
            rest = two[1];
            done = u;
        }
        columns.add(rest);
        List<List<BezierPatch>> grid = new ArrayList<>();
        for (BezierPatch column : columns) {
            List<BezierPatch> pieces = new ArrayList<>();
            BezierPatch r = transpose(column);
            double d = 0;
            for (double v : vs) {
                BezierPatch[] two = splitU(r, (v - d) / (1 - d));
                pieces.add(transpose(two[0]));
                r = two[1];
                d = v;
            }
            pieces.add(transpose(r));
            grid.add(pieces);
        }
        List<BezierPatch> out = new ArrayList<>();
        for (int j = 0; j <= vs.length; j++) {
            for (List<BezierPatch> column : grid) {
                out.add(column.get(j));
            }
        }
        return new Scene(out);
    }

    /** The two halves of {@code p} at {@code u = s} (de Casteljau on every row along u). */
    static BezierPatch[] splitU(BezierPatch p, double s) {
        int n = p.degreeU(), m = p.degreeV();
        double[] left = new double[3 * (n + 1) * (m + 1)], right = new double[left.length];
        double[] row = new double[3 * (n + 1)];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                for (int c = 0; c < 3; c++) {
                    row[3 * i + c] = p.get(i, j, c);
                }
            }
            for (int r = 0; r <= n; r++) {
                for (int c = 0; c < 3; c++) {
                    left[3 * (j * (n + 1) + r) + c] = row[c];
                    right[3 * (j * (n + 1) + n - r) + c] = row[3 * (n - r) + c];
                }
                for (int i = 0; i < n - r; i++) {
                    for (int c = 0; c < 3; c++) {
                        row[3 * i + c] = (1 - s) * row[3 * i + c] + s * row[3 * (i + 1) + c];
                    }
                }
            }
        }
        return new BezierPatch[] {new BezierPatch(n, m, left), new BezierPatch(n, m, right)};
    }

    /** {@code p} with u and v exchanged. */
    static BezierPatch transpose(BezierPatch p) {
        int n = p.degreeU(), m = p.degreeV();
        double[] net = new double[3 * (n + 1) * (m + 1)];
        for (int j = 0; j <= m; j++) {
            for (int i = 0; i <= n; i++) {
                for (int c = 0; c < 3; c++) {
                    net[3 * (i * (m + 1) + j) + c] = p.get(i, j, c);
                }
            }
        }
        return new BezierPatch(m, n, net);
    }
}
