package org.beziertracer.app;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.geometry.DeCasteljau;
import org.beziertracer.geometry.TrimCurves;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimRegion;

/**
 * The control polygon and the memoir's cheap wireframe for the patches chosen by
 * {@link ExtentBudget}: iso-curves evaluated with de Casteljau on the <b>projected</b> 2-D control
 * points (not projectively exact, but fast, and exact for a parallel projection by affine
 * invariance; a rational patch through its projected points and its weights), with fewer
 * subdivisions on patches too small on screen to show them. On a trimmed patch the iso-curves
 * stop where they leave the trim region (tested at their points on the exact trim curves), and
 * the trim curves within the patch's part of its surface are drawn too, as curves on the
 * projected surface. Not thread-safe (one per build).
 */
final class OverlayDetails {

    private final PatchProjection projection;
    private final double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
    private final List<float[]> polygon = new ArrayList<>();
    private final List<float[]> curves = new ArrayList<>();
    private final double[] point = new double[3];
    /** Each trim region's curves and their sampled polylines, made once per build. */
    private final Map<TrimRegion, TrimCurves> trims = new IdentityHashMap<>();
    private final Map<TrimRegion, List<double[]>> trimLines = new IdentityHashMap<>();
    private final double[] trimScratch = new double[TrimCurves.SCRATCH_LENGTH];

    /** Points per trim-curve segment drawn. */
    static final int TRIM_SAMPLES = 24;

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
                addIsoCurves(patch, subdivisions(k, extent[p]));
                if (patch.trim() != null) {
                    addTrimCurves(patch);
                }
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

    /** The k + 1 iso-curves of constant v, then the k + 1 of constant u (broken outside a trim region). */
    private void addIsoCurves(BezierPatch patch, int k) {
        double[] grid = new double[2 * (k + 1) * (k + 1)];
        boolean[] kept = patch.trim() == null ? null : new boolean[(k + 1) * (k + 1)];
        TrimCurves trim = patch.trim() == null ? null : trims.computeIfAbsent(patch.trim(), TrimCurves::of);
        PatchDomain d = patch.domain();
        for (int b = 0; b <= k; b++) {
            for (int a = 0; a <= k; a++) {
                double s = (double) a / k, t = (double) b / k;
                onScreen(patch, s, t, grid, 2 * (b * (k + 1) + a));
                if (kept != null) {
                    kept[b * (k + 1) + a] = trim.contains(d.u0() + s * (d.u1() - d.u0()), d.v0() + t * (d.v1() - d.v0()),
                            trimScratch);
                }
            }
        }
        for (int b = 0; b <= k; b++) {
            addRuns(grid, kept, k, b * (k + 1), 1);
        }
        for (int a = 0; a <= k; a++) {
            addRuns(grid, kept, k, a, k + 1);
        }
    }

    /** The trim curves where they cross the patch's part of its surface, on the projected patch. */
    private void addTrimCurves(BezierPatch patch) {
        TrimRegion region = patch.trim();
        List<double[]> lines = trimLines.computeIfAbsent(region,
                r -> trims.computeIfAbsent(r, TrimCurves::of).polylines(TRIM_SAMPLES));
        PatchDomain d = patch.domain();
        double du = d.u1() - d.u0(), dv = d.v1() - d.v0();
        for (double[] uv : lines) {
            int count = uv.length / 2;
            double[] screen = new double[uv.length];
            boolean[] inside = new boolean[count];
            for (int i = 0; i < count; i++) {
                double s = (uv[2 * i] - d.u0()) / du, t = (uv[2 * i + 1] - d.v0()) / dv;
                inside[i] = s >= 0 && s <= 1 && t >= 0 && t <= 1;
                if (inside[i]) {
                    onScreen(patch, s, t, screen, 2 * i);
                }
            }
            addRuns(screen, inside, count - 1, 0, 1);
        }
    }

    /** The projected surface point at the patch's own {@code (s,t)} into {@code out[o..o+2)}. */
    private void onScreen(BezierPatch patch, double s, double t, double[] out, int o) {
        int n = patch.degreeU(), m = patch.degreeV();
        if (!projection.rational) {
            DeCasteljau.evaluate(projection.xy, 0, n, m, 2, s, t, out, o, scratch);
            return;
        }
        DeCasteljau.evaluate(projection.xyw, 0, n, m, 3, s, t, point, 0, scratch);
        out[o] = point[0] / point[2];
        out[o + 1] = point[1] / point[2];
    }

    /**
     * The k + 1 points {@code first, first + step, …} as polylines: all of them, or (with
     * {@code kept}) each run of at least two kept points.
     */
    private void addRuns(double[] grid, boolean[] kept, int k, int first, int step) {
        if (kept == null) {
            curves.add(line(grid, k, first, step));
            return;
        }
        int t = 0;
        while (t <= k) {
            while (t <= k && !kept[first + t * step]) {
                t++;
            }
            int start = t;
            while (t <= k && kept[first + t * step]) {
                t++;
            }
            if (t - start >= 2) {
                curves.add(line(grid, t - start - 1, first + start * step, step));
            }
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
