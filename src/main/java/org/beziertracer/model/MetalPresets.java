package org.beziertracer.model;

import java.util.Locale;

/**
 * Named metals: complex indices of refraction {@code η + iκ} at the red, green and blue primaries
 * of linear sRGB. Source: the measured spectra of E. D. Palik, "Handbook of Optical Constants of
 * Solids", Academic Press, 1985, as tabulated with Mitsuba and pbrt-v3 ({@code Au, Cu, Al, Ag}
 * spectral files) and reduced to RGB by the same integration those renderers publish.
 */
public enum MetalPresets {
    GOLD(new double[] {0.1431189557, 0.3749570432, 1.4424785571}, new double[] {3.9831604247, 2.3857207478, 1.6032152899}),
    COPPER(new double[] {0.2004376970, 0.9240334304, 1.1022119527}, new double[] {3.9129485033, 2.4528477015, 2.1421879552}),
    ALUMINIUM(new double[] {1.6574599595, 0.8803689579, 0.5212287346}, new double[] {9.2238691996, 6.2695232477, 4.8370012281}),
    SILVER(new double[] {0.1552646489, 0.1167232965, 0.1383806959}, new double[] {4.8283433224, 3.1222459278, 2.1469504455});

    private final double[] eta, k;

    MetalPresets(double[] eta, double[] k) {
        this.eta = eta;
        this.k = k;
    }

    public double[] eta() { return eta.clone(); }

    public double[] k() { return k.clone(); }

    public String label() { return name().toLowerCase(Locale.ROOT); }

    /** The preset named {@code name} (gold, copper, aluminium — also aluminum — or silver). */
    public static MetalPresets parse(String name) {
        String v = name == null ? "" : name.trim().toLowerCase(Locale.ROOT);
        if (v.equals("aluminum")) {
            return ALUMINIUM;
        }
        for (MetalPresets p : values()) {
            if (p.label().equals(v)) {
                return p;
            }
        }
        throw new IllegalArgumentException("unknown metal '" + name + "': expected gold, copper, aluminium or silver");
    }
}
