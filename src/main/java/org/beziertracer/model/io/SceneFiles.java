package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import org.beziertracer.model.RenderSettings;

/**
 * Scene files (JSON, format version {@value SceneReader#VERSION}, described in
 * {@code docs/scene-file.md}), built-in scenes, and loading "whatever the user named".
 *
 * <h2>Built-in scenes</h2>
 * <ul>
 *   <li>{@code patch} — the default bicubic patch ({@link Models#patch()}), no lights (so the
 *       renderer lights it from the eye), no camera (the renderer frames it), default settings.</li>
 *   <li>{@code teapot-room} — the Utah teapot on a checkered floor with a mirror sphere and a glass
 *       sphere, one point light, a camera, shadows on, depth 5; read from the classpath resource
 *       {@value #TEAPOT_ROOM_RESOURCE}, which doubles as the format's example.</li>
 * </ul>
 *
 * <h2>Errors</h2>
 * Every failure is a one-line {@link ModelFormatException} starting with the file name: syntax
 * errors as {@code room.json:LINE: invalid JSON at column C: …}, everything else with the JSON
 * path, as {@code room.json: $.spheres[1].radius: expected a positive number, found -2} or
 * {@code room.json: unknown key "lightz" at $.lights[0] (…)}.
 *
 * <p>Stateless and thread-safe.
 */
public final class SceneFiles {
    private SceneFiles() {}

    /** Classpath resource of the {@code teapot-room} scene. */
    public static final String TEAPOT_ROOM_RESOURCE = "/org/beziertracer/scenes/teapot-room.json";

    /** Horizontal field of view, in degrees, of a camera that gives none. */
    public static final double DEFAULT_FOV = 40;

    private static final List<String> BUILT_IN = List.of("patch", "teapot-room");

    /** Names of the built-in scenes, in the order shown to users. */
    public static List<String> builtInNames() {
        return BUILT_IN;
    }

    /**
     * A built-in scene ({@link #builtInNames()}, case-insensitive; these win over the built-in
     * model of the same name), a {@code .json} scene file, or anything {@link Models#load} accepts —
     * a bare model, given {@link RenderSettings#defaults()}, no lights and no camera.
     *
     * @throws ModelFormatException one line naming the file, for any problem
     */
    public static SceneDocument load(String nameOrPath) {
        String lower = nameOrPath.toLowerCase(Locale.ROOT);
        if (lower.equals("patch")) {
            return new SceneDocument(Models.patch(), RenderSettings.defaults());
        }
        if (lower.equals("teapot-room")) {
            return teapotRoom();
        }
        if (lower.endsWith(".json")) {
            return read(Path.of(nameOrPath));
        }
        return new SceneDocument(Models.load(nameOrPath), RenderSettings.defaults());
    }

    /**
     * Reads a scene file; relative model paths resolve against its directory. Error messages name
     * the file as given.
     */
    public static SceneDocument read(Path file) {
        String name = file.toString();
        if (!Files.isRegularFile(file)) {
            throw new ModelFormatException(name, Files.isDirectory(file) ? "is a directory, not a scene file"
                    : "no such file (and not a built-in scene: " + String.join(", ", BUILT_IN) + ")");
        }
        String json;
        try {
            json = Files.readString(file, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new ModelFormatException(name, "cannot read: " + e.getClass().getSimpleName() + " " + e.getMessage());
        }
        Path dir = file.toAbsolutePath().getParent();
        return parse(json, name, dir);
    }

    /**
     * Parses scene-file text.
     *
     * @param fileName shown at the start of error messages
     * @param baseDir  directory for relative model paths; null = the working directory
     */
    public static SceneDocument parse(String json, String fileName, Path baseDir) {
        return new SceneReader(baseDir).read(JsonNode.parse(json, fileName));
    }

    /** The document as scene-file text (version {@value SceneReader#VERSION}, patches inline). */
    public static String toJson(SceneDocument doc) {
        return SceneWriter.toJson(doc);
    }

    /**
     * Saves {@code doc} atomically ({@link AtomicFiles}). The file is self-contained (patches are
     * written inline), and {@link #read} of it gives back an equal scene and equal settings.
     */
    public static void write(Path file, SceneDocument doc) throws IOException {
        String json = toJson(doc);
        AtomicFiles.write(file, out -> out.write(json));
    }

    private static SceneDocument teapotRoom() {
        try (InputStream in = SceneFiles.class.getResourceAsStream(TEAPOT_ROOM_RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("built-in scene resource " + TEAPOT_ROOM_RESOURCE + " is missing");
            }
            return parse(new String(in.readAllBytes(), StandardCharsets.UTF_8), "teapot-room.json", null);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
