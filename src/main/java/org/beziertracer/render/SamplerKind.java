package org.beziertracer.render;

import java.util.Locale;

/**
 * Where the samples of a pixel go. With {@code spp} samples the pixel is divided into a grid of
 * {@code kx = ⌈√spp⌉} columns and {@code ky = ⌈spp / kx⌉} rows; sample {@code s} lies in cell
 * {@code (s mod kx, s div kx)} (for a non-square spp the last row is incomplete).
 */
public enum SamplerKind {
    /** Cell centres (spp = 1: the pixel centre). */
    REGULAR,
    /** Stratified: a random point in each cell, seeded per pixel and sample, so renders repeat exactly. */
    JITTERED,
    /**
     * Adaptive: first sample at the pixel centre; the other {@code spp − 1} (jittered) only where the
     * first-sample colour differs from a 4-neighbour's by more than the threshold.
     */
    ADAPTIVE;

    public String label() { return name().toLowerCase(Locale.ROOT); }

    public static SamplerKind parse(String s) {
        String v = s == null ? "" : s.trim().toLowerCase(Locale.ROOT);
        for (SamplerKind k : values()) {
            if (k.label().equals(v)) {
                return k;
            }
        }
        throw new IllegalArgumentException("unknown sampler '" + s + "': expected regular, jittered or adaptive");
    }
}
