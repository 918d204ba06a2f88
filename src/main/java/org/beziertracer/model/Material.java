package org.beziertracer.model;

/**
 * Surface appearance for Phong shading and Whitted reflection/refraction. Colours are linear RGB
 * in [0,1].
 *
 * @param r,g,b         base (diffuse) colour
 * @param ambient       ambient coefficient ka
 * @param diffuse       diffuse coefficient kd
 * @param specular      specular coefficient ks
 * @param shininess     Phong exponent
 * @param reflectivity  mirror reflection weight kr, 0..1
 * @param transparency  refraction weight kt, 0..1
 * @param ior           index of refraction (≥ 1 for glass)
 * @param checkerSquares squares per unit of (u,v) of a procedural checker texture; 0 = none
 * @param r2,g2,b2      second checker colour
 */
public record Material(double r, double g, double b, double ambient, double diffuse, double specular,
                       double shininess, double reflectivity, double transparency, double ior,
                       int checkerSquares, double r2, double g2, double b2) {

    public Material {
        for (double c : new double[] {r, g, b, r2, g2, b2, ambient, diffuse, specular, reflectivity, transparency}) {
            if (!(c >= 0) || !Double.isFinite(c)) {
                throw new IllegalArgumentException("material coefficients and colours must be finite and >= 0, got " + c);
            }
        }
        if (reflectivity > 1 || transparency > 1) {
            throw new IllegalArgumentException("reflectivity and transparency must be in 0..1");
        }
        if (!(shininess >= 0) || !Double.isFinite(shininess)) {
            throw new IllegalArgumentException("shininess must be finite and >= 0, got " + shininess);
        }
        if (!(ior > 0) || !Double.isFinite(ior)) {
            throw new IllegalArgumentException("index of refraction must be positive, got " + ior);
        }
        if (checkerSquares < 0 || checkerSquares > 10_000) {
            throw new IllegalArgumentException("checker squares must be 0..10000, got " + checkerSquares);
        }
    }

    /** A plain Phong material of the given colour. */
    public static Material diffuse(double r, double g, double b) {
        return new Material(r, g, b, 0.1, 0.75, 0.4, 40, 0, 0, 1.5, 0, 0, 0, 0);
    }

    /** The default surface colour: a warm gold-ish tone, as in the memoir's screenshots. */
    public static final Material DEFAULT = diffuse(0.85, 0.55, 0.2);

    public Material withChecker(int squares) {
        return new Material(r, g, b, ambient, diffuse, specular, shininess, reflectivity, transparency, ior,
                squares, r2 == 0 && g2 == 0 && b2 == 0 ? 0.95 : r2, g2 == 0 && r2 == 0 && b2 == 0 ? 0.95 : g2,
                b2 == 0 && r2 == 0 && g2 == 0 ? 0.95 : b2);
    }

    public Material withReflection(double kr) {
        return new Material(r, g, b, ambient, diffuse, specular, shininess, kr, transparency, ior,
                checkerSquares, r2, g2, b2);
    }

    public Material withRefraction(double kt, double eta) {
        return new Material(r, g, b, ambient, diffuse, specular, shininess, reflectivity, kt, eta,
                checkerSquares, r2, g2, b2);
    }
}
