package org.beziertracer.render;

import java.util.Locale;

import org.beziertracer.geometry.SurfaceCurvature;
import org.beziertracer.intersect.Hit;
import org.beziertracer.intersect.SceneIntersector;
import org.beziertracer.intersect.SurfacePoint;
import org.beziertracer.intersect.TraceContext;

/**
 * The value an analysis view shows at one pixel, as text for a status bar: the camera ray through
 * the pixel's centre is traced and the view's quantity measured at its first hit, exactly as the
 * frame measures it ({@code "K = 0.00123 (k1 0.0402, k2 0.0306) on patch 7"}). Empty for a miss
 * and for the views that show no number (zebra, emap).
 */
public final class AnalysisProbe {
    private AnalysisProbe() {}

    /** The text for pixel {@code (x, y)} (pixels from the top left) of {@code job}'s picture. */
    public static String at(RenderJob job, double x, double y) {
        ShadingMode mode = job.shading();
        if (!mode.isAnalysis() || mode == ShadingMode.ZEBRA || mode == ShadingMode.EMAP
                || !(x >= 0 && y >= 0 && x < job.width() && y < job.height())) {
            return "";
        }
        SceneIntersector si = job.intersector();
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        SurfacePoint sp = new SurfacePoint();
        double[] ray = new double[6];
        job.camera().generateRay(Math.floor(x) + 0.5, Math.floor(y) + 0.5, job.width(), job.height(), ray);
        if (!si.closestHit(ctx, ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY, hit)) {
            return "";
        }
        si.surfacePoint(ctx, hit, sp);
        String where = hit.kind == Hit.PATCH ? " on patch " + (hit.index + 1) : "";
        Analysis a = job.options().analysis();
        if (mode == ShadingMode.DRAFT) {
            return String.format(Locale.ROOT, "draft %.2f°", AnalysisColours.draftAngle(a, sp.nx, sp.ny, sp.nz)) + where;
        }
        if (mode == ShadingMode.ISOPHOTES) {
            double len = Math.sqrt(ray[3] * ray[3] + ray[4] * ray[4] + ray[5] * ray[5]);
            double[] l = a.isophoteLight();
            double lx = l == null ? -ray[3] / len : l[0], ly = l == null ? -ray[4] / len : l[1], lz = l == null ? -ray[5] / len : l[2];
            double c = Math.abs(sp.nx * lx + sp.ny * ly + sp.nz * lz);
            return String.format(Locale.ROOT, "N·L %.4f (%.2f°)", c, Math.toDegrees(Math.acos(Math.min(1, c)))) + where;
        }
        double[] c = new double[SurfaceCurvature.LENGTH];
        si.curvature(ctx, hit, sp, c);
        double v = AnalysisColours.value(mode, c);
        String name = switch (mode) {
            case GAUSSIAN -> "K";
            case MEAN -> "H";
            case MIN_RADIUS -> "R min";
            default -> "R max";
        };
        return name + " = " + number(v) + " (k1 " + number(c[SurfaceCurvature.K1]) + ", k2 "
                + number(c[SurfaceCurvature.K2]) + ")" + where;
    }

    private static String number(double v) {
        return Double.isInfinite(v) ? "∞" : String.format(Locale.ROOT, "%.4g", v);
    }
}
