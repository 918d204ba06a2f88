package org.beziertracer.model.io;

import java.util.List;
import java.util.Map;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;

import org.beziertracer.math.Vec3;
import org.beziertracer.model.AreaLight;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Environment;
import org.beziertracer.model.Surface;
import org.beziertracer.model.SpotLight;
import org.beziertracer.model.CameraSpec;
import org.beziertracer.model.Material;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Plane;
import org.beziertracer.model.PointLight;
import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.Sphere;

/**
 * Writes a {@link SceneDocument} as a version-1 scene file that {@link SceneReader} reads back to
 * an equal document: every material is named {@code m0, m1, …} in scene order and referenced by
 * name, patches are written inline ({@code "patches"}, one model per run of patches sharing a
 * material; a rational patch with its {@code "weights"}, a piece of a free-form surface with its
 * {@code "domain"} and {@code "trim"}, {@link SceneFreeForm}), each mesh as an inline
 * {@code "mesh"} model,
 * numbers use the shortest text that parses back to the same double
 * ({@link NumberText#format}). Arrays of numbers stay on one line. Stateless.
 */
final class SceneWriter {
    private SceneWriter() {}

    static String toJson(SceneDocument doc) {
        Scene scene = doc.scene();
        JsonObject root = new JsonObject();
        root.addProperty("version", SceneReader.VERSION);

        // Materials by name, in index order
        JsonObject materials = new JsonObject();
        for (int k = 0; k < scene.materials().size(); k++) {
            Surface surface = scene.surface(k);
            materials.add("m" + k, surface == null ? material(scene.materials().get(k))
                    : typed(surface, scene.materials().get(k)));
        }
        root.add("materials", materials);

        addIfAny(root, "models", models(scene));
        addIfAny(root, "planes", planes(scene));
        addIfAny(root, "spheres", spheres(scene));
        addIfAny(root, "lights", lights(scene));
        scene.environment().ifPresent(e -> root.add("environment", environment(e)));
        scene.camera().ifPresent(c -> root.add("camera", camera(c)));
        root.add("render", settings(doc.settings()));

        StringBuilder out = new StringBuilder();
        print(root, "", out);
        return out.append('\n').toString();
    }

    /** The patches: one inline model per run of equal material. */
    private static JsonArray models(Scene scene) {
        JsonArray models = new JsonArray();
        for (int start = 0; start < scene.patchCount(); ) {
            int material = scene.patchMaterial(start);
            int end = start;
            JsonArray patches = new JsonArray();
            while (end < scene.patchCount() && scene.patchMaterial(end) == material) {
                patches.add(patch(scene.patches().get(end++)));
            }
            JsonObject model = new JsonObject();
            model.add("patches", patches);
            model.addProperty("material", "m" + material);
            models.add(model);
            start = end;
        }
        for (int k = 0; k < scene.meshes().size(); k++) {
            JsonObject model = new JsonObject();
            model.add("mesh", mesh(scene.meshes().get(k)));
            model.addProperty("material", "m" + scene.meshMaterial(k));
            models.add(model);
        }
        return models;
    }

    /** An inline mesh: positions, triangles (0-based), and normals and uvs when it has them. */
    private static JsonObject mesh(Mesh m) {
        JsonObject o = new JsonObject();
        JsonArray positions = new JsonArray();
        JsonArray normals = new JsonArray();
        JsonArray uvs = new JsonArray();
        for (int k = 0; k < m.vertexCount(); k++) {
            positions.add(numbers(m.position(k, 0), m.position(k, 1), m.position(k, 2)));
            if (m.hasNormals()) {
                normals.add(numbers(m.normal(k, 0), m.normal(k, 1), m.normal(k, 2)));
            }
            if (m.hasUvs()) {
                uvs.add(numbers(m.uv(k, 0), m.uv(k, 1)));
            }
        }
        JsonArray triangles = new JsonArray();
        for (int t = 0; t < m.triangleCount(); t++) {
            triangles.add(numbers(m.triangleVertex(t, 0), m.triangleVertex(t, 1), m.triangleVertex(t, 2)));
        }
        o.add("positions", positions);
        o.add("triangles", triangles);
        if (m.hasNormals()) {
            o.add("normals", normals);
        }
        if (m.hasUvs()) {
            o.add("uvs", uvs);
        }
        return o;
    }

    private static JsonArray planes(Scene scene) {
        JsonArray planes = new JsonArray();
        for (Plane p : scene.planes()) {
            JsonObject o = new JsonObject();
            o.add("point", vec(p.point()));
            o.add("normal", vec(p.normal()));
            o.addProperty("material", "m" + p.material());
            o.add("uvScale", number(p.uvScale()));
            planes.add(o);
        }
        return planes;
    }

    private static JsonArray spheres(Scene scene) {
        JsonArray spheres = new JsonArray();
        for (Sphere s : scene.spheres()) {
            JsonObject o = new JsonObject();
            o.add("center", vec(s.center()));
            o.add("radius", number(s.radius()));
            o.addProperty("material", "m" + s.material());
            spheres.add(o);
        }
        return spheres;
    }

    private static JsonArray lights(Scene scene) {
        JsonArray lights = new JsonArray();
        for (PointLight l : scene.lights()) {
            JsonObject o = new JsonObject();
            o.add("position", vec(l.position()));
            o.add("color", numbers(l.r(), l.g(), l.b()));
            lights.add(o);
        }
        for (SpotLight l : scene.spotLights()) {
            JsonObject o = new JsonObject();
            o.addProperty("type", "spot");
            o.add("position", vec(l.position()));
            o.add("direction", vec(l.direction()));
            o.add("angle", number(l.angle()));
            o.add("falloff", number(l.falloff()));
            o.add("color", numbers(l.r(), l.g(), l.b()));
            lights.add(o);
        }
        for (AreaLight a : scene.areaLights()) {
            JsonObject o = new JsonObject();
            if (a.shape() == AreaLight.Shape.SPHERE) {
                o.addProperty("type", "sphere");
                o.add("center", vec(a.center()));
                o.add("radius", number(a.radius()));
            } else {
                o.addProperty("type", "rect");
                o.add("corner", vec(a.corner()));
                o.add("edge1", vec(a.edge1()));
                o.add("edge2", vec(a.edge2()));
            }
            o.add("color", numbers(a.r(), a.g(), a.b()));
            if (!Double.isNaN(a.power())) {
                o.add("power", number(a.power()));
            }
            lights.add(o);
        }
        return lights;
    }

    /** A colour environment, or an image one by the file name it was read from. */
    private static JsonObject environment(Environment e) {
        JsonObject o = new JsonObject();
        if (e.image() != null) {
            o.addProperty("image", e.image());
        } else {
            o.add("color", numbers(e.r(), e.g(), e.b()));
        }
        putIfDiffers(o, "intensity", e.intensity(), 1);
        putIfDiffers(o, "rotate", e.rotate(), 0);
        return o;
    }

    /** A typed (physically based) material; its Phong look is derived again on reading. */
    private static JsonObject typed(Surface s, Material m) {
        JsonObject o = new JsonObject();
        o.addProperty("type", s.kind().label());
        o.add("color", s.texture() != null ? SceneTextures.write(s.texture()) : numbers(s.r(), s.g(), s.b()));
        o.add("roughness", number(s.roughness()));
        if (s.kind() == Surface.Kind.DIELECTRIC || s.kind() == Surface.Kind.PLASTIC) {
            o.add("ior", number(s.ior()));
        }
        if (s.kind() == Surface.Kind.CONDUCTOR) {
            if (s.metal() != null) {
                o.addProperty("metal", s.metal());
            } else {
                o.add("eta", numbers(s.eta().r(), s.eta().g(), s.eta().b()));
                o.add("k", numbers(s.k().r(), s.k().g(), s.k().b()));
            }
        }
        if (m.checkerSquares() > 0) {
            o.addProperty("checker", m.checkerSquares());
            o.add("color2", numbers(m.r2(), m.g2(), m.b2()));
        }
        return o;
    }

    private static void addIfAny(JsonObject root, String key, JsonArray array) {
        if (!array.isEmpty()) {
            root.add(key, array);
        }
    }

    /** Only the fields that differ from {@link Material#DEFAULT}; {@code color2} whenever it matters. */
    private static JsonObject material(Material m) {
        Material d = Material.DEFAULT;
        JsonObject o = new JsonObject();
        if (m.r() != d.r() || m.g() != d.g() || m.b() != d.b()) {
            o.add("color", numbers(m.r(), m.g(), m.b()));
        }
        putIfDiffers(o, "ambient", m.ambient(), d.ambient());
        putIfDiffers(o, "diffuse", m.diffuse(), d.diffuse());
        putIfDiffers(o, "specular", m.specular(), d.specular());
        putIfDiffers(o, "shininess", m.shininess(), d.shininess());
        putIfDiffers(o, "reflectivity", m.reflectivity(), d.reflectivity());
        putIfDiffers(o, "transparency", m.transparency(), d.transparency());
        putIfDiffers(o, "ior", m.ior(), d.ior());
        if (m.checkerSquares() != d.checkerSquares()) {
            o.addProperty("checker", m.checkerSquares());
        }
        if (m.checkerSquares() > 0 || m.r2() != 0 || m.g2() != 0 || m.b2() != 0) {
            o.add("color2", numbers(m.r2(), m.g2(), m.b2()));
        }
        return o;
    }

    private static void putIfDiffers(JsonObject o, String key, double value, double fallback) {
        if (Double.compare(value, fallback) != 0) {
            o.add(key, number(value));
        }
    }

    private static JsonObject patch(BezierPatch p) {
        JsonObject o = new JsonObject();
        JsonArray degree = new JsonArray();
        degree.add(p.degreeU());
        degree.add(p.degreeV());
        o.add("degree", degree);
        JsonArray points = new JsonArray();
        for (int j = 0; j <= p.degreeV(); j++) {
            for (int i = 0; i <= p.degreeU(); i++) {
                points.add(numbers(p.get(i, j, 0), p.get(i, j, 1), p.get(i, j, 2)));
            }
        }
        o.add("points", points);
        SceneFreeForm.write(o, p);
        return o;
    }

    private static JsonObject camera(CameraSpec c) {
        JsonObject o = new JsonObject();
        o.add("eye", vec(c.eye()));
        o.add("target", vec(c.target()));
        o.add("up", vec(c.up()));
        o.add("fov", number(c.fovDegrees()));
        o.add("orthoWidth", number(c.orthoWidth()));
        return o;
    }

    private static JsonObject settings(RenderSettings s) {
        JsonObject o = new JsonObject();
        o.addProperty("width", s.width());
        o.addProperty("height", s.height());
        o.addProperty("spp", s.spp());
        o.addProperty("sampler", s.sampler());
        o.addProperty("method", s.method());
        o.addProperty("bvh", s.bvh());
        o.addProperty("shading", s.shading());
        o.addProperty("checker", s.checker());
        o.addProperty("shadows", s.shadows());
        o.addProperty("maxDepth", s.maxDepth());
        return o;
    }

    private static JsonArray vec(Vec3 v) { return numbers(v.x(), v.y(), v.z()); }

    static JsonArray numbers(double... values) {
        JsonArray a = new JsonArray();
        for (double v : values) {
            a.add(number(v));
        }
        return a;
    }

    /** A number printed by {@link NumberText#format}: shortest round-trip text, whole numbers bare. */
    static JsonPrimitive number(double v) {
        return new JsonPrimitive(new JsonNode.NumberLiteral(NumberText.format(v)));
    }

    // Printing: objects one key per line, arrays of primitives on one line

    private static void print(JsonElement e, String indent, StringBuilder out) {
        if (e.isJsonObject()) {
            if (e.getAsJsonObject().isEmpty()) {
                out.append("{}");
                return;
            }
            String inner = indent + "  ";
            out.append("{\n");
            boolean first = true;
            for (Map.Entry<String, JsonElement> entry : e.getAsJsonObject().entrySet()) {
                out.append(first ? "" : ",\n").append(inner).append(new JsonPrimitive(entry.getKey())).append(": ");
                print(entry.getValue(), inner, out);
                first = false;
            }
            out.append('\n').append(indent).append('}');
        } else if (e.isJsonArray()) {
            List<JsonElement> items = e.getAsJsonArray().asList();
            boolean flat = items.stream().allMatch(JsonElement::isJsonPrimitive);
            String inner = indent + "  ";
            out.append(flat || items.isEmpty() ? "[" : "[\n");
            for (int k = 0; k < items.size(); k++) {
                out.append(k == 0 ? "" : flat ? ", " : ",\n").append(flat ? "" : inner);
                print(items.get(k), inner, out);
            }
            out.append(flat || items.isEmpty() ? "]" : "\n" + indent + "]");
        } else {
            out.append(e.isJsonPrimitive() && e.getAsJsonPrimitive().isNumber()
                    ? e.getAsNumber().toString() : e.toString());
        }
    }
}
