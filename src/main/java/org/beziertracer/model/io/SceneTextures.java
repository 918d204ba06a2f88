package org.beziertracer.model.io;

import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Locale;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import com.google.gson.JsonPrimitive;

import org.beziertracer.model.HdrImage;
import org.beziertracer.model.Surface;
import org.beziertracer.model.Texture;

/**
 * A typed material's {@code "color"} when it varies over (u,v) (docs/scene-file.md): {@code
 * {"checker": {"even": [r, g, b], "odd": [r, g, b], "scale": [su, sv]}}} or {@code {"image":
 * "wood.png", "scale": [su, sv]}} (a PNG or JPEG file relative to the scene file, sRGB decoded to
 * linear by {@link ImageFiles}); read into a {@link Texture} and written back. Errors name the file
 * and the key. Stateless.
 */
final class SceneTextures {
    private SceneTextures() {}

    /** Most pixels of a texture image (64 Mpixels), checked from its header before it is decoded. */
    static final long MAX_PIXELS = 1L << 26;

    /** The texture of a {@code "color"} object; image files resolve against {@code baseDir} (null: working directory). */
    static Texture read(JsonNode color, Path baseDir) {
        color.object("checker", "image", "scale");
        if (color.has("checker") == color.has("image")) {
            throw color.error("a textured colour needs exactly one of \"checker\" or \"image\"");
        }
        double[] scale = {1, 1};
        if (color.has("scale")) {
            JsonNode s = color.get("scale");
            scale = s.asNumbers(2);
            if (!(scale[0] > 0 && scale[1] > 0)) {
                throw s.error("scale must be 2 numbers > 0 (repeats along u and v), found " + shown(scale));
            }
        }
        double su = scale[0], sv = scale[1];
        if (color.has("checker")) {
            JsonNode c = color.get("checker");
            c.object("even", "odd", "scale");
            if (c.has("scale")) {
                throw c.get("scale").error("\"scale\" belongs beside \"checker\", not inside it");
            }
            Surface.Vec even = albedo(c.get("even"), 0.8), odd = albedo(c.get("odd"), 0.2);
            return SceneReader.build(color, () -> new Texture.Checker(even, odd, su, sv));
        }
        JsonNode image = color.get("image");
        String name = image.asString();
        String lower = name.toLowerCase(Locale.ROOT);
        if (!(lower.endsWith(".png") || lower.endsWith(".jpg") || lower.endsWith(".jpeg"))) {
            throw image.error("a texture image must be a .png, .jpg or .jpeg file, found " + Echo.quote(name));
        }
        HdrImage pixels;
        try {
            Path file = baseDir == null ? Path.of(name) : baseDir.resolve(name);
            pixels = ImageFiles.linear(ImageFiles.read(file, "a texture image", 1, MAX_PIXELS));
        } catch (InvalidPathException x) {
            throw image.error("not a file name: " + Echo.quote(name));
        } catch (ModelFormatException x) {
            throw image.error(Echo.cutQuoted(x.getMessage()));
        }
        return SceneReader.build(color, () -> new Texture.Image(name, pixels, su, sv));
    }

    /** An albedo {@code [r, g, b]} in 0..1, or {@code fallback} grey when the key is absent. */
    private static Surface.Vec albedo(JsonNode n, double fallback) {
        double[] c = n == null ? new double[] {fallback, fallback, fallback} : albedo(n);
        return new Surface.Vec(c[0], c[1], c[2]);
    }

    /** A colour {@code [r, g, b]} each in 0..1 (a physically based material's albedo or tint). */
    static double[] albedo(JsonNode n) {
        double[] c = n.asColor();
        if (c[0] > 1 || c[1] > 1 || c[2] > 1) {
            throw n.error("a physically based colour is an albedo in 0..1, found " + shown(c));
        }
        return c;
    }

    /** Numbers as the file gives them: {@code [2, 0, 0]}. */
    private static String shown(double[] v) {
        StringBuilder out = new StringBuilder("[");
        for (int i = 0; i < v.length; i++) {
            out.append(i > 0 ? ", " : "").append(NumberText.show(v[i]));
        }
        return out.append(']').toString();
    }

    /** The {@code "color"} object of a texture, as {@link #read} reads it. */
    static JsonObject write(Texture t) {
        JsonObject o = new JsonObject();
        if (t instanceof Texture.Checker c) {
            JsonObject checker = new JsonObject();
            checker.add("even", SceneWriter.numbers(c.even().r(), c.even().g(), c.even().b()));
            checker.add("odd", SceneWriter.numbers(c.odd().r(), c.odd().g(), c.odd().b()));
            o.add("checker", checker);
        } else {
            o.add("image", new JsonPrimitive(((Texture.Image) t).name()));
        }
        JsonArray scale = SceneWriter.numbers(t.su(), t.sv());
        o.add("scale", scale);
        return o;
    }
}
