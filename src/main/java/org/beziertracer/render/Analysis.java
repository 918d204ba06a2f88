package org.beziertracer.render;

import java.util.Locale;

/**
 * The settings of the surface-analysis views ({@link ShadingMode#isAnalysis()}), one record for
 * all of them, each view reading its own:
 *
 * @param zebraAxis      the direction the light bars of {@code zebra} run along (unit; default z)
 * @param zebraStripes   bars around the axis, 2..200 (a dark and a light stripe each)
 * @param zebraWidth     the dark share of each bar's period, in (0, 1)
 * @param isophoteLight  the direction toward the light of {@code isophotes} (unit), or null: from
 *                       the eye, along each camera ray
 * @param isophoteStep   degrees of {@code acos(N·L)} between two isophotes, 0.5..90
 * @param rangeLow, rangeHigh the curvature (or radius) shown at the two ends of the colour scale,
 *                       or both NaN: automatic, from robust percentiles of the values in view
 *                       ({@link AnalysisRange})
 * @param draftPull      the pull direction of {@code draft} (unit; default z)
 * @param draftTolerance degrees within which a face counts as vertical (neither positive nor
 *                       negative draft), 0..45
 * @param environment    the image {@code emap} reflects, or null for the built-in studio
 *                       ({@link EnvironmentMap#studio()}, made on first use: a render without
 *                       the {@code emap} view never pays the 30–70 ms of making it)
 */
public record Analysis(double[] zebraAxis, int zebraStripes, double zebraWidth, double[] isophoteLight,
                       double isophoteStep, double rangeLow, double rangeHigh, double[] draftPull,
                       double draftTolerance, EnvironmentMap environment) {

    /** With the built-in studio environment. */
    public Analysis(double[] zebraAxis, int zebraStripes, double zebraWidth, double[] isophoteLight,
                    double isophoteStep, double rangeLow, double rangeHigh, double[] draftPull, double draftTolerance) {
        this(zebraAxis, zebraStripes, zebraWidth, isophoteLight, isophoteStep, rangeLow, rangeHigh, draftPull,
                draftTolerance, null);
    }

    public Analysis {
        zebraAxis = unit("zebra axis", zebraAxis);
        isophoteLight = isophoteLight == null ? null : unit("isophote light", isophoteLight);
        draftPull = unit("pull direction", draftPull);
        if (zebraStripes < 2 || zebraStripes > 200) {
            throw new IllegalArgumentException("zebra stripes must be 2..200, got " + zebraStripes);
        }
        if (!(zebraWidth > 0 && zebraWidth < 1)) {
            throw new IllegalArgumentException("zebra width must be between 0 and 1, got " + zebraWidth);
        }
        if (!(isophoteStep >= 0.5 && isophoteStep <= 90)) {
            throw new IllegalArgumentException("isophote step must be 0.5..90 degrees, got " + isophoteStep);
        }
        if (!(draftTolerance >= 0 && draftTolerance <= 45)) {
            throw new IllegalArgumentException("draft tolerance must be 0..45 degrees, got " + draftTolerance);
        }
        boolean auto = Double.isNaN(rangeLow) && Double.isNaN(rangeHigh);
        if (!auto && !(Double.isFinite(rangeLow) && Double.isFinite(rangeHigh) && rangeLow < rangeHigh)) {
            throw new IllegalArgumentException("analysis range must be two finite numbers, low < high, got "
                    + rangeLow + ", " + rangeHigh);
        }
    }

    /** Bars along z, 16 of them, half dark; isophotes every 10° from the eye; automatic range; pull along z, 1°. */
    public static Analysis defaults() {
        return new Analysis(new double[] {0, 0, 1}, 16, 0.5, null, 10, Double.NaN, Double.NaN, new double[] {0, 0, 1}, 1);
    }

    /** The image {@code emap} reflects: the one given, or the built-in studio. */
    @Override
    public EnvironmentMap environment() {
        return environment != null ? environment : EnvironmentMap.studio();
    }

    /** True when the curvature range comes from the values in view. */
    public boolean autoRange() { return Double.isNaN(rangeLow); }

    public Analysis withRange(double low, double high) {
        return new Analysis(zebraAxis, zebraStripes, zebraWidth, isophoteLight, isophoteStep, low, high, draftPull,
                draftTolerance, environment);
    }

    public Analysis withZebra(double[] axis, int stripes, double width) {
        return new Analysis(axis, stripes, width, isophoteLight, isophoteStep, rangeLow, rangeHigh, draftPull,
                draftTolerance, environment);
    }

    public Analysis withIsophotes(double[] light, double step) {
        return new Analysis(zebraAxis, zebraStripes, zebraWidth, light, step, rangeLow, rangeHigh, draftPull,
                draftTolerance, environment);
    }

    public Analysis withDraft(double[] pull, double tolerance) {
        return new Analysis(zebraAxis, zebraStripes, zebraWidth, isophoteLight, isophoteStep, rangeLow, rangeHigh, pull,
                tolerance, environment);
    }

    /** With {@code image} reflected by {@code emap}. */
    public Analysis withEnvironment(EnvironmentMap image) {
        return new Analysis(zebraAxis, zebraStripes, zebraWidth, isophoteLight, isophoteStep, rangeLow, rangeHigh,
                draftPull, draftTolerance, image);
    }

    private static double[] unit(String what, double[] v) {
        if (v == null || v.length != 3) {
            throw new IllegalArgumentException(what + " must be three numbers x,y,z");
        }
        double len = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        if (!(len > 0) || !Double.isFinite(len)) {
            throw new IllegalArgumentException(what + " must be a non-zero finite direction, got "
                    + String.format(Locale.ROOT, "%s,%s,%s", v[0], v[1], v[2]));
        }
        return new double[] {v[0] / len, v[1] / len, v[2] / len};
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Analysis a && java.util.Arrays.equals(zebraAxis, a.zebraAxis) && zebraStripes == a.zebraStripes
                && zebraWidth == a.zebraWidth && java.util.Arrays.equals(isophoteLight, a.isophoteLight)
                && isophoteStep == a.isophoteStep && Double.compare(rangeLow, a.rangeLow) == 0
                && Double.compare(rangeHigh, a.rangeHigh) == 0 && java.util.Arrays.equals(draftPull, a.draftPull)
                && draftTolerance == a.draftTolerance && environment == a.environment;
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(java.util.Arrays.hashCode(zebraAxis), zebraStripes, zebraWidth,
                java.util.Arrays.hashCode(isophoteLight), isophoteStep, rangeLow, rangeHigh,
                java.util.Arrays.hashCode(draftPull), draftTolerance, System.identityHashCode(environment));
    }
}
