package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Supplier;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.FileFormat.Holds;

/**
 * The built-in models and scenes, declared once, in {@link #ALL}: the command line, the app's
 * Models menu and a scene file's {@code "builtin"} key all take their names from here. Adding one
 * is one line: {@code resource("teacup", "the teacup", "models/teacup.obj")} for a file under
 * {@code src/main/resources/org/beziertracer/} (read through the format registry, once, on first
 * use), or {@code model("name", "…", Models::something)} for a model built in code.
 *
 * <p>Names are matched case-insensitively; a built-in wins over a file of the same name. Loaded
 * documents are immutable and shared. Thread-safe.
 */
public final class BuiltIns {
    private BuiltIns() {}

    /** Classpath folder of the built-in resources. */
    static final String RESOURCES = "/org/beziertracer/";

    /** One built-in model or scene. */
    public record BuiltIn(String name, String description, Holds holds, Supplier<SceneDocument> source) {
        /** The document (loaded on first use, then shared). */
        public SceneDocument load() {
            return source.get();
        }
    }

    /** Every built-in, in the order shown to users. */
    public static final List<BuiltIn> ALL = List.of(
            model("patch", "the default bicubic patch", Models::patch),
            resource("teapot", "the Utah teapot (32 bicubic patches)", "models/teapot.bpt"),
            resource("teacup", "Newell's teacup (26 bicubic patches)", "models/teacup.bpt"),
            resource("teaspoon", "Newell's teaspoon (16 bicubic patches)", "models/teaspoon.bpt"),
            model("sphere", "the unit sphere, one rational biquadratic B-spline (8 rational pieces)", Models::sphere),
            model("torus", "a torus, one rational biquadratic B-spline (16 rational pieces)", Models::torus),
            model("trimmed-plate", "a curved plate trimmed by a rounded square, with three holes",
                    Models::trimmedPlate),
            model("wavy6", "a wavy 6×6-point grid (degree 5)", () -> GeneratedModels.wavy(6)),
            model("wavy10", "a wavy 10×10-point grid (degree 9)", () -> GeneratedModels.wavy(10)),
            model("curved", "a strongly curved bicubic arch", GeneratedModels::curved),
            resource("teapot-room", "the teapot on a checkered floor, with a mirror and a glass sphere",
                    "scenes/teapot-room.json"),
            resource("studio", "a gold teapot and a glass teacup on a floor under an area light and a constant sky "
                    + "(for the path tracer)", "scenes/studio.json"));

    /** Names of every built-in, in order. */
    public static List<String> names() {
        return ALL.stream().map(BuiltIn::name).toList();
    }

    /** Names of the built-ins that hold {@code holds} (models or scenes), in order. */
    public static List<String> names(Holds holds) {
        return ALL.stream().filter(b -> b.holds() == holds).map(BuiltIn::name).toList();
    }

    /** The built-in called {@code name} (any case), if there is one. */
    public static Optional<BuiltIn> find(String name) {
        String lower = name.toLowerCase(Locale.ROOT);
        return ALL.stream().filter(b -> b.name().equals(lower)).findFirst();
    }

    /** A model built in code, shown with default settings, no lights and no camera. */
    private static BuiltIn model(String name, String description, Supplier<Scene> scene) {
        return new BuiltIn(name, description, Holds.MODEL,
                once(() -> new SceneDocument(scene.get(), RenderSettings.defaults())));
    }

    /** A model or scene file under {@value #RESOURCES}, read by the format its extension names. */
    private static BuiltIn resource(String name, String description, String path) {
        FileFormat format = FileFormats.find(path).orElseThrow(
                () -> new IllegalStateException("built-in " + name + ": no format reads " + path));
        return new BuiltIn(name, description, format.holds(), once(() -> {
            try (InputStream in = BuiltIns.class.getResourceAsStream(RESOURCES + path)) {
                if (in == null) {
                    throw new IllegalStateException("built-in resource " + RESOURCES + path + " is missing");
                }
                return format.read(in, path.substring(path.lastIndexOf('/') + 1), null);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }));
    }

    /** {@code s} evaluated on first use only, then the same value (thread-safe). */
    private static <T> Supplier<T> once(Supplier<T> s) {
        return new Supplier<>() {
            private volatile T value;

            @Override
            public T get() {
                T v = value;
                if (v == null) {
                    synchronized (this) {
                        v = value;
                        if (v == null) {
                            v = s.get();
                            value = v;
                        }
                    }
                }
                return v;
            }
        };
    }
}
