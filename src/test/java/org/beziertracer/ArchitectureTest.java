package org.beziertracer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Reads every main source file (comments stripped) and checks the layer rule of the
 * architecture guide: each layer uses only the layers its table row allows — by import or by a
 * fully qualified name — {@code ui} and {@code cli} never use each other, {@code app} (the app
 * without its windows) uses neither, only {@code ui} uses Swing or FlatLaf, and only {@code ui} and
 * {@code cli} use AWT or ImageIO (so {@code app} is tested without a display) — but {@code model.io}
 * may decode pictures with ImageIO and {@code java.awt.image} rasters (texture files), which need
 * no display.
 */
class ArchitectureTest {

    private static final Path SRC = Path.of("src/main/java");
    private static final String BASE = "org.beziertracer";
    private static final Pattern PACKAGE = Pattern.compile("^package\\s+([\\w.]+)\\s*;", Pattern.MULTILINE);

    /** What each layer may use, from the architecture guide's table ("" is the root package). */
    private static final Map<String, Set<String>> ALLOWED = Map.ofEntries(
            Map.entry("math", Set.of()),
            Map.entry("model", Set.of("math")),
            Map.entry("model.io", Set.of("model", "math")),
            Map.entry("geometry", Set.of("math", "model")),
            Map.entry("accel", Set.of("math")),
            Map.entry("intersect", Set.of("math", "model", "geometry", "accel")),
            Map.entry("render", Set.of("math", "model", "model.io", "geometry", "accel", "intersect")),
            Map.entry("app", Set.of("math", "model", "model.io", "geometry", "accel", "intersect", "render")),
            Map.entry("ui", Set.of("math", "model", "model.io", "geometry", "accel", "intersect", "render", "app")),
            Map.entry("cli", Set.of("math", "model", "model.io", "geometry", "accel", "intersect", "render", "app")),
            Map.entry("", Set.of("math", "model", "model.io", "geometry", "accel", "intersect", "render", "app", "ui",
                    "cli")));

    /** A fully qualified use of one of our classes anywhere in the code, imported or not. */
    private static final Pattern QUALIFIED = Pattern.compile("\\b(org\\.beziertracer(?:\\.[a-z]\\w*)*)\\.[A-Z]");
    private static final Pattern AWT = Pattern.compile("\\b(java\\.awt|javax\\.imageio)\\b");
    /** What {@code model.io} may use of AWT: ImageIO and the {@code java.awt.image} rasters, no display. */
    private static final Pattern DECODING = Pattern.compile("\\b(javax\\.imageio|java\\.awt\\.image)\\.");
    private static final Pattern SWING = Pattern.compile("\\b(javax\\.swing|com\\.formdev)\\b");

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
        String code = source.replaceAll("(?s)/\\*.*?\\*/", "").replaceAll("//[^\\n]*", "")
                .replaceFirst("(?m)^package\\s+[\\w.]+\\s*;", "");
        if (SWING.matcher(code).find() && !"ui".equals(from)) {
            out.add(pkg + " uses Swing/FlatLaf (only ui may)");
        }
        // model.io decodes PNG and JPEG files (textures) with ImageIO's headless decoders and rasters
        String awtCode = "model.io".equals(from) ? DECODING.matcher(code).replaceAll("") : code;
        if (AWT.matcher(awtCode).find() && !"ui".equals(from) && !"cli".equals(from)) {
            out.add(pkg + " uses AWT/ImageIO (only ui and cli may)");
        }
        Set<String> allowed = ALLOWED.get(from);
        if (allowed == null) {
            out.add(pkg + " is in no known layer");
            return out;
        }
        Matcher m = QUALIFIED.matcher(code);
        while (m.find()) {
            String to = layerOf(m.group(1));
            if (to != null && !to.equals(from) && !allowed.contains(to)) {
                out.add(pkg + " (layer " + from + ") uses " + m.group(0) + "… (layer " + to + ")");
            }
        }
        return out;
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
    void theAppLayerMayUseRenderButNoWindowsAndNeitherUiNorCli() {
        assertEquals(List.of(), violations("org.beziertracer.app",
                "package org.beziertracer.app;\nimport org.beziertracer.render.RenderSession;\n"
                        + "import org.beziertracer.model.io.SceneFiles;\nimport java.util.prefs.Preferences;\n"));
        for (String banned : List.of("java.awt.Color", "java.awt.image.BufferedImage", "javax.swing.JPanel",
                "com.formdev.flatlaf.FlatLaf", "javax.imageio.ImageIO", "org.beziertracer.ui.AppFrame",
                "org.beziertracer.cli.RenderCommand")) {
            assertEquals(1, violations("org.beziertracer.app",
                    "package org.beziertracer.app;\nimport " + banned + ";\n").size(), banned);
            assertEquals(1, violations("org.beziertracer.app",
                    "package org.beziertracer.app;\nclass X { Object o = " + banned + ".class; }\n").size(),
                    banned + " by its qualified name");
        }
        // the layers above may use it; the layers below may not
        assertEquals(List.of(), violations("org.beziertracer.ui",
                "package org.beziertracer.ui;\nimport org.beziertracer.app.AppModel;\n"));
        assertEquals(1, violations("org.beziertracer.render",
                "package org.beziertracer.render;\nimport org.beziertracer.app.Picture;\n").size());
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
                "package org.beziertracer.intersect;\nimport org.beziertracer.accel.Bvh;\nimport org.beziertracer.geometry.DeCasteljau;\n"));
        // the guide's table, not just an order: accel uses math only, intersect no file formats
        assertEquals(1, violations("org.beziertracer.accel",
                "package org.beziertracer.accel;\nimport org.beziertracer.geometry.SubPatchTable;\n").size());
        assertEquals(1, violations("org.beziertracer.intersect",
                "package org.beziertracer.intersect;\nimport org.beziertracer.model.io.BptReader;\n").size());
        // fully qualified names count, not only imports
        assertEquals(1, violations("org.beziertracer.geometry",
                "package org.beziertracer.geometry;\nclass X { org.beziertracer.render.Camera c; }\n").size());
        assertEquals(1, violations("org.beziertracer.render",
                "package org.beziertracer.render;\nclass X { java.awt.image.BufferedImage i; }\n").size());
    }

    @Test
    void modelIoMayDecodePicturesButUseNoOtherAwt() {
        assertEquals(List.of(), violations("org.beziertracer.model.io", "package org.beziertracer.model.io;\n"
                + "import javax.imageio.ImageIO;\nimport java.awt.image.BufferedImage;\n"));
        for (String banned : List.of("java.awt.Color", "java.awt.Toolkit", "javax.swing.JPanel")) {
            assertEquals(1, violations("org.beziertracer.model.io",
                    "package org.beziertracer.model.io;\nimport " + banned + ";\n").size(), banned);
        }
        assertEquals(1, violations("org.beziertracer.model",
                "package org.beziertracer.model;\nimport javax.imageio.ImageIO;\n").size(), "model itself may not");
    }
}
