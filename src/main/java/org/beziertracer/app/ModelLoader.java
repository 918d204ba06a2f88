package org.beziertracer.app;

import java.nio.file.Path;
import java.util.List;

import org.beziertracer.intersect.HeapBudget;
import org.beziertracer.intersect.IntersectOptions;
import org.beziertracer.intersect.Method;
import org.beziertracer.model.io.BuiltIns;
import org.beziertracer.model.io.FileFormat;
import org.beziertracer.model.io.FileFormats;
import org.beziertracer.model.io.ModelFormatException;
import org.beziertracer.model.io.SceneDocument;
import org.beziertracer.model.io.SceneFiles;

/**
 * Loads what File → Open and the Models menu offer — BPT and OBJ models, JSON scene files and
 * the built-in models and scenes — always as a {@link SceneDocument} (a bare model gets the
 * default settings, no lights and no camera), through {@link SceneFiles#load} with the method
 * checked by {@link Method#parse}. Every failure is a
 * one-line {@link IllegalArgumentException} (usually a {@link ModelFormatException}) for the
 * error dialog. Stateless.
 */
public final class ModelLoader {
    private ModelLoader() {}

    /** Built-in models and scenes, in menu order ({@link BuiltIns}). */
    public static final List<String> BUILT_INS = BuiltIns.names();

    /** Formats File → Open accepts: every format of the registry. */
    public static final List<FileFormat> OPEN_FORMATS = FileFormats.ALL;

    /** Formats File → Save writes the surfaces in: the writable model formats of the registry. */
    public static final List<FileFormat> SAVE_FORMATS = FileFormats.writable().stream()
            .filter(f -> f.holds() == FileFormat.Holds.MODEL).toList();

    /** Extensions of {@link #SAVE_FORMATS}, the first the default. */
    public static String[] saveExtensions() {
        return FileFormats.extensions(SAVE_FORMATS).toArray(String[]::new);
    }

    /** True when {@code file} can be saved back in place (its format is one of {@link #SAVE_FORMATS}). */
    public static boolean savesInPlace(Path file) {
        return SAVE_FORMATS.stream().anyMatch(f -> f.matches(file.toString()));
    }

    /** Loads a built-in by name. */
    public static SceneDocument builtIn(String name) {
        return fitting(name, SceneFiles.load(name, Method::parse));
    }

    /**
     * Loads a file; one that would not fit in the heap is refused ({@link HeapBudget}), and so is a
     * scene file whose method {@link Method#parse} does not know.
     */
    public static SceneDocument load(Path file) {
        return fitting(file.toString(), SceneFiles.load(file.toString(), Method::parse));
    }

    private static SceneDocument fitting(String name, SceneDocument doc) {
        HeapBudget.require(name, doc.scene(), IntersectOptions.defaults());
        return doc;
    }
}
