package org.beziertracer.model.io;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Built-in models and loading a model by name or path.
 *
 * <h2>Built-in models</h2>
 * <ul>
 *   <li>{@code patch} — the default bicubic patch (the "reset" model): {@link #flatGrid(int, int)
 *       flatGrid(4, 4)}, a flat square of 4×4 control points at
 *       {@code x, y ∈ {-1.5, -0.5, 0.5, 1.5}}, {@code z = 0}.</li>
 *   <li>{@code teapot} — the 32-patch Utah teapot as built into Sunflow (z-up, bounding box
 *       {@code x[-120,141] y[-80,80] z[0,120]}), read from the classpath resource
 *       {@value #TEAPOT_RESOURCE}; see {@code shared/models/README.md} for its provenance.</li>
 *   <li>{@code wavy2} … {@code wavy16}, {@code curved} — generated benchmark surfaces
 *       ({@link GeneratedModels}).</li>
 * </ul>
 * Otherwise {@link #load(String)} takes a path and picks the reader by extension
 * ({@code .bpt} or {@code .obj}, any case). All failures are one-line
 * {@link ModelFormatException}s naming the file. Stateless and thread-safe.
 */
public final class Models {
    private Models() {}

    /** Classpath resource holding the teapot in BPT format. */
    public static final String TEAPOT_RESOURCE = "/org/beziertracer/models/teapot.bpt";

    /** Names accepted by {@link #builtIn(String)}, in the order shown to users. */
    public static final List<String> NAMES = List.of("patch", "teapot", "wavy2..wavy16", "curved");

    /** Half the side of the square spanned by {@link #flatGrid(int, int)}. */
    public static final double GRID_HALF_SIZE = 1.5;

    /** The default bicubic patch: {@code flatGrid(4, 4)}. */
    public static Scene patch() {
        return new Scene(List.of(flatGrid(4, 4)));
    }

    /**
     * A flat patch of {@code pointsU × pointsV} control points (degree {@code points − 1} in each
     * direction), evenly spaced over the square {@code [-1.5, 1.5]²} in the plane {@code z = 0}:
     * {@code P_ij = (-1.5 + 3i/(pointsU−1), -1.5 + 3j/(pointsV−1), 0)}. The square stays the same
     * size whatever the point count; u runs along +x, v along +y, so dS/du × dS/dv points to +z.
     *
     * @param pointsU control points along u, 2..16
     * @param pointsV control points along v, 2..16
     */
    public static BezierPatch flatGrid(int pointsU, int pointsV) {
        checkPoints("u", pointsU);
        checkPoints("v", pointsV);
        double[] net = new double[pointsU * pointsV * 3];
        double size = 2 * GRID_HALF_SIZE;
        for (int j = 0; j < pointsV; j++) {
            for (int i = 0; i < pointsU; i++) {
                int k = 3 * (j * pointsU + i);
                net[k] = -GRID_HALF_SIZE + size * i / (pointsU - 1);
                net[k + 1] = -GRID_HALF_SIZE + size * j / (pointsV - 1);
            }
        }
        return new BezierPatch(pointsU - 1, pointsV - 1, net);
    }

    private static void checkPoints(String direction, int points) {
        int max = BezierPatch.MAX_DEGREE + 1;
        if (points < 2 || points > max) {
            throw new IllegalArgumentException("control points along " + direction + " must be 2.." + max
                    + ", got " + points);
        }
    }

    /** The Utah teapot (32 bicubic patches), read from {@value #TEAPOT_RESOURCE}. */
    public static Scene teapot() {
        return TeapotHolder.TEAPOT;
    }

    private static final class TeapotHolder {
        static final Scene TEAPOT = loadTeapot();

        private static Scene loadTeapot() {
            try (InputStream in = Models.class.getResourceAsStream(TEAPOT_RESOURCE)) {
                if (in == null) {
                    throw new IllegalStateException("built-in model resource " + TEAPOT_RESOURCE + " is missing");
                }
                return new Scene(BptReader.read(new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8)),
                        "teapot.bpt"));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    /** The built-in model called {@code name} (case-insensitive), or null when there is none. */
    public static Scene builtIn(String name) {
        return switch (name.toLowerCase(Locale.ROOT)) {
            case "patch" -> patch();
            case "teapot" -> teapot();
            default -> GeneratedModels.builtIn(name.toLowerCase(Locale.ROOT));
        };
    }

    /**
     * Resolves a built-in name or a {@code .bpt}/{@code .obj} path.
     *
     * @throws ModelFormatException for an unknown extension, a missing or unreadable file or a
     *                              parse error; the message is one line naming the file
     */
    public static Scene load(String nameOrPath) {
        Scene builtIn = builtIn(nameOrPath);
        if (builtIn != null) {
            return builtIn;
        }
        Format format = Format.of(nameOrPath);
        Path file = Path.of(nameOrPath);
        if (!Files.isRegularFile(file)) {
            throw new ModelFormatException(nameOrPath, Files.isDirectory(file) ? "is a directory, not a model file"
                    : "no such file (and not a built-in model: " + String.join(", ", NAMES) + ")");
        }
        try (BufferedReader in = Files.newBufferedReader(file, StandardCharsets.UTF_8)) {
            return new Scene(format == Format.BPT ? BptReader.read(in, nameOrPath) : ObjReader.read(in, nameOrPath));
        } catch (IOException e) {
            throw new ModelFormatException(nameOrPath, "cannot read: " + e.getClass().getSimpleName() + " "
                    + e.getMessage());
        }
    }

    /** Saves patches atomically, choosing BPT or free-form OBJ by the extension of {@code file}. */
    public static void save(Path file, List<BezierPatch> patches) throws IOException {
        if (Format.of(file.toString()) == Format.BPT) {
            BptWriter.write(file, patches);
        } else {
            ObjWriter.write(file, patches);
        }
    }

    /** Model file formats, chosen by extension. */
    enum Format {
        BPT, OBJ;

        static Format of(String path) {
            String lower = path.toLowerCase(Locale.ROOT);
            if (lower.endsWith(".bpt")) {
                return BPT;
            }
            if (lower.endsWith(".obj")) {
                return OBJ;
            }
            throw new ModelFormatException(path, "unknown model format: expected a .bpt or .obj file or a built-in"
                    + " model (" + String.join(", ", NAMES) + ")");
        }
    }
}
