package org.beziertracer.ui;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.ModelFormatException;
import org.beziertracer.model.io.Models;
import org.beziertracer.model.io.SceneDocument;

/**
 * Loads what File → Open and the Models menu offer: BPT and OBJ models, scene files and the
 * built-in models and scenes, always as a {@link SceneDocument}. Every failure is a one-line
 * {@link IllegalArgumentException} (usually a {@link ModelFormatException}) for the error dialog.
 * Stateless.
 */
public final class ModelLoader {
    private ModelLoader() {}

    /** Built-in models and scenes, in menu order. */
    public static final List<String> BUILT_INS = List.of("patch", "teapot", "teapot-room");

    /** Extensions File → Open accepts. */
    public static final List<String> EXTENSIONS = List.of("bpt", "obj", "json");

    /** Loads a built-in by name. */
    public static SceneDocument builtIn(String name) {
        return load(name);
    }

    /** Loads a file. */
    public static SceneDocument load(Path file) {
        return load(file.toString());
    }

    static SceneDocument load(String nameOrPath) {
        String lower = nameOrPath.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".json") || lower.equals("teapot-room")) {
            return SceneSource.load(nameOrPath);
        }
        Scene scene = Models.load(nameOrPath);
        return new SceneDocument(scene, RenderSettings.defaults());
    }
}
