package org.beziertracer.render;

import java.util.Arrays;

import org.beziertracer.geometry.SurfaceCurvature;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;

/**
 * The ends of a curvature view's colour scale: the job's own ({@link Analysis#rangeLow},
 * {@code rangeHigh}), or automatic, from the values in view: a fixed grid of {@value #GRID_X} ×
 * {@value #GRID_Y} camera rays is traced before the frame and the curvature measured at each hit;
 * the scale spans the 2nd to the 98th percentile (radii, on their logarithmic axis) or ± the 90th
 * percentile of |value| (K and H, symmetric about zero), so that a few extreme points (a pole, a
 * sharp fillet) do not wash out the rest. Deterministic: the same job gives the same range on any
 * machine and thread count.
 */
public final class AnalysisRange {
    private AnalysisRange() {}

    static final int GRID_X = 64, GRID_Y = 48;
    private static final double LOW_PERCENTILE = 0.02, HIGH_PERCENTILE = 0.98, SIGNED_PERCENTILE = 0.9;

    /** {@code {low, high}} for the curvature view of {@code job}; {@code {0, 1}} for any other view. */
    public static double[] of(RenderJob job) {
        ShadingMode mode = job.shading();
        Analysis a = job.options().analysis();
        if (!mode.needsCurvature()) {
            return new double[] {0, 1};
        }
        if (!a.autoRange()) {
            return new double[] {a.rangeLow(), a.rangeHigh()};
        }
        double[] values = sample(job, mode);
        int n = values.length;
        boolean radius = AnalysisColours.radius(mode);
        if (radius) {
            int finite = 0;
            for (double v : values) {
                if (v < Double.POSITIVE_INFINITY && v > 0) {
                    values[finite++] = v;
                }
            }
            n = finite;
        } else {
            for (int k = 0; k < n; k++) {
                values[k] = Math.abs(values[k]);
            }
        }
        double size = RenderJob.bounds(job.scene()).diagonal();
        size = size > 0 && Double.isFinite(size) ? size : 1;
        if (n == 0) {
            // nothing curved in view: a scale from a hundredth of the scene's size to a hundred times it
            return radius ? new double[] {size / 100, size * 100} : new double[] {-1 / size, 1 / size};
        }
        Arrays.sort(values, 0, n);
        double high = values[Math.min(n - 1, (int) Math.floor((radius ? HIGH_PERCENTILE : SIGNED_PERCENTILE) * (n - 1)))];
        if (radius) {
            double low = values[(int) Math.floor(LOW_PERCENTILE * (n - 1))];
            if (!(high > low * 1.01)) {
                low /= 2;
                high *= 2;
            }
            return new double[] {low, high};
        }
        double bound = high > 0 ? high : 1e-9 / (size * size);
        return new double[] {-bound, bound};
    }

    /** The curvature values of {@code mode} at the hits of the grid's rays (misses left out). */
    private static double[] sample(RenderJob job, ShadingMode mode) {
        SceneIntersector si = job.intersector();
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] ray = new double[6], c = new double[SurfaceCurvature.LENGTH];
        double[] out = new double[GRID_X * GRID_Y];
        int n = 0;
        int w = job.width(), h = job.height();
        for (int j = 0; j < GRID_Y; j++) {
            for (int i = 0; i < GRID_X; i++) {
                job.camera().generateRay((i + 0.5) * w / GRID_X, (j + 0.5) * h / GRID_Y, w, h, ray);
                if (si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, hit)) {
                    si.surfacePoint(ctx, hit, sp);
                    si.curvature(ctx, hit, sp, c);
                    double v = AnalysisColours.value(mode, c);
                    if (!Double.isNaN(v)) {
                        out[n++] = v;
                    }
                }
            }
        }
        return Arrays.copyOf(out, n);
    }
}
