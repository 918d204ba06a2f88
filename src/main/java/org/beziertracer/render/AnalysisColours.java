package org.beziertracer.render;

import org.beziertracer.geometry.SurfaceCurvature;

/**
 * The colour of a hit in each surface-analysis view, in linear RGB, from the exact unit normal,
 * the view direction and (for the curvature views) the exact curvature at the hit.
 * <ul>
 *   <li><b>zebra</b>: the view ray reflected in the surface, {@code r = d − 2(d·n)n}, meets a ring
 *       of parallel light bars at infinity around {@link Analysis#zebraAxis}: the stripe is read
 *       from the angle of {@code r} about the axis, so the stripes follow the reflection lines of
 *       the surface (a G1 break shows as a jump, a G2 break as a kink);</li>
 *   <li><b>emap</b>: the environment image seen in the same mirror direction;</li>
 *   <li><b>isophotes</b>: the grey {@code N·L} with a dark line where {@code acos(N·L)} crosses a
 *       multiple of the step (lines of constant N·L: R. Klass, "Correction of local surface
 *       irregularities using reflection lines", CAD 12(2), 1980; H. Theisel, "Are isophotes and
 *       reflection lines the same?", CAGD 18, 2001);</li>
 *   <li><b>gaussian</b>, <b>mean</b>: a diverging scale (K. Moreland's cool–warm, "Diverging
 *       Color Maps for Scientific Visualization", 2009), blue below zero, white at zero, red above,
 *       over {@code [low, high]} made symmetric about zero (K on a square-root axis, linear in
 *       the curvatures it multiplies);</li>
 *   <li><b>min-radius</b>, <b>max-radius</b>: a sequential scale (dark blue → green → yellow) of
 *       the radius on a logarithmic axis over {@code [low, high]}; a flat point has an infinite
 *       radius and takes the top;</li>
 *   <li><b>draft</b>: the angle between the surface and the pull direction,
 *       {@code 90° − angle(n, pull)} with the surface's own normal: green above the tolerance,
 *       red below minus it, yellow in between (a face that needs draft), shaded by {@code |N·V|} so
 *       the form stays readable.</li>
 * </ul>
 * The curvature views shade their colour by {@code 0.55 + 0.45 |N·V|} for the same reason.
 */
final class AnalysisColours {
    private AnalysisColours() {}

    /** Dark and light zebra stripes. */
    static final double DARK = 0.02, LIGHT = 0.92;

    /**
     * The zebra colour for the unit view direction {@code (ux, uy, uz)} and the unit normal facing
     * the viewer {@code (nx, ny, nz)}.
     */
    static void zebra(Analysis a, double ux, double uy, double uz, double nx, double ny, double nz, double[] out) {
        double dn = ux * nx + uy * ny + uz * nz;
        double rx = ux - 2 * dn * nx, ry = uy - 2 * dn * ny, rz = uz - 2 * dn * nz;
        double[] ax = a.zebraAxis();
        // a frame (e1, e2) across the axis, then the angle of r about it
        double e1x, e1y, e1z;
        if (Math.abs(ax[0]) < 0.9) {
            e1x = 0; e1y = -ax[2]; e1z = ax[1];      // (1,0,0) × axis
        } else {
            e1x = ax[2]; e1y = 0; e1z = -ax[0];      // (0,1,0) × axis
        }
        double l1 = Math.sqrt(e1x * e1x + e1y * e1y + e1z * e1z);
        e1x /= l1; e1y /= l1; e1z /= l1;
        double e2x = ax[1] * e1z - ax[2] * e1y, e2y = ax[2] * e1x - ax[0] * e1z, e2z = ax[0] * e1y - ax[1] * e1x;
        double phi = Math.atan2(rx * e2x + ry * e2y + rz * e2z, rx * e1x + ry * e1y + rz * e1z);
        double period = (phi / (2 * Math.PI) + 0.5) * a.zebraStripes();
        double g = period - Math.floor(period) < a.zebraWidth() ? DARK : LIGHT;
        out[0] = g; out[1] = g; out[2] = g;
    }

    /**
     * The environment image ({@link Analysis#environment}) seen in the mirror direction
     * {@code r = d − 2(d·n)n}: the reflection a polished part shows in a studio.
     */
    static void emap(Analysis a, double ux, double uy, double uz, double nx, double ny, double nz, double[] out) {
        double dn = ux * nx + uy * ny + uz * nz;
        a.environment().lookup(ux - 2 * dn * nx, uy - 2 * dn * ny, uz - 2 * dn * nz, out);
    }

    /** The isophote colour for the unit normal facing the viewer and the unit direction {@code l} to the light. */
    static void isophotes(Analysis a, double nx, double ny, double nz, double lx, double ly, double lz, double[] out) {
        double c = Math.max(-1, Math.min(1, nx * lx + ny * ly + nz * lz));
        double degrees = Math.toDegrees(Math.acos(c)) / a.isophoteStep();
        double f = degrees - Math.floor(degrees);
        // a line a tenth of a step wide, centred on each multiple
        boolean line = f < 0.05 || f > 0.95;
        double g = line ? 0.03 : 0.15 + 0.75 * Math.max(0, c);
        out[0] = g; out[1] = g; out[2] = line ? 0.2 : g;
    }

    /** The value a curvature view shows at a hit ({@link SurfaceCurvature} layout in {@code c}). */
    static double value(ShadingMode mode, double[] c) {
        double k1 = c[SurfaceCurvature.K1], k2 = c[SurfaceCurvature.K2];
        return switch (mode) {
            case GAUSSIAN -> c[SurfaceCurvature.GAUSSIAN];
            case MEAN -> c[SurfaceCurvature.MEAN];
            case MIN_RADIUS -> 1 / Math.max(Math.abs(k1), Math.abs(k2));
            case MAX_RADIUS -> 1 / Math.min(Math.abs(k1), Math.abs(k2));
            default -> throw new IllegalArgumentException(mode + " shows no curvature");
        };
    }

    /** True for the views drawn on a logarithmic radius axis. */
    static boolean radius(ShadingMode mode) {
        return mode == ShadingMode.MIN_RADIUS || mode == ShadingMode.MAX_RADIUS;
    }

    // Moreland's cool–warm end points and middle, linear RGB
    private static final double[] COOL = {0.0497, 0.0763, 0.5223}, MID = {0.7529, 0.7529, 0.7529},
            WARM = {0.4452, 0.0012, 0.0232};
    // dark blue, teal, green, yellow (linear RGB)
    private static final double[][] SEQUENTIAL = {{0.0466, 0.0008, 0.1714}, {0.0280, 0.1200, 0.3000},
        {0.0137, 0.3600, 0.2900}, {0.2500, 0.6000, 0.0400}, {0.9700, 0.8300, 0.0100}};

    /**
     * The colour of {@code value} in view {@code mode} over {@code [low, high]}, shaded by
     * {@code facing} = |N·V|.
     */
    static void curvature(ShadingMode mode, double value, double low, double high, double facing, double[] out) {
        double shade = 0.55 + 0.45 * facing;
        if (radius(mode)) {
            double t;
            if (!(value < Double.POSITIVE_INFINITY)) {
                t = 1;
            } else {
                t = (Math.log(value) - Math.log(low)) / (Math.log(high) - Math.log(low));
            }
            t = Math.max(0, Math.min(1, Double.isNaN(t) ? 1 : t)) * (SEQUENTIAL.length - 1);
            int i = Math.min(SEQUENTIAL.length - 2, (int) t);
            double f = t - i;
            for (int c = 0; c < 3; c++) {
                out[c] = shade * (SEQUENTIAL[i][c] + f * (SEQUENTIAL[i + 1][c] - SEQUENTIAL[i][c]));
            }
            return;
        }
        double bound = Math.max(Math.abs(low), Math.abs(high));
        double t = bound > 0 ? Math.max(-1, Math.min(1, value / bound)) : 0;
        if (mode == ShadingMode.GAUSSIAN) {
            t = Math.copySign(Math.sqrt(Math.abs(t)), t); // K is a product of two curvatures: linear in √|K|
        }
        double[] end = t < 0 ? COOL : WARM;
        double f = Math.abs(t);
        for (int c = 0; c < 3; c++) {
            out[c] = shade * (MID[c] + f * (end[c] - MID[c]));
        }
    }

    /** Draft colour: {@code n} the surface's own unit normal, {@code facing} = |N·V|. */
    static void draft(Analysis a, double nx, double ny, double nz, double facing, double[] out) {
        double draft = draftAngle(a, nx, ny, nz);
        double shade = 0.45 + 0.55 * facing;
        double r, g, b;
        if (draft > a.draftTolerance()) {
            r = 0.05; g = 0.55; b = 0.08;
        } else if (draft < -a.draftTolerance()) {
            r = 0.65; g = 0.03; b = 0.02;
        } else {
            r = 0.85; g = 0.70; b = 0.02;
        }
        out[0] = shade * r; out[1] = shade * g; out[2] = shade * b;
    }

    /** The draft angle in degrees of the unit normal {@code n} against the pull direction. */
    static double draftAngle(Analysis a, double nx, double ny, double nz) {
        double[] p = a.draftPull();
        return 90 - Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, nx * p[0] + ny * p[1] + nz * p[2]))));
    }
}
