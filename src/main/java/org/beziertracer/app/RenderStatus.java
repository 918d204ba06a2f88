package org.beziertracer.app;

import org.beziertracer.intersect.Method;
import org.beziertracer.render.ShadingMode;

/**
 * What the status bar shows about the latest render; made on render threads, shown on the UI
 * thread.
 *
 * @param pass           1-based pass just finished
 * @param passCount      passes of a full frame
 * @param millis         time since the render started
 * @param mraysPerSecond millions of rays (all kinds) per second
 * @param spp            samples per pixel of the final pass
 * @param method         solver
 * @param bvh            sub-patch BVH on
 * @param bvhSpeedUp     measured frame time without the BVH divided by the time with it, for the
 *                       same picture; 0 when not measured yet
 * @param prepMillis     time to re-split and refit (or build) the scene snapshot
 * @param tessellate     0: exact; {@code K ≥ 1}: rendered as a K×K triangle mesh per patch
 * @param shading        what the picture shows (an analysis view has a legend)
 * @param analysisLow, analysisHigh the ends of a curvature view's colour scale
 * @param samplesDone    path traced: the samples every pixel has so far (0 while the first is being
 *                       traced; {@code spp} at the end); -1 for the Whitted renderer
 * @param samplesPerSecond path traced: camera samples (whole paths) traced a second so far
 */
public record RenderStatus(int pass, int passCount, double millis, double mraysPerSecond, int spp, Method method,
                           boolean bvh, double bvhSpeedUp, double prepMillis, int tessellate, ShadingMode shading,
                           double analysisLow, double analysisHigh, int samplesDone, double samplesPerSecond) {

    /** A status of the Whitted renderer. */
    public RenderStatus(int pass, int passCount, double millis, double mraysPerSecond, int spp, Method method,
                        boolean bvh, double bvhSpeedUp, double prepMillis, int tessellate, ShadingMode shading,
                        double analysisLow, double analysisHigh) {
        this(pass, passCount, millis, mraysPerSecond, spp, method, bvh, bvhSpeedUp, prepMillis, tessellate, shading,
                analysisLow, analysisHigh, -1, 0);
    }

    /** True for a path-traced picture. */
    public boolean pathTraced() { return samplesDone >= 0; }

    /**
     * The status bar's samples text: {@code "4 spp"} for Whitted; path traced, the samples so far
     * of the target and the rate, {@code "37 of 256 spp, 412k samples/s"}.
     */
    public String samplesText() {
        if (!pathTraced()) {
            return spp + " spp";
        }
        double r = samplesPerSecond;
        String rate = r >= 1e6 ? String.format(java.util.Locale.ROOT, "%.2fM", r / 1e6)
                : r >= 1e3 ? String.format(java.util.Locale.ROOT, "%.0fk", r / 1e3)
                : String.format(java.util.Locale.ROOT, "%.0f", r);
        return samplesDone + " of " + spp + " spp, " + rate + " samples/s";
    }

    /** A status of a shaded (not analysed) picture. */
    public RenderStatus(int pass, int passCount, double millis, double mraysPerSecond, int spp, Method method,
                        boolean bvh, double bvhSpeedUp, double prepMillis, int tessellate) {
        this(pass, passCount, millis, mraysPerSecond, spp, method, bvh, bvhSpeedUp, prepMillis, tessellate,
                ShadingMode.PHONG, 0, 1);
    }

    /**
     * The legend of an analysis view for the status bar: the view and, for a curvature view, the
     * values at the two ends of its colour scale ({@code "gaussian −0.0096 … 0.0096"}); empty for
     * the shaded views.
     */
    public String legend() {
        if (shading == null || !shading.isAnalysis()) {
            return "";
        }
        if (!shading.needsCurvature()) {
            return shading.label();
        }
        return shading.label() + " " + number(analysisLow) + " … " + number(analysisHigh)
                + (shading == ShadingMode.GAUSSIAN ? " (√ scale)" : shading.label().endsWith("radius") ? " (log scale)" : "");
    }

    private static String number(double v) {
        return String.format(java.util.Locale.ROOT, "%.3g", v).replace('-', '−');
    }
}
