package org.beziertracer.app;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * The control polygon and the memoir's cheap wireframe for the patches chosen by
 * {@link ExtentBudget}: iso-curves evaluated with de Casteljau on the <b>projected</b> 2-D control
 * points (not projectively exact, but fast, and exact for a parallel projection by affine
 * invariance), with fewer subdivisions on patches too small on screen to show them. Not
 * thread-safe (one per build).
 */
final class OverlayDetails {

    private final PatchProjection projection;
    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
    private final List<float[]> polygon = new ArrayList<>();
    private final List<float[]> curves = new ArrayList<>();

    OverlayDetails(PatchProjection projection) {
        this.projection = projection;
    }

    /** Segments of the control polygon of a patch: rows and columns of its net. */
    static long polygonCost(BezierPatch p) {
        return (long) p.degreeU() * (p.degreeV() + 1) + (long) p.degreeV() * (p.degreeU() + 1);
    }

    /** Pixels per iso-curve step below which finer subdivisions add nothing visible. */
    static final double MIN_STEP_PIXELS = 3;

    /**
     * The subdivisions a patch of this on-screen extent gets: the chosen {@code k}, fewer when its
     * steps would be shorter than {@value #MIN_STEP_PIXELS} pixels (at least 1).
     */
    static int subdivisions(int k, double extent) {
        return (int) Math.max(1, Math.min(k, Math.ceil(extent / MIN_STEP_PIXELS)));
    }

    /** Polyline points of a patch's iso-curves at {@code k} subdivisions. */
    static long curveCost(int k) {
        return 2L * (k + 1) * (k + 1);
    }

    /**
     * Adds the polygon and/or the iso-curves of every patch whose extent reaches its threshold.
     *
     * @param extent       per patch, negative when not drawn
     * @param polygonFrom  smallest extent that gets its polygon (infinity: none)
     * @param curvesFrom   smallest extent that gets iso-curves (infinity: none)
     * @param k            iso-curve subdivisions per direction
     */
    void add(Scene scene, float[] extent, double polygonFrom, double curvesFrom, int k) {
        for (int p = 0; p < extent.length; p++) {
            boolean polygon = extent[p] >= 0 && extent[p] >= polygonFrom;
            boolean iso = extent[p] >= 0 && extent[p] >= curvesFrom;
            if (!polygon && !iso) {
                continue;
            }
            BezierPatch patch = scene.patches().get(p);
            projection.project(patch);
            if (polygon) {
                addPolygon(patch.degreeU(), patch.degreeV());
            }
            if (iso) {
                addIsoCurves(patch.degreeU(), patch.degreeV(), subdivisions(k, extent[p]));
            }
        }
    }

    /** The rows, then the columns, of the projected net as polylines. */
    private void addPolygon(int n, int m) {
        for (int j = 0; j <= m; j++) {
            polygon.add(line(projection.xy, n, j * (n + 1), 1));
        }
        for (int i = 0; i <= n; i++) {
            polygon.add(line(projection.xy, m, i, n + 1));
        }
    }

    /** The k + 1 iso-curves of constant v, then the k + 1 of constant u. */
    private void addIsoCurves(int n, int m, int k) {
        double[] grid = new double[2 * (k + 1) * (k + 1)];
        for (int b = 0; b <= k; b++) {
            for (int a = 0; a <= k; a++) {
                DeCasteljau.evaluate(projection.xy, 0, n, m, 2, (double) a / k, (double) b / k,
                        grid, 2 * (b * (k + 1) + a), scratch);
            }
        }
        for (int b = 0; b <= k; b++) {
            curves.add(line(grid, k, b * (k + 1), 1));
        }
        for (int a = 0; a <= k; a++) {
            curves.add(line(grid, k, a, k + 1));
        }
    }

    /** The k + 1 points {@code first, first + step, …} of a 2-D point array as a polyline. */
    private static float[] line(double[] grid, int k, int first, int step) {
        float[] line = new float[2 * (k + 1)];
        for (int t = 0; t <= k; t++) {
            line[2 * t] = (float) grid[2 * (first + t * step)];
            line[2 * t + 1] = (float) grid[2 * (first + t * step) + 1];
        }
        return line;
    }

    List<float[]> polygon() { return polygon; }

    List<float[]> curves() { return curves; }
}
