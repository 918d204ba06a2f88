package org.beziertracer.model.io;

import java.util.Locale;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.Environment;
import org.beziertracer.model.HdrImage;
import org.beziertracer.model.Material;
import org.beziertracer.model.MetalPresets;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.Scene;
import org.beziertracer.model.SpotLight;
import java.util.List;
import org.beziertracer.model.Surface;
import org.beziertracer.model.Texture;

/**
 * The scene file's keys for the path tracer (docs/scene-file.md): typed materials
 * ({@code "type": "diffuse" | "conductor" | "dielectric" | "plastic"}), area lights in
 * {@code "lights"} ({@code "type": "sphere" | "rect"}) and the top-level {@code "environment"}.
 * Errors name the file and the key's path. Stateless.
 *
 * <p>Metal presets: {@link MetalPresets}.
 */
final class ScenePhysics {
    private ScenePhysics() {}

    static final String[] MATERIAL_KEYS = {"type", "color", "roughness", "ior", "metal", "eta", "k", "checker", "color2"};

    /** The metals by name ({@link MetalPresets}): eta (r, g, b) then k (r, g, b); null for an unknown name. */
    static double[] metal(String name) {
        try {
            MetalPresets m = MetalPresets.parse(name);
            double[] eta = m.eta(), k = m.k();
            return new double[] {eta[0], eta[1], eta[2], k[0], k[1], k[2]};
        } catch (IllegalArgumentException e) {
            return null;
        }
    }

    /**
     * A typed material object: its surface. Its {@code "color"} is {@code [r, g, b]} or a texture
     * ({@link SceneTextures}), whose image file resolves against {@code baseDir}.
     */
    static Surface surface(JsonNode n, java.nio.file.Path baseDir) {
        n.object(MATERIAL_KEYS);
        JsonNode typeNode = n.require("type");
        String type = typeNode.asString();
        Surface.Kind kind;
        try {
            kind = Surface.Kind.parse(type);
        } catch (IllegalArgumentException e) {
            throw typeNode.error("unknown material type " + Echo.quote(type)
                    + " (expected diffuse, conductor, dielectric or plastic)");
        }
        JsonNode color = n.get("color");
        Texture texture = color != null && color.isObject() ? SceneTextures.read(color, baseDir) : null;
        if (texture != null && n.has("checker")) {
            throw n.get("checker").error("give either a textured \"color\" or \"checker\", not both");
        }
        double[] c = texture != null ? texture.mean() : color != null ? SceneTextures.albedo(color)
                : kind == Surface.Kind.DIFFUSE || kind == Surface.Kind.PLASTIC ? new double[] {0.8, 0.8, 0.8}
                : new double[] {1, 1, 1};
        double roughness = kind == Surface.Kind.DIFFUSE ? 1 : 0;
        if (n.has("roughness")) {
            JsonNode r = n.get("roughness");
            roughness = r.asDouble();
            if (!(roughness >= 0 && roughness <= 1)) {
                throw r.error("roughness must be in 0..1, found " + r.text());
            }
        }
        double ior = 1.5;
        if (n.has("ior")) {
            JsonNode i = n.get("ior");
            ior = i.asDouble();
            if (!(ior > 1) || !Double.isFinite(ior)) {
                throw i.error("ior must be a finite number > 1, found " + i.text());
            }
        }
        Surface.Vec eta = null, k = null;
        String metal = null;
        if (kind == Surface.Kind.CONDUCTOR) {
            if (n.has("metal")) {
                if (n.has("eta") || n.has("k")) {
                    throw n.error("give either \"metal\" or \"eta\" and \"k\", not both");
                }
                JsonNode m = n.get("metal");
                metal = m.asString().toLowerCase(Locale.ROOT);
                double[] v = metal(metal);
                if (v == null) {
                    throw m.error("unknown metal " + Echo.quote(m.asString()) + " (expected gold, copper, aluminium or silver)");
                }
                metal = metal.equals("aluminum") ? "aluminium" : metal;
                eta = new Surface.Vec(v[0], v[1], v[2]);
                k = new Surface.Vec(v[3], v[4], v[5]);
            } else if (n.has("eta") || n.has("k")) {
                double[] e = positive(n.require("eta"), true);
                double[] kk = positive(n.require("k"), false);
                eta = new Surface.Vec(e[0], e[1], e[2]);
                k = new Surface.Vec(kk[0], kk[1], kk[2]);
            } else {
                throw n.error("a conductor needs \"metal\" (gold, copper, aluminium or silver) or \"eta\" and \"k\"");
            }
        } else {
            for (String key : new String[] {"metal", "eta", "k"}) {
                if (n.has(key)) {
                    throw n.get(key).error("\"" + key + "\" belongs to a conductor, not to a " + kind.label() + " material");
                }
            }
        }
        Surface.Vec fe = eta, fk = k;
        String fm = metal;
        double fr = roughness, fi = ior;
        return SceneReader.build(n, () -> new Surface(kind, c[0], c[1], c[2], fr, fi, fe, fk, fm, texture));
    }

    private static double[] positive(JsonNode n, boolean strict) {
        double[] v = n.asNumbers(3);
        for (double x : v) {
            if (strict ? !(x > 0) : !(x >= 0)) {
                throw n.error("expected 3 numbers " + (strict ? "> 0" : ">= 0") + ", found " + n.text());
            }
        }
        return v;
    }

    /**
     * The Whitted renderer's look of a typed material: diffuse → Phong of its colour; conductor →
     * a mirror (reflectivity 0.8) of its colour times its head-on reflectance; dielectric →
     * transparent glass of its index; plastic → Phong with a highlight as sharp as its roughness.
     */
    static Material phong(Surface s, int checker, double[] color2) {
        Material d = Material.diffuse(s.r(), s.g(), s.b());
        Material m = switch (s.kind()) {
            case DIFFUSE -> d;
            case PLASTIC -> new Material(s.r(), s.g(), s.b(), 0.1, 0.75, 0.5, 2 / Math.max(1e-3, Math.pow(s.roughness(), 4)) + 2,
                    0, 0, 1.5, 0, 0, 0, 0);
            case DIELECTRIC -> new Material(s.r(), s.g(), s.b(), 0, 0.05, 0.6, 200, 0, 0.9, s.ior(), 0, 0, 0, 0);
            case CONDUCTOR -> {
                double[] f = new double[3];
                double[] eta = s.eta().toArray(), k = s.k().toArray();
                for (int i = 0; i < 3; i++) {
                    f[i] = ((eta[i] - 1) * (eta[i] - 1) + k[i] * k[i]) / ((eta[i] + 1) * (eta[i] + 1) + k[i] * k[i]);
                }
                yield new Material(s.r() * f[0], s.g() * f[1], s.b() * f[2], 0.1, 0.3, 0.8, 80, 0.8, 0, 1.5, 0, 0, 0, 0);
            }
        };
        if (checker > 0) {
            m = m.withChecker(checker);
            m = new Material(m.r(), m.g(), m.b(), m.ambient(), m.diffuse(), m.specular(), m.shininess(), m.reflectivity(),
                    m.transparency(), m.ior(), checker, color2[0], color2[1], color2[2]);
        }
        return m;
    }

    /** An entry of {@code "lights"}: a point light (no {@code "type"}, or {@code "point"}), a sphere or a rect light. */
    static void light(JsonNode l, Scene.Builder builder) {
        String type = l.keys().contains("type") ? l.get("type").asString() : "point";
        switch (type) {
            case "point" -> builder.addLight(pointLight(l));
            case "sphere", "rect" -> builder.addAreaLight(areaLight(l, type));
            case "spot" -> builder.addSpotLight(spotLight(l));
            default -> throw l.get("type").error("unknown light type " + Echo.quote(type)
                    + " (expected point, spot, sphere or rect)");
        }
    }

    /** A light; a colour whose total overflows is named with the literal values. */
    private static PointLight pointLight(JsonNode l) {
        l.object("type", "position", "color");
        Vec3 position = vec(l.require("position"));
        double[] c = {1, 1, 1};
        if (l.has("color")) {
            JsonNode color = l.get("color");
            c = color.asColor();
            if (!Double.isFinite(c[0] + c[1] + c[2])) {
                List<JsonNode> rgb = color.array();
                throw l.error("the light's total intensity r + g + b = " + rgb.get(0).text() + " + " + rgb.get(1).text()
                        + " + " + rgb.get(2).text() + " overflows (" + NumberText.BEYOND + ")");
            }
        }
        double[] rgb = c;
        return SceneReader.build(l, () -> new PointLight(position, rgb[0], rgb[1], rgb[2]));
    }

    /** A spot light: position, direction, angle (default 30), falloff (default 3/4 of the angle), colour. */
    private static SpotLight spotLight(JsonNode l) {
        l.object("type", "position", "direction", "angle", "falloff", "color");
        Vec3 position = vec(l.require("position")), direction = vec(l.require("direction"));
        double angle = l.has("angle") ? l.get("angle").asDouble() : 30;
        double falloff = l.has("falloff") ? l.get("falloff").asDouble() : 0.75 * angle;
        double[] c = l.has("color") ? l.get("color").asColor() : new double[] {1, 1, 1};
        return SceneReader.build(l, () -> new SpotLight(position, direction, angle, falloff, c[0], c[1], c[2]));
    }

    /** An area light entry of {@code "lights"} ({@code "type"} sphere or rect). */
    static AreaLight areaLight(JsonNode l, String type) {
        boolean sphere = type.equals("sphere");
        if (sphere) {
            l.object("type", "center", "radius", "color", "power");
        } else {
            l.object("type", "corner", "edge1", "edge2", "color", "power");
        }
        double[] c = l.has("color") ? l.get("color").asColor() : new double[] {1, 1, 1};
        double power = Double.NaN;
        if (l.has("power")) {
            JsonNode p = l.get("power");
            power = p.asDouble();
            if (!(power >= 0) || !Double.isFinite(power)) {
                throw p.error("power must be a finite number >= 0, found " + p.text());
            }
        }
        double fp = power;
        if (sphere) {
            Vec3 center = vec(l.require("center"));
            double radius = l.require("radius").asPositive();
            return SceneReader.build(l, () -> AreaLight.sphere(center, radius, c[0], c[1], c[2], fp));
        }
        Vec3 corner = vec(l.require("corner")), e1 = vec(l.require("edge1")), e2 = vec(l.require("edge2"));
        return SceneReader.build(l, () -> AreaLight.rect(corner, e1, e2, c[0], c[1], c[2], fp));
    }

    /**
     * The top-level {@code "environment"}: a colour, or an {@code "image"} (a Radiance {@code .hdr}
     * file relative to {@code baseDir}, read by {@link HdrReader}).
     */
    static Environment environment(JsonNode e, java.nio.file.Path baseDir) {
        e.object("color", "image", "intensity", "rotate");
        double intensity = 1, rotate = 0;
        if (e.has("intensity")) {
            JsonNode i = e.get("intensity");
            intensity = i.asDouble();
            if (!(intensity >= 0) || !Double.isFinite(intensity)) {
                throw i.error("intensity must be a finite number >= 0, found " + i.text());
            }
        }
        if (e.has("rotate")) {
            rotate = e.get("rotate").asDouble();
        }
        double fi = intensity, fr = rotate;
        if (e.has("image")) {
            if (e.has("color")) {
                throw e.error("give either \"color\" or \"image\", not both");
            }
            JsonNode image = e.get("image");
            String name = image.asString();
            if (!name.toLowerCase(Locale.ROOT).endsWith(".hdr")) {
                throw image.error("an environment image must be a Radiance .hdr file, found " + Echo.quote(name));
            }
            HdrImage picture;
            try {
                java.nio.file.Path file = baseDir == null ? java.nio.file.Path.of(name) : baseDir.resolve(name);
                picture = HdrReader.read(file);
            } catch (java.nio.file.InvalidPathException x) {
                throw image.error("not a file name: " + Echo.quote(name));
            } catch (ModelFormatException x) {
                throw image.error(Echo.cutQuoted(x.getMessage()));
            }
            return SceneReader.build(e, () -> Environment.image(name, picture, fi, fr));
        }
        if (!e.has("color")) {
            throw e.error("missing key \"color\" (or \"image\")");
        }
        double[] c = e.get("color").asColor();
        return SceneReader.build(e, () -> new Environment(c[0], c[1], c[2], null, fi, fr, null));
    }

    private static Vec3 vec(JsonNode n) {
        double[] v = n.asNumbers(3);
        return new Vec3(v[0], v[1], v[2]);
    }
}
