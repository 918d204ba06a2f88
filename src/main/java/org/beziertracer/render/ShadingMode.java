package org.beziertracer.render;

import java.util.Locale;

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
    PATCH_ID("patch-id");

    private final String label;

    ShadingMode(String label) { this.label = label; }

    public String label() { return label; }

    /** Parses a label ({@code phong, flat, normals, uv, patch-id}) with a one-line error. */
    public static ShadingMode parse(String s) {
        String v = s == null ? "" : s.trim().toLowerCase(Locale.ROOT);
        for (ShadingMode m : values()) {
            if (m.label.equals(v)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown shading '" + s + "': expected phong, flat, normals, uv or patch-id");
    }
}
