package org.beziertracer.model.io;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Material;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;

/**
 * Turns a parsed scene file ({@link JsonNode}) into a {@link SceneDocument}; the format is
 * described in {@code docs/scene-file.md}. One instance per file, not thread-safe.
 *
 * <p>Material indices: named materials get indices in file order; an inline material or the
 * default ({@link Material#DEFAULT}, for primitives without {@code "material"}) reuses the first
 * equal material already in the list, or is appended.
 */
final class SceneReader {

    static final int VERSION = 1;

    private final Path baseDir;
    private final Scene.Builder builder = Scene.builder();
    private final List<Material> materials = new ArrayList<>();
    private final Map<String, Integer> named = new HashMap<>();

    /** @param baseDir directory against which relative model paths resolve; null = working directory */
    SceneReader(Path baseDir) {
        this.baseDir = baseDir;
    }

    SceneDocument read(JsonNode root) {
        root.keys(); // an object: check its version first, as a newer file may have newer keys
        checkVersion(root);
        root.object("version", "description", "models", "materials", "planes", "spheres", "lights", "camera", "render");
        if (root.has("description")) {
            root.get("description").asString();
        }
        if (root.has("materials")) {
            JsonNode map = root.get("materials");
            for (String name : map.keys()) {
                named.put(name, materials.size());
                addMaterial(material(map.get(name)));
            }
        }
        for (JsonNode m : list(root, "models")) {
            model(m);
        }
        for (JsonNode p : list(root, "planes")) {
            p.object("point", "normal", "material", "uvScale");
            int material = materialRef(p.get("material"));
            double uvScale = p.has("uvScale") ? p.get("uvScale").asPositive() : 1;
            builder.addPlane(build(p, () -> new Plane(vec(p.require("point")), vec(p.require("normal")),
                    material, uvScale)));
        }
        for (JsonNode s : list(root, "spheres")) {
            s.object("center", "radius", "material");
            Vec3 center = vec(s.require("center"));
            double radius = s.require("radius").asPositive();
            builder.addSphere(new Sphere(center, radius, materialRef(s.get("material"))));
        }
        for (JsonNode l : list(root, "lights")) {
            l.object("position", "color");
            Vec3 position = vec(l.require("position"));
            double[] c = l.has("color") ? l.get("color").asColor() : new double[] {1, 1, 1};
            builder.addLight(new PointLight(position, c[0], c[1], c[2]));
        }
        if (root.has("camera")) {
            builder.camera(camera(root.get("camera")));
        }
        RenderSettings settings = root.has("render") ? settings(root.get("render")) : RenderSettings.defaults();
        materials.forEach(builder::addMaterial);
        Scene scene = build(root, builder::build);
        return new SceneDocument(scene, settings);
    }

    private static void checkVersion(JsonNode root) {
        JsonNode v = root.get("version");
        if (v == null) {
            throw root.error("missing key \"version\" (this program reads version " + VERSION + ")");
        }
        if (!v.isNumber()) {
            throw v.expected("a version number");
        }
        if (v.asDouble() != VERSION) {
            throw v.error("unsupported scene version " + v.text() + " (this program reads version " + VERSION + ")");
        }
    }

    private static List<JsonNode> list(JsonNode root, String key) {
        return root.has(key) ? root.get(key).array() : List.of();
    }

    /** Runs a model-record constructor, re-throwing its validation error with the JSON path. */
    private static <T> T build(JsonNode where, Supplier<T> constructor) {
        try {
            return constructor.get();
        } catch (ModelFormatException e) {
            throw e;
        } catch (IllegalArgumentException e) {
            throw where.error(e.getMessage());
        }
    }

    // Models

    private void model(JsonNode m) {
        m.object("file", "builtin", "patches", "transform", "material");
        int sources = (m.has("file") ? 1 : 0) + (m.has("builtin") ? 1 : 0) + (m.has("patches") ? 1 : 0);
        if (sources != 1) {
            throw m.error("expected exactly one of \"file\", \"builtin\" or \"patches\", found " + sources);
        }
        List<BezierPatch> patches;
        if (m.has("file")) {
            patches = loadFile(m.get("file"));
        } else if (m.has("builtin")) {
            JsonNode b = m.get("builtin");
            Scene model = Models.builtIn(b.asString());
            if (model == null) {
                throw b.error("unknown built-in model \"" + b.asString() + "\" (expected one of: "
                        + String.join(", ", Models.NAMES) + ")");
            }
            patches = model.patches();
        } else {
            patches = inlinePatches(m.get("patches"));
        }
        ModelTransform transform = m.has("transform") ? transform(m.get("transform")) : ModelTransform.IDENTITY;
        List<BezierPatch> placed = new ArrayList<>(patches.size());
        for (BezierPatch p : patches) {
            placed.add(build(m, () -> transform.apply(p)));
        }
        builder.addPatches(placed, materialRef(m.get("material")));
    }

    private List<BezierPatch> loadFile(JsonNode f) {
        String name = f.asString();
        if (name.isBlank()) {
            throw f.expected("a model file name");
        }
        Path file = baseDir == null ? Path.of(name) : baseDir.resolve(name);
        String lower = name.toLowerCase(Locale.ROOT);
        if (!lower.endsWith(".bpt") && !lower.endsWith(".obj")) {
            throw f.error("model file \"" + name + "\" must end in .bpt or .obj (for a built-in model use"
                    + " \"builtin\")");
        }
        if (!Files.isRegularFile(file)) {
            throw f.error("no such model file " + file + (file.equals(Path.of(name)) ? "" : " (\"" + name
                    + "\" resolved against the scene file's directory)"));
        }
        try {
            return Models.load(file.toString()).patches();
        } catch (ModelFormatException e) {
            throw f.error(e.getMessage());
        }
    }

    private static List<BezierPatch> inlinePatches(JsonNode list) {
        List<BezierPatch> out = new ArrayList<>();
        for (JsonNode p : list.array()) {
            p.object("degree", "points", "weights", "domain");
            JsonNode degree = p.require("degree");
            List<JsonNode> nm = degree.array();
            if (nm.size() != 2) {
                throw degree.expected("an array of 2 whole numbers");
            }
            int n = nm.get(0).asInt();
            int m = nm.get(1).asInt();
            build(degree, () -> {
                BezierPatch.checkDegree("u", n);
                BezierPatch.checkDegree("v", m);
                return null;
            });
            JsonNode points = p.require("points");
            List<JsonNode> pts = points.array();
            if (pts.size() != (n + 1) * (m + 1)) {
                throw points.error("a degree " + n + "x" + m + " patch needs " + (n + 1) * (m + 1)
                        + " points (u index fastest), found " + pts.size());
            }
            double[] net = new double[pts.size() * 3];
            for (int k = 0; k < pts.size(); k++) {
                System.arraycopy(pts.get(k).asNumbers(3), 0, net, 3 * k, 3);
            }
            double[] weights = p.has("weights") ? p.get("weights").asNumbers(pts.size()) : null;
            PatchDomain domain = null;
            if (p.has("domain")) {
                double[] d = p.get("domain").asNumbers(4);
                domain = build(p.get("domain"), () -> new PatchDomain(d[0], d[1], d[2], d[3], null));
            }
            PatchDomain dom = domain;
            out.add(build(p.has("weights") ? p.get("weights") : points, () -> new BezierPatch(n, m, net, weights, dom, null)));
        }
        return out;
    }

    private static ModelTransform transform(JsonNode t) {
        t.object("translate", "scale", "rotate");
        double[] translate = t.has("translate") ? t.get("translate").asNumbers(3) : new double[3];
        double[] rotate = t.has("rotate") ? t.get("rotate").asNumbers(3) : new double[3];
        double[] scale = {1, 1, 1};
        JsonNode s = t.get("scale");
        if (s != null) {
            if (s.isNumber()) {
                double k = s.asDouble();
                scale = new double[] {k, k, k};
            } else {
                scale = s.asNumbers(3);
            }
            for (double k : scale) {
                if (k == 0) {
                    throw s.error("scale factors must be non-zero (a zero scale flattens the model)");
                }
            }
        }
        return new ModelTransform(translate, scale, rotate);
    }

    // Materials

    private int addMaterial(Material m) {
        materials.add(m);
        return materials.size() - 1;
    }

    /** Index of a material reference: absent = default, a name, or an inline object. */
    private int materialRef(JsonNode ref) {
        if (ref == null) {
            return indexOrAdd(Material.DEFAULT);
        }
        if (ref.isString()) {
            Integer index = named.get(ref.asString());
            if (index == null) {
                throw ref.error("unknown material \"" + ref.asString() + "\" (defined: "
                        + (named.isEmpty() ? "none" : JsonNode.list(named.keySet())) + ")");
            }
            return index;
        }
        return indexOrAdd(material(ref));
    }

    private int indexOrAdd(Material m) {
        int index = materials.indexOf(m);
        return index >= 0 ? index : addMaterial(m);
    }

    private static Material material(JsonNode n) {
        if (n.isString()) {
            throw n.expected("a material object");
        }
        n.object("color", "ambient", "diffuse", "specular", "shininess", "reflectivity", "transparency", "ior",
                "checker", "color2");
        Material d = Material.DEFAULT;
        double[] c = n.has("color") ? n.get("color").asColor() : new double[] {d.r(), d.g(), d.b()};
        int checker = n.has("checker") ? n.get("checker").asInt() : d.checkerSquares();
        double[] c2 = n.has("color2") ? n.get("color2").asColor()
                : checker > 0 ? new double[] {0.95, 0.95, 0.95} : new double[] {d.r2(), d.g2(), d.b2()};
        double ambient = number(n, "ambient", d.ambient());
        double diffuse = number(n, "diffuse", d.diffuse());
        double specular = number(n, "specular", d.specular());
        double shininess = number(n, "shininess", d.shininess());
        double reflectivity = number(n, "reflectivity", d.reflectivity());
        double transparency = number(n, "transparency", d.transparency());
        double ior = number(n, "ior", d.ior());
        return build(n, () -> new Material(c[0], c[1], c[2], ambient, diffuse, specular, shininess, reflectivity,
                transparency, ior, checker, c2[0], c2[1], c2[2]));
    }

    private static double number(JsonNode object, String key, double fallback) {
        return object.has(key) ? object.get(key).asDouble() : fallback;
    }

    // Camera and render settings

    private static Vec3 vec(JsonNode n) {
        double[] v = n.asNumbers(3);
        return new Vec3(v[0], v[1], v[2]);
    }

    private static CameraSpec camera(JsonNode c) {
        c.object("eye", "target", "up", "fov", "orthoWidth");
        Vec3 eye = vec(c.require("eye"));
        Vec3 target = vec(c.require("target"));
        Vec3 up = c.has("up") ? vec(c.get("up")) : Vec3.Z;
        double fov = number(c, "fov", SceneFiles.DEFAULT_FOV);
        double orthoWidth = c.has("orthoWidth") ? c.get("orthoWidth").asPositive() : 1;
        return build(c, () -> new CameraSpec(eye, target, up, fov, orthoWidth));
    }

    /**
     * Each key overrides {@link RenderSettings#defaults()}, applied one at a time in file order, so a
     * range error names the key that made the settings invalid.
     */
    private static RenderSettings settings(JsonNode r) {
        r.object("width", "height", "spp", "sampler", "method", "bvh", "shading", "checker", "shadows", "maxDepth");
        RenderSettings all = RenderSettings.defaults();
        for (String key : r.keys()) {
            all = with(all, r.get(key), key);
        }
        return all;
    }

    /** {@code s} with {@code key} set from {@code v}; a range error names {@code v}'s path. */
    private static RenderSettings with(RenderSettings s, JsonNode v, String key) {
        int w = s.width(), h = s.height(), spp = s.spp(), checker = s.checker(), depth = s.maxDepth();
        String sampler = s.sampler(), method = s.method(), shading = s.shading();
        boolean bvh = s.bvh(), shadows = s.shadows();
        switch (key) {
            case "width" -> w = v.asInt();
            case "height" -> h = v.asInt();
            case "spp" -> spp = v.asInt();
            case "checker" -> checker = v.asInt();
            case "maxDepth" -> depth = v.asInt();
            case "sampler" -> sampler = v.asString();
            case "method" -> method = v.asString();
            case "shading" -> shading = v.asString();
            case "bvh" -> bvh = v.asBoolean();
            case "shadows" -> shadows = v.asBoolean();
            default -> throw new IllegalStateException("unhandled render key " + key);
        }
        try {
            return new RenderSettings(w, h, spp, sampler, method, bvh, shading, checker, shadows, depth);
        } catch (IllegalArgumentException e) {
            throw v.error(e.getMessage());
        }
    }
}
