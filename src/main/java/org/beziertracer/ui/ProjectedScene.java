package org.beziertracer.ui;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The control nets of a scene projected to the screen, for drawing the control polygon and
 * points, picking, and the memoir's cheap wireframe: de Casteljau evaluated on the
 * <b>projected</b> 2-D control points (not projectively exact, but fast and close while the
 * patch is small against its distance to the eye).
 *
 * <h2>Layout</h2>
 * {@code xy[p]} holds, for patch {@code p}, {@code 2·(n+1)(m+1)} pixel coordinates in the
 * patch's own net order (u fastest); {@code depth[p]} the view depth of each point. A patch with
 * a point behind the eye is {@linkplain #isVisible(int) not visible} and never drawn or picked.
 *
 * <p>Immutable after construction; built on the event thread per paint, cheap (a few hundred
 * points).
 */
public final class ProjectedScene {

    private final Scene scene;
    private final double[][] xy;
    private final double[][] depth;
    private final boolean[] visible;

    public ProjectedScene(Scene scene, ScreenProjector projector) {
        this.scene = scene;
        int count = scene.patchCount();
        xy = new double[count][];
        depth = new double[count][];
        visible = new boolean[count];
        double[] out = new double[3];
        for (int p = 0; p < count; p++) {
            BezierPatch patch = scene.patches().get(p);
            double[] net = patch.copyNet();
            int points = patch.pointCount();
            xy[p] = new double[2 * points];
            depth[p] = new double[points];
            boolean ok = true;
            for (int k = 0; k < points && ok; k++) {
                ok = projector.project(net[3 * k], net[3 * k + 1], net[3 * k + 2], out);
                xy[p][2 * k] = out[0];
                xy[p][2 * k + 1] = out[1];
                depth[p][k] = out[2];
            }
            visible[p] = ok;
        }
    }

    public Scene scene() { return scene; }

    public boolean isVisible(int patch) { return visible[patch]; }

    /** Pixel x of {@code P_ij} of patch {@code p}. */
    public double x(int p, int i, int j) { return xy[p][2 * index(p, i, j)]; }

    /** Pixel y of {@code P_ij} of patch {@code p}. */
    public double y(int p, int i, int j) { return xy[p][2 * index(p, i, j) + 1]; }

    private int index(int p, int i, int j) {
        return j * (scene.patches().get(p).degreeU() + 1) + i;
    }

    /**
     * The control point nearest to pixel {@code (x, y)} within {@code radius} pixels, the
     * nearer to the eye on a tie; null when none.
     */
    public PointRef pick(double x, double y, double radius) {
        PointRef best = null;
        double bestD2 = radius * radius, bestDepth = Double.POSITIVE_INFINITY;
        for (int p = 0; p < xy.length; p++) {
            if (!visible[p]) {
                continue;
            }
            int n = scene.patches().get(p).degreeU();
            for (int k = 0; k < depth[p].length; k++) {
                double dx = xy[p][2 * k] - x, dy = xy[p][2 * k + 1] - y;
                double d2 = dx * dx + dy * dy;
                boolean nearer = d2 < bestD2 - 1e-9 || (d2 <= bestD2 + 1e-9 && depth[p][k] < bestDepth);
                if (d2 <= radius * radius && nearer) {
                    best = new PointRef(p, k % (n + 1), k / (n + 1));
                    bestD2 = d2;
                    bestDepth = depth[p][k];
                }
            }
        }
        return best;
    }

    /**
     * The projected wireframe: for each visible patch, the 2-D surface evaluated with
     * de Casteljau on the projected net at a {@code (k+1)×(k+1)} grid of parameters
     * {@code (a/k, b/k)}, returned as polylines ({@code x0,y0,x1,y1,…}): the {@code k+1}
     * iso-curves of constant v, then the {@code k+1} of constant u, per patch.
     *
     * @param k subdivisions per direction, at least 1
     */
    public List<double[]> isoCurves(int k) {
        int steps = Math.max(1, k);
        List<double[]> curves = new ArrayList<>();
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int p = 0; p < xy.length; p++) {
            if (!visible[p]) {
                continue;
            }
            BezierPatch patch = scene.patches().get(p);
            int n = patch.degreeU(), m = patch.degreeV();
            double[] grid = new double[2 * (steps + 1) * (steps + 1)];
            for (int b = 0; b <= steps; b++) {
                for (int a = 0; a <= steps; a++) {
                    DeCasteljau.evaluate(xy[p], 0, n, m, 2, (double) a / steps, (double) b / steps,
                            grid, 2 * (b * (steps + 1) + a), scratch);
                }
            }
            for (int b = 0; b <= steps; b++) {
                double[] line = new double[2 * (steps + 1)];
                System.arraycopy(grid, 2 * b * (steps + 1), line, 0, line.length);
                curves.add(line);
            }
            for (int a = 0; a <= steps; a++) {
                double[] line = new double[2 * (steps + 1)];
                for (int b = 0; b <= steps; b++) {
                    line[2 * b] = grid[2 * (b * (steps + 1) + a)];
                    line[2 * b + 1] = grid[2 * (b * (steps + 1) + a) + 1];
                }
                curves.add(line);
            }
        }
        return curves;
    }
}
