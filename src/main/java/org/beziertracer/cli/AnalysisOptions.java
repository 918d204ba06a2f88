package org.beziertracer.cli;

import java.util.Locale;

import org.beziertracer.math.Vec3;
import org.beziertracer.render.Analysis;
import org.beziertracer.render.ShadingMode;

import picocli.CommandLine.Option;

/**
 * The options of {@code render}'s surface-analysis views: {@code --analysis NAME} (the shading
 * it stands for) and each view's settings ({@link Analysis}). A picocli mixin.
 */
final class AnalysisOptions {

    @Option(names = "--analysis", paramLabel = "NAME", description = "surface analysis view instead of the shading: "
            + "zebra, emap, isophotes, gaussian, mean, min-radius, max-radius or draft (exact derivatives at every pixel)")
    String analysis;

    @Option(names = "--emap", paramLabel = "IMAGE", description = "environment image of the emap view: an "
            + "equirectangular PNG or JPEG, z up (default: the built-in studio)")
    java.nio.file.Path emap;

    @Option(names = "--analysis-range", paramLabel = "LOW,HIGH", description = "ends of a curvature view's colour "
            + "scale (curvature in 1/model units, radii in model units); default: automatic, from the values in view")
    String range;

    @Option(names = "--zebra-axis", paramLabel = "x,y,z", description = "direction the zebra light bars run along "
            + "(default: 0,0,1)")
    String zebraAxis;

    @Option(names = "--zebra-stripes", paramLabel = "N", description = "light bars around the axis, 2..200 (default: 16)")
    Integer zebraStripes;

    @Option(names = "--zebra-width", paramLabel = "F", description = "dark share of each bar's period, 0..1 "
            + "(default: 0.5)")
    Double zebraWidth;

    @Option(names = "--isophote-light", paramLabel = "x,y,z", description = "direction toward the isophotes' light "
            + "(default: from the eye)")
    String isophoteLight;

    @Option(names = "--isophote-step", paramLabel = "DEGREES", description = "angle between isophotes, 0.5..90 "
            + "(default: 10)")
    Double isophoteStep;

    @Option(names = "--draft-pull", paramLabel = "x,y,z", description = "pull direction of the draft view "
            + "(default: 0,0,1)")
    String draftPull;

    @Option(names = "--draft-tolerance", paramLabel = "DEGREES", description = "draft within ± this counts as "
            + "vertical, 0..45 (default: 1)")
    Double draftTolerance;

    /** The shading {@code --analysis} names, or {@code fallback}; a one-line error for a name that is not a view. */
    String shading(String fallback) {
        if (analysis == null) {
            return fallback;
        }
        ShadingMode mode;
        try {
            mode = ShadingMode.parse(analysis);
        } catch (IllegalArgumentException e) {
            mode = null;
        }
        if (mode == null || !mode.isAnalysis()) {
            throw new IllegalArgumentException("unknown analysis '" + analysis + "': expected zebra, emap, isophotes, "
                    + "gaussian, mean, min-radius, max-radius or draft");
        }
        return mode.label();
    }

    /** The views' settings from the options given, defaults for the others. */
    Analysis settings() {
        Analysis a = Analysis.defaults();
        if (zebraAxis != null || zebraStripes != null || zebraWidth != null) {
            a = a.withZebra(zebraAxis != null ? array(RenderCommand.vec("--zebra-axis", zebraAxis)) : a.zebraAxis(),
                    zebraStripes != null ? zebraStripes : a.zebraStripes(), zebraWidth != null ? zebraWidth : a.zebraWidth());
        }
        if (isophoteLight != null || isophoteStep != null) {
            a = a.withIsophotes(isophoteLight != null ? array(RenderCommand.vec("--isophote-light", isophoteLight))
                    : a.isophoteLight(), isophoteStep != null ? isophoteStep : a.isophoteStep());
        }
        if (draftPull != null || draftTolerance != null) {
            a = a.withDraft(draftPull != null ? array(RenderCommand.vec("--draft-pull", draftPull)) : a.draftPull(),
                    draftTolerance != null ? draftTolerance : a.draftTolerance());
        }
        if (range != null) {
            String[] parts = range.split(",", -1);
            if (parts.length != 2) {
                throw new IllegalArgumentException("--analysis-range must be LOW,HIGH, got '" + range + "'");
            }
            try {
                a = a.withRange(Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()));
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("--analysis-range must be two numbers LOW,HIGH, got '"
                        + range.toLowerCase(Locale.ROOT) + "'");
            }
        }
        if (emap != null) {
            a = a.withEnvironment(EnvironmentImages.read(emap));
        }
        return a;
    }

    private static double[] array(Vec3 v) {
        return new double[] {v.x(), v.y(), v.z()};
    }
}
