package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.Scene;

/**
 * Curvature continuity (G2) on the five-point cross-border rows {@code (A2, A, B, C, C2)} of
 * {@link SmoothJoins}: the C2 condition at {@code B} of the two Bézier curves the row belongs to,
 * {@code P} of degree {@code n} ending {@code …, A2, A, B} and {@code Q} of degree {@code m}
 * starting {@code B, C, C2, …}, with the C1 ratio {@code ρ} the row already has:
 * <pre>
 *   C1:  m (C − B)            = ρ n (B − A)
 *   C2:  m (m−1) (C2 − 2C + B) = ρ² n (n−1) (B − 2A + A2)
 * </pre>
 * (G. Farin, <i>Curves and Surfaces for CAGD: A Practical Guide</i>, 5th ed., 2002, §7.2 "Smoothness
 * conditions" for composite Bézier curves; a tensor-product surface is C^r across a border when every
 * cross-border row is, as its cross derivatives are the rows' derivatives blended by the border's
 * Bernstein polynomials). Written with the row's ratio {@code λ = |C − B| / |A − B| = ρ n / m}
 * (the one "Keep tangent continuity" keeps): {@code C − B = λ (B − A)} and
 * {@code C2 − 2C + B = k (B − 2A + A2)}, {@code k = λ² m (n−1) / (n (m−1))}.
 *
 * <p><b>Why this is enough.</b> When every row across a border satisfies both with the same
 * {@code ρ}, the patch on C's side is, after the linear change of its cross parameter
 * {@code s ↦ s / ρ}, the C2 continuation of the patch on A's side: the surface is C2 across the
 * border in that parametrisation, so position, tangent plane and every normal curvature agree —
 * it is G2 there (C2 after a regular reparametrisation implies G2: T. DeRose, <i>Geometric
 * Continuity: A Parametrization Independent Measure of Continuity for CAGD</i>, PhD thesis,
 * UC Berkeley, 1985). Rows with different {@code ρ} along one border are each C2 but the surface need
 * not be; the keep never changes a row's ratio, so a border that starts uniform (a split patch, a
 * B-spline converted to Bézier form) stays so. The conditions need {@code n, m ≥ 2}; we keep them
 * from degree {@link SmoothJoins#CURVATURE_DEGREE} (bicubic) up, where the second row is not the
 * opposite border.
 *
 * <p>Residuals are in scene units: the larger of the C1 mismatch {@code |C − B − λ (B − A)|} and the
 * C2 mismatch {@code |C2 − 2C + B − k (B − 2A + A2)|}; "relative" ones are divided by the model's
 * control-box diagonal. Stateless.
 */
public final class CurvatureJoins {
    private CurvatureJoins() {}

    /** A join whose relative residual is at most this counts as curvature-continuous (as {@link SmoothJoins#COLLINEAR} for G1). */
    static final double HOLDS = 1e-6;

    /** {@code k = λ² m (n−1) / (n (m−1))}: the C2 factor of a row with C1 ratio {@code λ} and degrees {@code n} (A's side), {@code m} (C's side). */
    static double secondRatio(double lambda, int n, int m) {
        return lambda * lambda * m * (n - 1) / ((double) n * (m - 1));
    }

    /** {@code |C − B| / |A − B|}. */
    static double ratio(double[] a, double[] b, double[] c) {
        return dist(c, b) / dist(a, b);
    }

    /** The residual of row {@code (a2, a, b, c, c2)} with degrees {@code n}, {@code m}, its ratio measured from the row. */
    static double residual(double[] a2, double[] a, double[] b, double[] c, double[] c2, int n, int m) {
        double lambda = ratio(a, b, c), k = secondRatio(lambda, n, m);
        double c1 = 0, c2r = 0;
        for (int q = 0; q < 3; q++) {
            double e1 = c[q] - b[q] - lambda * (b[q] - a[q]);
            double e2 = c2[q] - 2 * c[q] + b[q] - k * (b[q] - 2 * a[q] + a2[q]);
            c1 += e1 * e1;
            c2r += e2 * e2;
        }
        return Math.sqrt(Math.max(c1, c2r));
    }

    /**
     * Writes into {@code dest} the second-row point {@code y2} that makes row {@code (x2, x, b, y, y2)}
     * C2 at {@code b}, where {@code y − b = λ (b − x)} and the degrees across are {@code nx} on x's side,
     * {@code ny} on y's: {@code y2 = 2y − b + k (b − 2x + x2)}. Either side: for {@code A2} pass the row reversed,
     * {@code 1/λ} and the degrees swapped.
     */
    static void solveOuter(double[] x2, double[] x, double[] b, double[] y, double lambda, int nx, int ny, double[] dest) {
        double k = secondRatio(lambda, nx, ny);
        for (int q = 0; q < 3; q++) {
            dest[q] = 2 * y[q] - b[q] + k * (b[q] - 2 * x[q] + x2[q]);
        }
    }

    /** The positions of join {@code t}'s nodes A2, A, B, C, C2 in {@code scene} (the join must have second rows). */
    static double[][] row(Scene scene, WeldIndex welds, SmoothJoins joins, int t) {
        int[] nodes = {joins.outer(t, 0), joins.node(t, 0), joins.node(t, 1), joins.node(t, 2), joins.outer(t, 1)};
        double[][] out = new double[5][3];
        for (int r = 0; r < 5; r++) {
            PointRef p = welds.ref(nodes[r], scene);
            for (int q = 0; q < 3; q++) {
                out[r][q] = scene.patches().get(p.patch()).get(p.i(), p.j(), q);
            }
        }
        return out;
    }

    /** The residual of join {@code t} in {@code scene} relative to the model's size. */
    static double relativeResidual(Scene scene, WeldIndex welds, SmoothJoins joins, int t) {
        double[][] r = row(scene, welds, joins, t);
        return residual(r[0], r[1], r[2], r[3], r[4], joins.degree(t, 0), joins.degree(t, 1)) / size(scene);
    }

    /** The joins of {@code scene} that are curvature-continuous: tangent-continuous, with second rows, within {@link #HOLDS}. */
    static List<Integer> holding(Scene scene, WeldIndex welds, SmoothJoins joins) {
        List<Integer> out = new ArrayList<>();
        for (int t = 0; t < joins.count(); t++) {
            if (joins.hasOuter(t)) {
                double[][] r = row(scene, welds, joins, t);
                if (SmoothJoins.holds(r[1], r[2], r[3], welds.tolerance())
                        && residual(r[0], r[1], r[2], r[3], r[4], joins.degree(t, 0), joins.degree(t, 1)) <= HOLDS * size(scene)) {
                    out.add(t);
                }
            }
        }
        return out;
    }

    /**
     * The G2 check: the largest relative residual over the joins {@code kept} in {@code scene} (0 for none).
     * A model is curvature-continuous across its kept borders to {@code ε} when this is at most {@code ε}.
     */
    static double worstResidual(Scene scene, WeldIndex welds, SmoothJoins joins, List<Integer> kept) {
        double worst = 0;
        for (int t : kept) {
            worst = Math.max(worst, relativeResidual(scene, welds, joins, t));
        }
        return worst;
    }

    /** The G2 check over every join of {@code scene} that has second rows (welds and joins found afresh). */
    public static double worstResidual(Scene scene) {
        Topology topology = Topology.of(scene, true);
        List<Integer> all = new ArrayList<>();
        for (int t = 0; t < topology.joins().count(); t++) {
            if (topology.joins().hasOuter(t)) {
                all.add(t);
            }
        }
        return worstResidual(scene, topology.welds(), topology.joins(), all);
    }

    /** The model's size: the diagonal of its control box (1 for an empty one). */
    static double size(Scene scene) {
        double d = scene.patchCount() == 0 ? 0 : scene.controlBounds().diagonal();
        return d > 0 ? d : 1;
    }

    static double dist(double[] p, double[] q) {
        double x = p[0] - q[0], y = p[1] - q[1], z = p[2] - q[2];
        return Math.sqrt(x * x + y * y + z * z);
    }
}
