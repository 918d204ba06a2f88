package org.beziertracer.model.io;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Face colours of a STEP file: every {@code STYLED_ITEM} (and {@code OVER_RIDING_STYLED_ITEM})
 * whose item is a face, or a shell, solid or face set holding faces, and whose styles lead through
 * {@code PRESENTATION_STYLE_ASSIGNMENT} → {@code SURFACE_STYLE_USAGE} → {@code SURFACE_SIDE_STYLE}
 * → {@code SURFACE_STYLE_FILL_AREA} → {@code FILL_AREA_STYLE} → {@code FILL_AREA_STYLE_COLOUR}
 * (or {@code SURFACE_STYLE_RENDERING}'s surface colour) to a {@code COLOUR_RGB} or a
 * {@code DRAUGHTING_PRE_DEFINED_COLOUR}. Curve and point styles are not followed. A colour on the
 * face itself wins over one on its shell or solid; an over-riding styled item over a plain one.
 * A malformed style is ignored (the face keeps the default colour), never a failure of the file.
 *
 * <p>References: ISO 10303-46 (presentation: styled items, surface styles); CAx-IF
 * <i>Recommended Practices for Model Styling and Organization</i> (§4, colour on faces and
 * bodies).
 */
final class StepColours {
    private StepColours() {}

    /** The style entities followed from a styled item towards its colour. */
    private static final Set<String> SURFACE_STYLES = Set.of("PRESENTATION_STYLE_ASSIGNMENT",
            "PRESENTATION_STYLE_BY_CONTEXT", "SURFACE_STYLE_USAGE", "SURFACE_SIDE_STYLE", "SURFACE_STYLE_FILL_AREA",
            "FILL_AREA_STYLE", "FILL_AREA_STYLE_COLOUR", "SURFACE_STYLE_RENDERING",
            "SURFACE_STYLE_RENDERING_WITH_PROPERTIES");

    /** The draughting pre-defined colours (ISO 10303-46 §4.4.x; CAx-IF) by name. */
    private static final Map<String, double[]> PREDEFINED = Map.of("black", new double[] {0, 0, 0},
            "red", new double[] {1, 0, 0}, "green", new double[] {0, 1, 0}, "blue", new double[] {0, 0, 1},
            "yellow", new double[] {1, 1, 0}, "magenta", new double[] {1, 0, 1}, "cyan", new double[] {0, 1, 1},
            "white", new double[] {1, 1, 1});

    /** Each coloured face's id → its {@code r, g, b} in [0, 1]. */
    static Map<Integer, double[]> of(StepFile file) {
        Map<Integer, double[]> onFace = new HashMap<>(), onBody = new HashMap<>();
        List<StepFile.Entity> plain = new java.util.ArrayList<>(), overriding = new java.util.ArrayList<>();
        for (StepFile.Entity e : file.order) {
            if (e.is("OVER_RIDING_STYLED_ITEM")) {
                overriding.add(e);
            } else if (e.is("STYLED_ITEM")) {
                plain.add(e);
            }
        }
        for (List<StepFile.Entity> items : List.of(plain, overriding)) { // plain styled items, then the over-riding ones
            for (StepFile.Entity e : items) {
                List<Object> p = e.parts().get(0).params();
                if (p.size() < 3 || !(p.get(1) instanceof List<?> styles) || !(p.get(2) instanceof StepFile.Ref item)) {
                    continue;
                }
                double[] rgb = null;
                for (Object s : styles) {
                    rgb = rgb != null ? rgb : colour(file, s, 0);
                }
                StepFile.Entity target = file.entities.get(item.id());
                if (rgb == null || target == null) {
                    continue;
                }
                if (target.is("ADVANCED_FACE") || target.is("FACE_SURFACE")) {
                    onFace.put(target.id(), rgb);
                } else {
                    faces(file, target, rgb, onBody, 0, new java.util.HashSet<>());
                }
            }
        }
        onBody.putAll(onFace);
        return onBody;
    }

    /** The first colour a style value leads to, or null. */
    private static double[] colour(StepFile file, Object value, int depth) {
        if (depth > 48) { // lists and references count: a chain of 8 styles is about 24 deep
            return null;
        }
        if (value instanceof List<?> list) {
            for (Object o : list) {
                double[] c = colour(file, o, depth + 1);
                if (c != null) {
                    return c;
                }
            }
            return null;
        }
        if (!(value instanceof StepFile.Ref r)) {
            return null;
        }
        StepFile.Entity e = file.entities.get(r.id());
        if (e == null) {
            return null;
        }
        if (e.is("COLOUR_RGB")) {
            List<Object> p = e.part("COLOUR_RGB").params();
            if (p.size() == 4 && p.get(1) instanceof Number red && p.get(2) instanceof Number green
                    && p.get(3) instanceof Number blue) {
                double[] rgb = {red.doubleValue(), green.doubleValue(), blue.doubleValue()};
                for (double x : rgb) {
                    if (!(x >= 0 && x <= 1)) {
                        return null; // outside [0, 1]: not a colour
                    }
                }
                return rgb;
            }
            return null;
        }
        if (e.is("DRAUGHTING_PRE_DEFINED_COLOUR")) {
            List<Object> p = e.part("DRAUGHTING_PRE_DEFINED_COLOUR").params();
            return p.size() == 1 && p.get(0) instanceof String name ? PREDEFINED.get(name) : null;
        }
        if (e.complex() || !SURFACE_STYLES.contains(e.type())) {
            return null;
        }
        return colour(file, e.parts().get(0).params(), depth + 1);
    }

    /** Every face under a shell, solid or face set gets {@code rgb}. */
    private static void faces(StepFile file, StepFile.Entity e, double[] rgb, Map<Integer, double[]> out, int depth,
                              Set<Integer> seen) {
        if (e.is("ADVANCED_FACE") || e.is("FACE_SURFACE")) {
            out.put(e.id(), rgb);
            return;
        }
        if (depth > 16 || e.complex() || !StepReader.CONTAINERS.contains(e.type()) || !seen.add(e.id())) {
            return;
        }
        refs(file, e.parts().get(0).params(), rgb, out, depth, seen);
    }

    private static void refs(StepFile file, List<?> params, double[] rgb, Map<Integer, double[]> out, int depth,
                             Set<Integer> seen) {
        for (Object o : params) {
            if (o instanceof StepFile.Ref r && file.entities.get(r.id()) != null) {
                faces(file, file.entities.get(r.id()), rgb, out, depth + 1, seen);
            } else if (o instanceof List<?> l) {
                refs(file, l, rgb, out, depth, seen);
            }
        }
    }
}
