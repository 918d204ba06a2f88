package org.beziertracer.render;

/**
 * The colour scale of a curvature view, for a legend drawn beside the picture: the colour at a
 * fraction {@code f ∈ [0, 1]} of the way from the scale's low end to its high end, on the view's
 * own axis (linear for H, square-root for K, logarithmic for the radii), exactly as
 * {@link AnalysisColours} colours a point of that value facing the viewer; and the value there.
 */
public final class AnalysisLegend {
    private AnalysisLegend() {}

    /** The value at fraction {@code f} of the scale {@code [low, high]} of {@code mode}. */
    public static double valueAt(ShadingMode mode, double low, double high, double f) {
        if (AnalysisColours.radius(mode)) {
            return Math.exp(Math.log(low) + f * (Math.log(high) - Math.log(low)));
        }
        double bound = Math.max(Math.abs(low), Math.abs(high));
        double t = 2 * f - 1;
        return mode == ShadingMode.GAUSSIAN ? Math.copySign(t * t, t) * bound : t * bound;
    }

    /** The colour (linear RGB) at fraction {@code f} of the scale, into {@code out}. */
    public static void colourAt(ShadingMode mode, double low, double high, double f, double[] out) {
        if (!mode.needsCurvature()) {
            throw new IllegalArgumentException(mode.label() + " has no colour scale");
        }
        AnalysisColours.curvature(mode, valueAt(mode, low, high, f), low, high, 1, out);
    }
}
