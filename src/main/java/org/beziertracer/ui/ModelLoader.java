package org.beziertracer.ui;

import java.nio.file.Path;
import java.util.List;

import org.beziertracer.model.io.ModelFormatException;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;

/**
 * Loads what File → Open and the Models menu offer — BPT and OBJ models, JSON scene files and
 * the built-in models and scenes — always as a {@link SceneDocument} (a bare model gets the
 * default settings, no lights and no camera), through {@link SceneFiles#load}. Every failure is a
 * one-line {@link IllegalArgumentException} (usually a {@link ModelFormatException}) for the
 * error dialog. Stateless.
 */
public final class ModelLoader {
    private ModelLoader() {}

    /** Built-in models and scenes, in menu order. */
    public static final List<String> BUILT_INS = List.of("patch", "teapot", "teapot-room", "teacup", "teaspoon",
            "sphere", "torus", "trimmed-plate");

    /** Extensions File → Open accepts. */
    public static final List<String> EXTENSIONS = List.of("bpt", "obj", "json");

    /** Loads a built-in by name. */
    public static SceneDocument builtIn(String name) {
        return SceneFiles.load(name);
    }

    /** Loads a file. */
    public static SceneDocument load(Path file) {
        return SceneFiles.load(file.toString());
    }
}
