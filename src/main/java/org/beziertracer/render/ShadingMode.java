package org.beziertracer.render;

import java.util.Locale;

import org.beziertracer.model.io.Echo;

/**
 * What a primary hit shows. The normal used everywhere is the unit geometric normal
 * ({@code dpdu × dpdv} for patches, outward for spheres, the given normal for planes)
 * <b>flipped toward the viewer</b> when it faces away, so surfaces are two-sided.
 */
public enum ShadingMode {
    /** Whitted ray tracing with Phong local illumination, shadows, reflection and refraction. */
    PHONG("phong"),
    /** Unlit base (or checker) colour. */
    FLAT("flat"),
    /** {@code (n + 1) / 2} of the unit normal, flipped toward the viewer. */
    NORMALS("normals"),
    /** Debug: red = u, green = v, blue = 0 (planes: fractional part of the plane uv). */
    UV("uv"),
    /** Debug: one distinct colour per patch; planes grey, spheres white. */
    PATCH_ID("patch-id"),
    /** Analysis: the reflection of parallel light bars (stripes along {@link Analysis#zebraAxis}). */
    ZEBRA("zebra", true),
    /** Analysis: an environment image reflected in the surface ({@link Analysis#environment}, the built-in studio by default). */
    EMAP("emap", true),
    /** Analysis: lines of constant N·L every {@link Analysis#isophoteStep} degrees over a grey N·L shading. */
    ISOPHOTES("isophotes", true),
    /** Analysis: Gaussian curvature K = k1 k2 in false colour (blue negative, white 0, red positive). */
    GAUSSIAN("gaussian", true),
    /** Analysis: mean curvature H = (k1 + k2)/2 in false colour, signed against the surface's own normal. */
    MEAN("mean", true),
    /** Analysis: the smallest radius of curvature, 1/max(|k1|, |k2|), on a logarithmic scale. */
    MIN_RADIUS("min-radius", true),
    /** Analysis: the largest radius of curvature, 1/min(|k1|, |k2|), on a logarithmic scale (flat: the top). */
    MAX_RADIUS("max-radius", true),
    /** Analysis: the draft angle against {@link Analysis#draftPull}: positive green, negative red, vertical yellow. */
    DRAFT("draft", true);

    private final String label;
    private final boolean analysis;

    ShadingMode(String label) { this(label, false); }

    ShadingMode(String label, boolean analysis) {
        this.label = label;
        this.analysis = analysis;
    }

    public String label() { return label; }

    /** True for the surface-analysis views (exact derivatives at each hit; {@link Analysis} settings). */
    public boolean isAnalysis() { return analysis; }

    /** True for the views that need the curvature at each hit. */
    public boolean needsCurvature() { return this == GAUSSIAN || this == MEAN || this == MIN_RADIUS || this == MAX_RADIUS; }

    /** Every label, in order, for messages and help. */
    public static String labels() {
        return String.join(", ", java.util.Arrays.stream(values()).map(ShadingMode::label).toList());
    }

    /** Parses a label ({@link #labels()}) with a one-line error. */
    public static ShadingMode parse(String s) {
        String v = s == null ? "" : s.trim().toLowerCase(Locale.ROOT);
        for (ShadingMode m : values()) {
            if (m.label.equals(v)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown shading " + Echo.quote(s == null ? "" : s)
                + ": expected one of " + labels());
    }
}
