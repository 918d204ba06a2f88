package org.beziertracer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Reads the {@code package} and {@code import} lines of every main source file and checks the
 * layer rule: {@code math → model (+model.io) → geometry → accel → intersect → render → ui / cli},
 * each layer importing only layers before it; {@code ui} and {@code cli} never import each
 * other; only {@code ui} imports Swing or FlatLaf.
 */
class ArchitectureTest {

    private static final Path SRC = Path.of("src/main/java");
    private static final String BASE = "org.beziertracer";
    private static final Pattern PACKAGE = Pattern.compile("^package\\s+([\\w.]+)\\s*;", Pattern.MULTILINE);
    private static final Pattern IMPORT = Pattern.compile("^import\\s+(?:static\\s+)?([\\w.]+)(?:\\.\\*)?\\s*;", Pattern.MULTILINE);

    /** Rank of each layer; a layer may import layers of strictly lower rank (and itself). */
    private static final Map<String, Integer> RANK = Map.of(
            "math", 0, "model", 1, "model.io", 2, "geometry", 3, "accel", 4,
            "intersect", 5, "render", 6, "ui", 7, "cli", 7, "", 8);

    static String layerOf(String pkg) {
        if (!pkg.startsWith(BASE)) {
            return null;
        }
        String rest = pkg.equals(BASE) ? "" : pkg.substring(BASE.length() + 1);
        if (rest.startsWith("model.io")) {
            return "model.io";
        }
        int dot = rest.indexOf('.');
        return dot < 0 ? rest : rest.substring(0, dot);
    }

    static List<String> violations(String pkg, String source) {
        List<String> out = new ArrayList<>();
        String from = layerOf(pkg);
        Matcher m = IMPORT.matcher(source);
        while (m.find()) {
            String imported = m.group(1);
            boolean swing = imported.startsWith("javax.swing") || imported.startsWith("com.formdev.flatlaf");
            if (swing && !"ui".equals(from)) {
                out.add(pkg + " imports " + imported + " (Swing/FlatLaf only in ui)");
            }
            String to = layerOf(imported.startsWith(BASE + ".") ? packageOfClass(imported) : imported);
            if (to == null || from == null || to.equals(from)) {
                continue;
            }
            Integer rf = RANK.get(from), rt = RANK.get(to);
            if (rf == null || rt == null) {
                out.add(pkg + " is in an unknown layer or imports one: " + imported);
            } else if (rt >= rf) {
                out.add(pkg + " (layer " + from + ") imports " + imported + " (layer " + to + ")");
            }
        }
        return out;
    }

    /** {@code org.beziertracer.model.io.BptReader} → {@code org.beziertracer.model.io}. */
    private static String packageOfClass(String name) {
        String[] parts = name.split("\\.");
        StringBuilder sb = new StringBuilder();
        for (String part : parts) {
            if (!part.isEmpty() && Character.isUpperCase(part.charAt(0))) {
                break;
            }
            if (sb.length() > 0) sb.append('.');
            sb.append(part);
        }
        return sb.toString();
    }

    @Test
    void everyLayerImportsOnlyLayersBelowIt() throws IOException {
        List<String> all = new ArrayList<>();
        int files = 0;
        try (Stream<Path> walk = Files.walk(SRC)) {
            for (Path p : (Iterable<Path>) walk.filter(f -> f.toString().endsWith(".java"))::iterator) {
                String src = Files.readString(p);
                Matcher pm = PACKAGE.matcher(src);
                assertTrue(pm.find(), "no package line in " + p);
                all.addAll(violations(pm.group(1), src));
                files++;
            }
        }
        assertTrue(files > 5, "expected to read the main sources, read " + files);
        assertEquals(List.of(), all, "layer violations");
    }

    @Test
    void theCheckCatchesAnUpwardImport() {
        assertEquals(1, violations("org.beziertracer.geometry",
                "package org.beziertracer.geometry;\nimport org.beziertracer.render.Camera;\n").size());
        assertEquals(1, violations("org.beziertracer.render",
                "package org.beziertracer.render;\nimport javax.swing.JPanel;\n").size());
        assertEquals(1, violations("org.beziertracer.cli",
                "package org.beziertracer.cli;\nimport org.beziertracer.ui.AppFrame;\n").size());
        assertEquals(1, violations("org.beziertracer.model.io",
                "package org.beziertracer.model.io;\nimport static org.beziertracer.geometry.DeCasteljau.evaluate;\n").size());
        assertEquals(List.of(), violations("org.beziertracer.intersect",
                "package org.beziertracer.intersect;\nimport org.beziertracer.accel.Bvh;\nimport org.beziertracer.model.io.BptReader;\n"));
    }
}
