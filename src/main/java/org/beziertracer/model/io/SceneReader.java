package org.beziertracer.model.io;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Supplier;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Material;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Plane;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;
import org.beziertracer.model.Surface;

/**
 * Turns a parsed scene file ({@link JsonNode}) into a {@link SceneDocument}; the format is
 * described in {@code docs/scene-file.md}. One instance per file, not thread-safe.
 *
 * <p>Material indices: named materials get indices in file order; an inline material or the
 * default ({@link Material#DEFAULT}, for primitives without {@code "material"}) reuses the first
 * equal material already in the list, or is appended.
 *
 * <p>Caps ({@link ReadLimits}): entries of {@code models}; of each of {@code materials},
 * {@code planes}, {@code spheres} and {@code lights}; patches in the whole scene.
 */
final class SceneReader {

    static final int VERSION = 1;

    private final Path baseDir;
    private final ReadLimits limits;
    private int patchCount;
    /** Models read so far, by file path or built-in name: a model listed again is the same {@code Scene}. */
    private final Map<String, Scene> loaded = new HashMap<>();
    private final Scene.Builder builder = Scene.builder();
    private final List<Material> materials = new ArrayList<>();
    /** Per material, its physically based surface when it was given a {@code "type"}, else null. */
    private final List<Surface> surfaces = new ArrayList<>();
    private final Map<String, Integer> named = new HashMap<>();
    /** The notes of the model files read, each file's once. */
    private final List<String> notes = new ArrayList<>();

    /** @param baseDir directory against which relative model paths resolve; null = working directory */
    SceneReader(Path baseDir, ReadLimits limits) {
        this.baseDir = baseDir;
        this.limits = limits;
    }

    SceneDocument read(JsonNode root) {
        root.keys(); // an object: check its version first, as a newer file may have newer keys
        checkVersion(root);
        root.object("version", "description", "models", "materials", "planes", "spheres", "lights", "environment", "camera",
                "render");
        if (root.has("description")) {
            root.get("description").asString();
        }
        if (root.has("materials")) {
            JsonNode map = root.get("materials");
            checkCount(map, map.keys().size(), limits.sceneObjects(), "materials");
            for (String name : map.keys()) {
                named.put(name, materials.size());
                JsonNode m = map.get(name);
                Surface surface = typed(m);
                addMaterial(material(m, surface), surface);
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
            int material = materialRef(s.get("material"));
            builder.addSphere(build(s, () -> new Sphere(center, radius, material)));
        }
        for (JsonNode l : list(root, "lights")) {
            ScenePhysics.light(l, builder);
        }
        if (root.has("environment")) {
            builder.environment(ScenePhysics.environment(root.get("environment"), baseDir));
        }
        if (root.has("camera")) {
            builder.camera(camera(root.get("camera")));
        }
        RenderSettings settings = root.has("render") ? settings(root.get("render")) : RenderSettings.defaults();
        materials.forEach(builder::addMaterial);
        for (int k = 0; k < surfaces.size(); k++) {
            if (surfaces.get(k) != null) {
                builder.surface(k, surfaces.get(k));
            }
        }
        Scene scene = build(root, builder::build);
        return new SceneDocument(scene, settings, notes);
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

    /** The entries of array {@code key} (none when absent), at most the cap of that list. */
    private List<JsonNode> list(JsonNode root, String key) {
        if (!root.has(key)) {
            return List.of();
        }
        JsonNode list = root.get(key);
        List<JsonNode> items = list.array();
        checkCount(list, items.size(), key.equals("models") ? limits.sceneModels() : limits.sceneObjects(), key);
        return items;
    }

    private static void checkCount(JsonNode where, int count, int cap, String what) {
        if (count > cap) {
            throw where.error(count + " " + what + ", more than the " + cap + " a scene may hold");
        }
    }

    /** Runs a model-record constructor, re-throwing its validation error with the JSON path. */
    static <T> T build(JsonNode where, Supplier<T> constructor) {
        try {
            return constructor.get();
        } catch (ModelFormatException e) {
            throw e;
        } catch (IllegalArgumentException e) {
            throw where.error(Echo.cutQuoted(e.getMessage()));
        }
    }

    // Models

    private void model(JsonNode m) {
        m.object("file", "builtin", "patches", "mesh", "transform", "material");
        int sources = (m.has("file") ? 1 : 0) + (m.has("builtin") ? 1 : 0) + (m.has("patches") ? 1 : 0)
                + (m.has("mesh") ? 1 : 0);
        if (sources != 1) {
            throw m.error("expected exactly one of \"file\", \"builtin\", \"patches\" or \"mesh\", found " + sources);
        }
        List<BezierPatch> patches;
        Mesh mesh = null;
        boolean shared = m.has("file") || m.has("builtin");
        if (m.has("file")) {
            Scene file = loadFile(m.get("file"));
            patches = file.patches();
            if (!file.meshes().isEmpty()) {
                mesh = file.meshes().get(0);
            }
        } else if (m.has("builtin")) {
            JsonNode b = m.get("builtin");
            Optional<BuiltIns.BuiltIn> model = BuiltIns.find(b.asString())
                    .filter(x -> x.holds() == FileFormat.Holds.MODEL);
            if (model.isEmpty()) {
                throw b.error("unknown built-in model " + Echo.quote(b.asString()) + " (expected one of: "
                        + String.join(", ", BuiltIns.names(FileFormat.Holds.MODEL)) + ")");
            }
            // a built-in listed again is the same model (one list of patches: split once, Instance)
            patches = loaded.computeIfAbsent("builtin:" + model.get().name(), key -> model.get().load().scene()).patches();
        } else if (m.has("mesh")) {
            patches = List.of();
            mesh = inlineMesh(m.get("mesh"));
        } else {
            patches = inlinePatches(m.get("patches"));
        }
        if ((long) patchCount + patches.size() > limits.patches()) {
            throw m.error("the scene would hold " + ((long) patchCount + patches.size()) + " patches, more than the "
                    + limits.patches() + " a scene may hold");
        }
        patchCount += patches.size();
        JsonNode t = m.get("transform");
        ModelTransform transform = t != null ? transform(t) : ModelTransform.IDENTITY;
        List<BezierPatch> placed = new ArrayList<>(patches.size());
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch p = patches.get(k);
            int number = k + 1;
            placed.add(build(t != null ? t : m, () -> transform.apply(p, number)));
        }
        int material = materialRef(m.get("material"));
        if (shared) {
            builder.addInstance(patches, placed, transform, material);
        } else {
            builder.addPatches(placed, material);
        }
        if (mesh != null) {
            Mesh source = mesh;
            builder.addMesh(build(t != null ? t : m, () -> transform.apply(source)), material);
        }
    }

    private Scene loadFile(JsonNode f) {
        String name = f.asString();
        if (name.isBlank()) {
            throw f.expected("a model file name");
        }
        List<FileFormat> models = FileFormats.holding(FileFormat.Holds.MODEL);
        Optional<FileFormat> format = models.stream().filter(x -> x.matches(name)).findFirst();
        if (format.isEmpty()) {
            throw f.error("model file " + Echo.quote(name) + " must end in " + FileFormats.extensionList(models)
                    + " (for a built-in model use \"builtin\")");
        }
        Path file = FilePaths.find(baseDir, name).orElseThrow(() ->
                f.error(FilePaths.invalidName() + ": " + Echo.quote(name)));
        if (!Files.isRegularFile(file)) {
            throw f.error("no such model file " + Echo.quote(name) + (baseDir == null || name.startsWith("/")
                    ? "" : " in " + baseDir));
        }
        // a file listed again is read once and is the same model (split once, Instance)
        String key = "file:" + file.toAbsolutePath().normalize();
        Scene known = loaded.get(key);
        if (known != null) {
            return known;
        }
        try {
            SceneDocument read = format.get().read(file);
            loaded.put(key, read.scene());
            notes.addAll(read.notes());
            return read.scene();
        } catch (ModelFormatException e) {
            throw f.error(e.getMessage());
        }
    }

    /**
     * An inline triangle mesh: {@code "positions"} ([x, y, z] each), {@code "triangles"} (three
     * 0-based vertex indices each), optional {@code "normals"} ([x, y, z] per vertex) and
     * {@code "uvs"} ([u, v] per vertex).
     */
    private Mesh inlineMesh(JsonNode mesh) {
        mesh.object("positions", "triangles", "normals", "uvs");
        double[] positions = rows(mesh.require("positions"), 3);
        int vertices = positions.length / 3;
        JsonNode tris = mesh.require("triangles");
        List<JsonNode> rows = tris.array();
        if ((long) rows.size() > limits.vertices()) {
            throw tris.error(rows.size() + " triangles, more than the " + limits.vertices() + " a mesh may hold");
        }
        int[] triangles = new int[3 * rows.size()];
        for (int k = 0; k < rows.size(); k++) {
            List<JsonNode> corner = rows.get(k).array();
            if (corner.size() != 3) {
                throw rows.get(k).expected("an array of 3 vertex indices");
            }
            for (int c = 0; c < 3; c++) {
                int index = corner.get(c).asInt();
                if (index < 0 || index >= vertices) {
                    throw corner.get(c).error("vertex index " + index + " out of range 0.." + (vertices - 1));
                }
                triangles[3 * k + c] = index;
            }
        }
        double[] normals = mesh.has("normals") ? rows(mesh.get("normals"), 3) : null;
        double[] uvs = mesh.has("uvs") ? rows(mesh.get("uvs"), 2) : null;
        if (normals != null && normals.length != positions.length) {
            throw mesh.get("normals").error("expected one normal per position (" + vertices + "), found "
                    + normals.length / 3);
        }
        if (uvs != null && uvs.length / 2 != vertices) {
            throw mesh.get("uvs").error("expected one uv per position (" + vertices + "), found " + uvs.length / 2);
        }
        return build(mesh, () -> Mesh.faces(positions, normals, uvs, triangles));
    }

    /** An array of rows of {@code width} finite numbers, flat. */
    private double[] rows(JsonNode list, int width) {
        List<JsonNode> items = list.array();
        if ((long) items.size() > limits.vertices()) {
            throw list.error(items.size() + " rows, more than the " + limits.vertices() + " a mesh may hold");
        }
        double[] out = new double[width * items.size()];
        for (int k = 0; k < items.size(); k++) {
            System.arraycopy(items.get(k).asNumbers(width), 0, out, width * k, width);
        }
        return out;
    }

    private static List<BezierPatch> inlinePatches(JsonNode list) {
        List<BezierPatch> out = new ArrayList<>();
        for (JsonNode p : list.array()) {
            p.object("degree", "points", "weights", "domain", "trim");
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
            out.add(SceneFreeForm.patch(p, n, m, net));
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

    private int addMaterial(Material m, Surface surface) {
        materials.add(m);
        surfaces.add(surface);
        return materials.size() - 1;
    }

    /** The surface of a material object with a {@code "type"}, else null (a Phong material). */
    private Surface typed(JsonNode n) {
        return !n.isString() && n.keys().contains("type") ? ScenePhysics.surface(n, baseDir) : null;
    }

    /** Index of a material reference: absent = default, a name, or an inline object. */
    private int materialRef(JsonNode ref) {
        if (ref == null) {
            return indexOrAdd(Material.DEFAULT, null);
        }
        if (ref.isString()) {
            Integer index = named.get(ref.asString());
            if (index == null) {
                throw ref.error("unknown material " + Echo.quote(ref.asString()) + " (defined: "
                        + (named.isEmpty() ? "none" : Echo.cut(JsonNode.list(named.keySet()))) + ")");
            }
            return index;
        }
        Surface surface = typed(ref);
        return indexOrAdd(material(ref, surface), surface);
    }

    private int indexOrAdd(Material m, Surface surface) {
        for (int k = 0; k < materials.size(); k++) {
            if (materials.get(k).equals(m) && java.util.Objects.equals(surfaces.get(k), surface)) {
                return k;
            }
        }
        return addMaterial(m, surface);
    }

    /** The Phong material of a material object; {@code surface} is its typed surface already read, or null. */
    private static Material material(JsonNode n, Surface surface) {
        if (n.isString()) {
            throw n.expected("a material object");
        }
        if (surface != null) {
            int checker = n.has("checker") ? n.get("checker").asInt() : 0;
            double[] c2 = n.has("color2") ? n.get("color2").asColor() : new double[] {0.95, 0.95, 0.95};
            return build(n, () -> ScenePhysics.phong(surface, checker, c2));
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
        double[] e = {eye.x(), eye.y(), eye.z()}, t = {target.x(), target.y(), target.z()};
        for (int k = 0; k < 3; k++) {
            if (!Double.isFinite(e[k] - t[k])) {
                throw c.error("the distance from eye to target overflows (" + "xyz".charAt(k) + ": "
                        + NumberText.show(e[k]) + " - " + NumberText.show(t[k]) + " is " + NumberText.BEYOND + ")");
            }
        }
        if (!Double.isFinite(eye.sub(target).length())) {
            throw c.error("the distance from eye to target overflows (its square is " + NumberText.BEYOND + ")");
        }
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
        return settings(r, RenderSettings.defaults());
    }

    /** A scene file's render keys. */
    private static final List<String> RENDER_KEYS = List.of("width", "height", "spp", "sampler", "method", "bvh",
            "shading", "checker", "shadows", "maxDepth");

    /**
     * As {@link #settings(JsonNode)}, each key overriding {@code base} (a job file's settings over its
     * scene's); {@code otherKeys} are allowed too and left to the caller.
     */
    static RenderSettings settings(JsonNode r, RenderSettings base, String... otherKeys) {
        List<String> allowed = new ArrayList<>(RENDER_KEYS);
        allowed.addAll(List.of(otherKeys));
        r.object(allowed.toArray(new String[0]));
        RenderSettings all = base;
        for (String key : r.keys()) {
            if (RENDER_KEYS.contains(key)) {
                all = with(all, r.get(key), key);
            }
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
            throw v.error(Echo.cutQuoted(e.getMessage()));
        }
    }
}
