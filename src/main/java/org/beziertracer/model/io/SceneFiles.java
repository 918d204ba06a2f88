package org.beziertracer.model.io;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * Opening "whatever the user named" — a built-in ({@link BuiltIns}) or a file in any format of
 * {@link FileFormats} — and the scene file format itself (JSON, format version
 * {@value SceneReader#VERSION}, described in {@code docs/scene-file.md}).
 *
 * <h2>Errors</h2>
 * Every failure is a one-line {@link ModelFormatException} starting with the file name: syntax
 * errors as {@code room.json:LINE: invalid JSON at column C: …}, everything else with the path of
 * the element in the document, as {@code room.json: spheres[1].radius: expected a positive number,
 * found -2} or {@code room.json: lights[0]: unknown key "colour" (…)}.
 *
 * <p>Stateless and thread-safe.
 */
public final class SceneFiles {
    private SceneFiles() {}

    /** Horizontal field of view, in degrees, of a camera that gives none. */
    public static final double DEFAULT_FOV = 40;

    /**
     * A built-in ({@link BuiltIns}, any case; a built-in wins over a file of the same name), or a
     * file read by the format its extension names ({@link FileFormats}). A model file opens with
     * {@link org.beziertracer.model.RenderSettings#defaults()}, no lights and no camera.
     *
     * @throws ModelFormatException one line naming the file (or the name), for any problem
     */
    public static SceneDocument load(String nameOrPath) {
        Optional<BuiltIns.BuiltIn> builtIn = BuiltIns.find(nameOrPath);
        if (builtIn.isPresent()) {
            return builtIn.get().load();
        }
        Optional<FileFormat> format = FileFormats.find(nameOrPath);
        if (format.isEmpty()) {
            throw new ModelFormatException(nameOrPath, "not a built-in name (" + String.join(", ", BuiltIns.names())
                    + ") and not a " + FileFormats.extensionList(FileFormats.ALL) + " file");
        }
        return format.get().read(FilePaths.of(nameOrPath));
    }

    /**
     * {@link #load(String)}, with the render settings' method checked by {@code methods}: to the
     * model layer a method is a plain word ({@link org.beziertracer.model.RenderSettings#method()});
     * which words name one only the layer of the solvers knows ({@code intersect.Method::parse}). A
     * name it refuses fails the load in the one line any bad value of the file gets, naming the
     * file and the key: {@code room.json: render.method: unknown method 'x': expected clipping,
     * newton or subdivision}.
     *
     * @param methods throws an {@link IllegalArgumentException} with a one-line message for a name
     *                it does not know
     * @throws ModelFormatException one line naming the file (or the name), for any problem
     */
    public static SceneDocument load(String nameOrPath, Consumer<String> methods) {
        SceneDocument doc = load(nameOrPath);
        try {
            methods.accept(doc.settings().method());
        } catch (IllegalArgumentException e) {
            // Named as the reader names the file (FileFormat.read: the path as given)
            throw new ModelFormatException(FilePaths.text(FilePaths.of(nameOrPath)),
                    "render.method: " + Echo.cutQuoted(e.getMessage()));
        }
        return doc;
    }

    /**
     * Parses scene-file text.
     *
     * @param fileName shown at the start of error messages
     * @param baseDir  directory for relative model paths; null = the working directory
     */
    public static SceneDocument parse(String json, String fileName, Path baseDir) {
        try {
            return read(TextSource.of(json, fileName), baseDir);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Reads a scene file (the reader {@link FileFormats#SCENE} declares): the whole text, at most
     * {@link ReadLimits#bytesInMemory()} bytes, then the document.
     */
    static SceneDocument read(TextSource text, Path baseDir) throws IOException {
        String json = text.readAll("a scene file");
        return new SceneReader(baseDir, text.limits()).read(JsonNode.parse(json, text.fileName()));
    }

    /** The document as scene-file text (version {@value SceneReader#VERSION}, patches inline). */
    public static String toJson(SceneDocument doc) {
        return SceneWriter.toJson(doc);
    }
}
