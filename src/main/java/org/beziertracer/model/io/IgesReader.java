package org.beziertracer.model.io;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Material;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimRegion;

/**
 * Reads the surfaces of an IGES 5.3 file (fixed ASCII form): every independent, shown surface
 * entity — 128, 144 and 143 (trimmed through their parameter-space curves), 120, 122, 108 — and
 * the surfaces of 408 subfigure instances of 308 definitions, each mapped by its 124 matrices and
 * the global section's model scale into millimetres, coloured by its colour number or 314
 * colour entity. What it does not draw (curves, points, annotations, solids' topology, faces it
 * cannot make exact) is counted in {@link Model#skipped()}, never a failure of the whole file.
 *
 * <pre>
 * IgesReader.Model m = IgesReader.readModel(TextSource.of(text, "part.igs"));
 * m.surfaces()  → the FreeFormSurfaces, in file order
 * m.summary()   → "skipped 3 entities: 2 × 116 (point), 1 face trimmed by model-space curves only"
 * </pre>
 *
 * <p>Reference: <i>Initial Graphics Exchange Specification 5.3</i> (US PRO, 1996).
 */
public final class IgesReader {
    private IgesReader() {}

    /** What a file gives: its surfaces, each surface's colour (index into {@code materials}), and what was left out. */
    public record Model(List<FreeFormSurface> surfaces, List<Integer> surfaceMaterial, List<Material> materials,
                        Map<String, Integer> skipped) {

        /** One line for {@code info} and the app: {@code "skipped 5 entities: 3 × 116 (point), …"}; empty when none. */
        public String summary() {
            int total = skipped.values().stream().mapToInt(Integer::intValue).sum();
            if (total == 0) {
                return "";
            }
            StringBuilder sb = new StringBuilder("skipped " + total + (total == 1 ? " entity: " : " entities: "));
            String sep = "";
            for (Map.Entry<String, Integer> e : skipped.entrySet()) {
                sb.append(sep).append(e.getValue()).append(" × ").append(e.getKey());
                sep = ", ";
            }
            return sb.toString();
        }
    }

    /** Predefined colours 1..8 (§2.2.4.4.13): black, red, green, blue, yellow, magenta, cyan, white. */
    private static final double[][] PREDEFINED = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1},
            {0, 1, 1}, {1, 1, 1}};

    private static final Map<Integer, String> NAMES = Map.ofEntries(Map.entry(100, "arc"), Map.entry(102, "composite curve"),
            Map.entry(104, "conic"), Map.entry(106, "copious data"), Map.entry(110, "line"), Map.entry(112, "parametric spline curve"),
            Map.entry(114, "parametric spline surface"), Map.entry(116, "point"), Map.entry(126, "B-spline curve"),
            Map.entry(186, "solid"), Map.entry(190, "plane surface"), Map.entry(192, "cylinder"), Map.entry(196, "sphere"),
            Map.entry(198, "torus"), Map.entry(202, "angular dimension"), Map.entry(206, "diameter dimension"),
            Map.entry(212, "note"), Map.entry(214, "leader"), Map.entry(216, "linear dimension"), Map.entry(402, "associativity"),
            Map.entry(406, "property"), Map.entry(410, "view"), Map.entry(502, "vertex list"), Map.entry(504, "edge list"),
            Map.entry(508, "loop"), Map.entry(510, "face"), Map.entry(514, "shell"));

    /** The surfaces of {@code text} as a scene (the reader {@link FileFormats#IGES} declares); the summary as a note. */
    static Scene readScene(TextSource text, List<String> notes) throws IOException {
        return toScene(readModel(text), text, notes);
    }

    /** The scene of surfaces {@code m} read from {@code text} (IGES or STEP), its skip summary added to {@code notes}. */
    static Scene toScene(Model m, TextSource text, List<String> notes) {
        if (!m.summary().isEmpty()) {
            notes.add(text.fileName() + ": " + m.summary());
        }
        Scene.Builder b = Scene.builder();
        for (Material mat : m.materials()) {
            b.addMaterial(mat);
        }
        for (int k = 0; k < m.surfaces().size(); k++) {
            b.addPatches(m.surfaces().get(k).toPatches(), m.surfaceMaterial().get(k));
        }
        return b.build();
    }

    /**
     * Reads IGES text.
     *
     * @throws ModelFormatException one line naming the file and the line, for a corrupt file or
     *                              a file without a surface to draw
     */
    public static Model readModel(TextSource text) throws IOException {
        IgesSections file = IgesSections.read(text);
        return new Walk(file).run();
    }

    /** One pass over the directory: the entities drawn, with their matrices and colours. */
    private static final class Walk {
        private final IgesSections file;
        private final IgesEntities entities;
        private final IgesMatrix units;
        private final List<FreeFormSurface> surfaces = new ArrayList<>();
        private final List<Integer> surfaceMaterial = new ArrayList<>();
        private final List<Material> materials = new ArrayList<>();
        private final Map<String, Integer> materialOf = new HashMap<>();
        private final Map<String, Integer> skipped = new TreeMap<>();
        private long pieces;

        Walk(IgesSections file) {
            this.file = file;
            this.entities = new IgesEntities(file);
            double s = file.unitMillimetres / file.scale;
            this.units = s == 1 ? IgesMatrix.IDENTITY : IgesMatrix.scaleMove(s, 0, 0, 0);
            materials.add(Material.DEFAULT);
        }

        Model run() {
            for (IgesSections.Entry e : file.order) {
                if (e.subordinate() != 0 || e.type() == 0) {
                    continue; // drawn through its parent, or a null entity
                }
                if (e.blanked()) {
                    skip("blanked (hidden) entity");
                    continue;
                }
                draw(e, units, 0);
            }
            if (surfaces.isEmpty()) {
                String what = skipped.isEmpty() ? "no entities" : new Model(surfaces, surfaceMaterial, materials, skipped).summary();
                throw file.source.error(0, "no surface to draw (IGES entities 108, 120, 122, 128, 143, 144 or 408): " + what);
            }
            return new Model(List.copyOf(surfaces), List.copyOf(surfaceMaterial), List.copyOf(materials), skipped);
        }

        private void skip(String what) {
            skipped.merge(what, 1, Integer::sum);
        }

        private void draw(IgesSections.Entry e, IgesMatrix outer, int depth) {
            switch (e.type()) {
                case 128, 120, 122, 144, 143, 108 -> {
                    try {
                        face(e, outer);
                    } catch (IgesEntities.Skip s) {
                        skip("face " + s.getMessage());
                    }
                }
                case 408 -> instance(e, outer, depth);
                case 124, 308, 314, 406, 402 -> { } // definitions and properties, used by the others
                default -> skip(e.type() + (NAMES.containsKey(e.type()) ? " (" + NAMES.get(e.type()) + ")" : ""));
            }
        }

        private void face(IgesSections.Entry e, IgesMatrix outer) {
            IgesMatrix m = outer.after(entities.matrix(e));
            IgesParams p = file.params(e);
            IgesSections.Entry base = e;
            IgesSurface surface;
            TrimRegion trim = null;
            switch (e.type()) {
                case 144 -> {
                    base = entities.entry(p.pointer(1), p, "the surface", 128, 120, 122);
                    surface = entities.surface(base);
                    trim = entities.region144(p, surface);
                    m = m.after(entities.matrix(base));
                }
                case 143 -> {
                    base = entities.entry(p.pointer(2), p, "the surface", 128, 120, 122);
                    surface = entities.surface(base);
                    trim = entities.region143(p, surface);
                    m = m.after(entities.matrix(base));
                }
                case 108 -> {
                    IgesPlane plane = IgesPlane.of(p, e.form(), entities);
                    surface = plane.surface();
                    trim = plane.trim();
                }
                default -> surface = entities.surface(e);
            }
            FreeFormSurface f;
            try {
                f = surface.toFreeForm(trim, m);
            } catch (IllegalArgumentException bad) {
                throw p.error(bad.getMessage());
            }
            pieces += f.pieceCount();
            int cap = file.source.limits().patches();
            if (pieces > cap) {
                throw p.error("a model may have at most " + cap + " patches; this surface makes " + f.pieceCount()
                        + " more after " + (pieces - f.pieceCount()));
            }
            surfaces.add(f);
            surfaceMaterial.add(material(e.colour() != 0 || base == e ? e : base));
        }

        private int material(IgesSections.Entry e) {
            double[] rgb;
            int c = e.colour();
            if (c == 0) {
                return 0;
            } else if (c > 0) {
                if (c > 8) {
                    return 0;
                }
                rgb = PREDEFINED[c - 1];
            } else {
                IgesSections.Entry def = file.entries.get(-c);
                if (def == null || def.type() != 314) {
                    throw file.source.error(e.line(), "entity " + e.type() + " (directory line " + e.sequence()
                            + "): its colour points to directory entry " + -c + ", not a colour definition (314)");
                }
                IgesParams p = file.params(def);
                p.require(4, "CC1 CC2 CC3");
                rgb = new double[] {p.fraction(1), p.fraction(2), p.fraction(3)};
                for (double v : rgb) {
                    if (!(v >= 0 && v <= 1)) {
                        throw p.error("expected colour percentages 0..100, found " + v * 100);
                    }
                }
            }
            String key = rgb[0] + "," + rgb[1] + "," + rgb[2];
            return materialOf.computeIfAbsent(key, k -> {
                materials.add(Material.diffuse(rgb[0], rgb[1], rgb[2]));
                return materials.size() - 1;
            });
        }

        /** 408: the 308 definition's entities, scaled and moved, in the instance's own matrix. */
        private void instance(IgesSections.Entry e, IgesMatrix outer, int depth) {
            IgesParams p = file.params(e);
            p.require(5, "DE X Y Z S");
            if (depth > 8) {
                throw p.error("subfigure instances nested more than 8 deep (a cycle?)");
            }
            IgesSections.Entry def = entities.entry(p.pointer(1), p, "the subfigure definition", 308);
            double s = p.has(5) ? p.real(5) : 1;
            IgesMatrix m = outer.after(entities.matrix(e)).after(IgesMatrix.scaleMove(s, p.real(2), p.real(3), p.real(4)));
            IgesParams d = file.params(def);
            d.require(4, "DEPTH NAME N");
            int n = d.integer(3);
            if (n < 0 || n > d.size() - 4) {
                throw d.error("expected N members and as many pointers, found N = " + n);
            }
            for (int k = 0; k < n; k++) {
                IgesSections.Entry member = file.entries.get(d.pointer(4 + k));
                if (member == null) {
                    throw d.error("member " + (k + 1) + " points to directory entry " + d.pointer(4 + k)
                            + ", which does not exist");
                }
                draw(member, m, depth + 1);
            }
        }
    }
}
