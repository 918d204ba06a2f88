package org.beziertracer.model;

import java.util.Locale;

/**
 * A physically based material for the path tracer (the Whitted renderer keeps using the
 * {@link Material} beside it). Colours are linear RGB.
 *
 * @param kind      diffuse, conductor, dielectric or plastic
 * @param r,g,b     albedo (diffuse, plastic), tint of the reflection (conductor) or of the
 *                  transmitted light (dielectric), each 0..1
 * @param roughness perceptual roughness 0..1 (the microfacet α is its square); 0 = smooth
 * @param ior       index of refraction of a dielectric or of a plastic's coat
 * @param eta       a conductor's complex index, real part per channel
 * @param k         a conductor's complex index, imaginary part per channel
 * @param metal     the preset a conductor came from (gold, copper, aluminium, silver), or null
 * @param texture   the colour over (u,v) when it varies (a checker or an image), else null; then
 *                  {@code r, g, b} hold its mean colour
 */
public record Surface(Kind kind, double r, double g, double b, double roughness, double ior, Vec eta, Vec k,
                      String metal, Texture texture) {

    /** The kinds of surface, by their scene-file names. */
    public enum Kind {
        DIFFUSE, CONDUCTOR, DIELECTRIC, PLASTIC;

        public String label() { return name().toLowerCase(Locale.ROOT); }

        /** The kind named {@code s}; the error lists the names. */
        public static Kind parse(String s) {
            for (Kind k : values()) {
                if (k.label().equals(s)) {
                    return k;
                }
            }
            throw new IllegalArgumentException("unknown material type '" + s
                    + "': expected diffuse, conductor, dielectric or plastic");
        }
    }

    /** Three components per channel (a record so that equal surfaces are equal). */
    public record Vec(double r, double g, double b) {
        public double[] toArray() { return new double[] {r, g, b}; }
    }

    public Surface {
        if (kind == null) {
            throw new IllegalArgumentException("a material needs a type");
        }
        for (double c : new double[] {r, g, b}) {
            if (!(c >= 0 && c <= 1)) {
                throw new IllegalArgumentException("a physically based colour must be in 0..1, got " + c);
            }
        }
        if (!(roughness >= 0 && roughness <= 1)) {
            throw new IllegalArgumentException("roughness must be in 0..1, got " + roughness);
        }
        if (!(ior >= 1) || !Double.isFinite(ior) || (kind == Kind.DIELECTRIC || kind == Kind.PLASTIC) && ior == 1) {
            throw new IllegalArgumentException("index of refraction must be finite and > 1, got " + ior);
        }
        if (kind == Kind.CONDUCTOR) {
            if (eta == null || k == null) {
                throw new IllegalArgumentException("a conductor needs eta and k, or a metal preset");
            }
            for (double v : new double[] {eta.r(), eta.g(), eta.b()}) {
                if (!(v > 0) || !Double.isFinite(v)) {
                    throw new IllegalArgumentException("a conductor's eta must be finite and > 0, got " + v);
                }
            }
            for (double v : new double[] {k.r(), k.g(), k.b()}) {
                if (!(v >= 0) || !Double.isFinite(v)) {
                    throw new IllegalArgumentException("a conductor's k must be finite and >= 0, got " + v);
                }
            }
        }
    }

    /** A surface of one colour (no texture). */
    public Surface(Kind kind, double r, double g, double b, double roughness, double ior, Vec eta, Vec k, String metal) {
        this(kind, r, g, b, roughness, ior, eta, k, metal, null);
    }

    /** This surface with its colour given by {@code t} (null: one colour), {@code r, g, b} set to its mean. */
    public Surface withTexture(Texture t) {
        double[] c = t == null ? new double[] {r, g, b} : t.mean();
        return new Surface(kind, c[0], c[1], c[2], roughness, ior, eta, k, metal, t);
    }

    public static Surface diffuse(double r, double g, double b) {
        return new Surface(Kind.DIFFUSE, r, g, b, 1, 1.5, null, null, null);
    }

    public static Surface dielectric(double ior, double roughness) {
        return new Surface(Kind.DIELECTRIC, 1, 1, 1, roughness, ior, null, null, null);
    }

    public static Surface plastic(double r, double g, double b, double roughness) {
        return new Surface(Kind.PLASTIC, r, g, b, roughness, 1.5, null, null, null);
    }

    public static Surface conductor(Vec eta, Vec k, double roughness) {
        return new Surface(Kind.CONDUCTOR, 1, 1, 1, roughness, 1.5, eta, k, null);
    }

    /**
     * The path tracer's reading of a Phong material: transparent → smooth glass of its index;
     * mostly reflective (kr ≥ ½) → a smooth mirror of its colour; else diffuse of its colour
     * (clamped to 1).
     */
    public static Surface fromPhong(Material m) {
        if (m.transparency() > 0) {
            return dielectric(Math.max(1.0001, m.ior()), 0);
        }
        double r = Math.min(1, m.r()), g = Math.min(1, m.g()), b = Math.min(1, m.b());
        if (m.reflectivity() >= 0.5) {
            return new Surface(Kind.CONDUCTOR, r, g, b, 0, 1.5, new Vec(1, 1, 1), new Vec(1e3, 1e3, 1e3), null);
        }
        return diffuse(r, g, b);
    }
}
