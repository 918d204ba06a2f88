package org.beziertracer.app;

import java.util.Arrays;
import java.util.EnumSet;
import java.util.Objects;

import org.beziertracer.intersect.Method;
import org.beziertracer.math.Vec3;
import org.beziertracer.render.Analysis;
import org.beziertracer.render.ShadingMode;

/**
 * The toolbox state as one immutable value: which {@link Toggle}s are on, the value of every
 * {@link Level}, the intersection {@link Method}, the {@link LightPlacement} and — once the light
 * was dragged — its offset from the placement's preset position. Typed once (no
 * strings); {@link RenderChoices} turns it into what the renderer takes. Every change makes a new
 * value, so a snapshot can be handed to other threads.
 */
public final class Settings {

    private final EnumSet<Toggle> on;
    private final int[] levels;
    private final Method method;
    private final LightPlacement light;
    private final Vec3 lightOffset;
    /** The analysis view shown instead of the shading, or null. */
    private final ShadingMode analysis;
    /** The analysis views' settings (View → Analysis → Analysis Settings…). */
    private final Analysis analysisSettings;

    private Settings(EnumSet<Toggle> on, int[] levels, Method method, LightPlacement light, Vec3 lightOffset,
                     ShadingMode analysis) {
        this(on, levels, method, light, lightOffset, analysis, Analysis.defaults());
    }

    private Settings(EnumSet<Toggle> on, int[] levels, Method method, LightPlacement light, Vec3 lightOffset,
                     ShadingMode analysis, Analysis analysisSettings) {
        this.analysisSettings = Objects.requireNonNull(analysisSettings);
        if (analysis != null && !analysis.isAnalysis()) {
            throw new IllegalArgumentException(analysis.label() + " is not an analysis view");
        }
        this.analysis = analysis;
        this.on = on;
        this.levels = levels;
        this.method = Objects.requireNonNull(method);
        this.light = Objects.requireNonNull(light);
        this.lightOffset = lightOffset;
    }

    /** The settings of a fresh app. */
    public static Settings defaults() {
        EnumSet<Toggle> on = EnumSet.noneOf(Toggle.class);
        for (Toggle t : Toggle.values()) {
            if (t.initial()) {
                on.add(t);
            }
        }
        int[] levels = new int[Level.values().length];
        for (Level l : Level.values()) {
            levels[l.ordinal()] = l.initial();
        }
        return new Settings(on, levels, Method.CLIPPING, LightPlacement.EYE_ABOVE_LEFT, null, null);
    }

    public boolean on(Toggle t) { return on.contains(t); }

    public int level(Level l) { return levels[l.ordinal()]; }

    public Method method() { return method; }

    public LightPlacement light() { return light; }

    /** Where the light is, in the units of its placement's {@link LightPlacement#frame() frame}: dragged there, or the preset. */
    public Vec3 lightOffset() { return lightOffset != null ? lightOffset : light.preset(); }

    /** True when the light was dragged away from its preset position. */
    public boolean lightMoved() { return lightOffset != null; }

    public Settings with(Toggle t, boolean value) {
        EnumSet<Toggle> copy = EnumSet.copyOf(on);
        if (value) {
            copy.add(t);
        } else {
            copy.remove(t);
        }
        return new Settings(copy, levels, method, light, lightOffset, analysis, analysisSettings);
    }

    /** @throws IllegalArgumentException one line, when {@code value} is outside the level's range */
    public Settings with(Level l, int value) {
        int[] copy = levels.clone();
        copy[l.ordinal()] = l.check(value);
        return new Settings(EnumSet.copyOf(on), copy, method, light, lightOffset, analysis, analysisSettings);
    }

    public Settings with(Method m) { return new Settings(EnumSet.copyOf(on), levels, m, light, lightOffset, analysis, analysisSettings); }

    /** Another placement, its light at the preset position. */
    public Settings with(LightPlacement p) { return new Settings(EnumSet.copyOf(on), levels, method, p, null, analysis, analysisSettings); }

    /** The light dragged to {@code offset} (in the placement's frame; ignored for {@link LightPlacement#SCENE}). */
    public Settings withLightOffset(Vec3 offset) {
        return new Settings(EnumSet.copyOf(on), levels, method, light, light.preset() == null ? null : offset, analysis, analysisSettings);
    }

    /** The analysis view shown instead of the shading ({@link ShadingMode#isAnalysis()}), or null for none. */
    public Settings withAnalysis(ShadingMode view) {
        return new Settings(EnumSet.copyOf(on), levels, method, light, lightOffset, view, analysisSettings);
    }

    /** With the analysis views' settings {@code a}. */
    public Settings withAnalysisSettings(Analysis a) {
        return new Settings(EnumSet.copyOf(on), levels, method, light, lightOffset, analysis, a);
    }

    /** The analysis views' settings. */
    public Analysis analysisSettings() { return analysisSettings; }

    /** The analysis view (View → Analysis), or null. */
    public ShadingMode analysis() { return analysis; }

    /** Horizontal field of view of the {@link Level#PERSPECTIVE} position. */
    public double fovDegrees() {
        return level(Level.PERSPECTIVE) * OrbitView.MAX_FOV_DEGREES / 100.0;
    }

    /** The {@link Level#PERSPECTIVE} position of a field of view (inverse of {@link #fovDegrees()}). */
    public static int perspectiveOf(double fovDegrees) {
        return (int) Math.round(Math.min(OrbitView.MAX_FOV_DEGREES, fovDegrees) * 100 / OrbitView.MAX_FOV_DEGREES);
    }

    /** 0 (exact surface) or the K of the tessellated mode. */
    public int tessellate() {
        return on(Toggle.TESSELLATED) ? level(Level.TESSELLATION) : 0;
    }

    /** What the status bar shows for the intersection: the method, or "tessellated K". */
    public String intersectionLabel() {
        return on(Toggle.TESSELLATED) ? "tessellated " + level(Level.TESSELLATION) : method.label();
    }

    /** An analysis view wins; then normals over Phong; neither is flat. */
    public ShadingMode shading() {
        return analysis != null ? analysis : on(Toggle.NORMALS) ? ShadingMode.NORMALS : on(Toggle.PHONG) ? ShadingMode.PHONG : ShadingMode.FLAT;
    }

    /** Samples per pixel rendered: the chosen level while super-sampling, else 1. */
    public int samplesPerPixel() {
        return on(Toggle.SUPER_SAMPLING) ? level(Level.SAMPLES_PER_PIXEL) : 1;
    }

    /** True when the picture is path traced: Render → Path Traced on and no analysis view shown. */
    public boolean pathTraced() {
        return on(Toggle.PATH_TRACED) && analysis == null;
    }

    /**
     * The exposure of the path-traced picture in stops ({@link Level#EXPOSURE} tenths ÷ 10: the same
     * double as {@code render --exposure} given that decimal).
     */
    public double exposure() {
        return level(Level.EXPOSURE) / 10.0;
    }

    /** True when the settings differ at most in their {@link Level#EXPOSURE} (a change that needs no new render). */
    public boolean sameButExposure(Settings other) {
        return other != null && with(Level.EXPOSURE, 0).equals(other.with(Level.EXPOSURE, 0));
    }

    /** True when control points are shown and can be picked (their toggle decides, in both views). */
    public boolean pointsShown() {
        return on(Toggle.CONTROL_POINTS);
    }

    /** True when the control polygon is drawn (its toggle decides, in both views). */
    public boolean polygonShown() {
        return on(Toggle.CONTROL_POLYGON);
    }

    /** True when the projected iso-curves are drawn (always in the wireframe view). */
    public boolean isoCurvesShown() {
        return on(Toggle.WIREFRAME) || !on(Toggle.RAY_TRACE);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Settings s && s.on.equals(on) && Arrays.equals(s.levels, levels) && s.method == method
                && s.light == light && Objects.equals(s.lightOffset, lightOffset) && s.analysis == analysis
                && s.analysisSettings.equals(analysisSettings);
    }

    @Override
    public int hashCode() {
        return Objects.hash(on, Arrays.hashCode(levels), method, light, lightOffset, analysis, analysisSettings);
    }

    @Override
    public String toString() {
        return "Settings" + on + Arrays.toString(levels) + method + "/" + light + (lightOffset == null ? "" : lightOffset)
                + (analysis == null ? "" : "/analysis " + analysis.label());
    }
}
