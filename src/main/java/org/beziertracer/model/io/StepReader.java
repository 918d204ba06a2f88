package org.beziertracer.model.io;

import java.io.IOException;
import java.io.InterruptedIOException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Material;
import org.beziertracer.model.Scene;

/**
 * Reads the faces of a STEP file (ISO 10303-21 clear text; AP203, AP214, AP242 geometry) as
 * trimmed rational B-spline surfaces ({@link StepFaces}), in millimetres, placed by the file's
 * assembly structure: the shape representations' items lead to their faces (through solids,
 * shells and face sets); a {@code REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION} (the
 * {@code CONTEXT_DEPENDENT_SHAPE_REPRESENTATION} of an assembly) places {@code rep_1} in
 * {@code rep_2} by its {@code ITEM_DEFINED_TRANSFORMATION}, mapping {@code transform_item_1}
 * onto {@code transform_item_2}; a {@code MAPPED_ITEM} places its representation map's
 * representation by mapping its origin onto its target; a relationship without a transformation
 * makes two representations share one frame. A face drawn in no representation is drawn once in
 * the file's frame; a face reached twice in the same place is drawn once. Length and plane angle
 * units come from the first {@code GLOBAL_UNIT_ASSIGNED_CONTEXT} ({@code SI_UNIT} with its
 * prefix, or a {@code CONVERSION_BASED_UNIT} such as the inch). Faces it cannot make exact are
 * counted in {@link IgesReader.Model#skipped()} with the reason, never a failure of the whole file.
 *
 * <pre>
 * IgesReader.Model m = StepReader.readModel(TextSource.of(text, "part.stp"));
 * m.surfaces() → the FreeFormSurfaces, a face per placement
 * m.summary()  → "skipped 2 entities: 2 × face trimmed by model-space curves only (no PCURVE on its surface)"
 * </pre>
 *
 * <p>References: ISO 10303-21 (the file), ISO 10303-42 (geometry and topology), ISO 10303-43
 * (representation structures), CAx-IF <i>Recommended Practices for AP203/AP214</i> (assemblies).
 */
public final class StepReader {
    private StepReader() {}

    /** Nesting depth of assemblies beyond which the structure is taken for a cycle. */
    static final int MAX_DEPTH = 32;

    /** Most representations placed in all (a part placed n times counts n), so no structure fans out for ever. */
    static final int MAX_PLACEMENTS = 1_000_000;

    static Scene readScene(TextSource text, List<String> notes) throws IOException {
        return IgesReader.toScene(readModel(text), text, notes);
    }

    /**
     * Reads STEP text.
     *
     * @throws ModelFormatException one line naming the file, the line and the entity, for a
     *                              corrupt file or a file without a face to draw
     */
    public static IgesReader.Model readModel(TextSource text) throws IOException {
        return new Walk(StepFile.read(text)).run();
    }

    /** Entities that hold faces: solids, shells, face sets. */
    static final Set<String> CONTAINERS = Set.of("MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS",
            "SHELL_BASED_SURFACE_MODEL", "FACE_BASED_SURFACE_MODEL", "CLOSED_SHELL", "OPEN_SHELL",
            "ORIENTED_CLOSED_SHELL", "ORIENTED_OPEN_SHELL", "CONNECTED_FACE_SET");

    /** A placed child of a representation: the child's class and the map from its frame into the parent's. */
    private record Child(int rep, IgesMatrix m) { }

    private static final class Walk {
        private final StepFile file;
        private final StepGeometry g;
        private final StepFaces faces;
        private final IgesMatrix units;
        private final Map<Integer, Integer> sameFrame = new HashMap<>();
        private final Map<Integer, List<Child>> children = new HashMap<>();
        private final Map<Integer, List<Child>> childrenOfFrame = new HashMap<>();
        private final Set<Integer> placedAsChild = new HashSet<>();
        private int placements;
        private final Map<Integer, Set<Integer>> facesOf = new HashMap<>();
        private final Set<Integer> drawn = new HashSet<>();
        private final Map<Integer, List<IgesMatrix>> placedWith = new HashMap<>();
        /** Containers (shells, solids, face sets) whose faces are already collected for the representation at hand. */
        private final Set<Integer> opened = new HashSet<>();
        private final Map<Integer, Object> converted = new HashMap<>();
        private final List<FreeFormSurface> surfaces = new ArrayList<>();
        private final List<Integer> surfaceMaterial = new ArrayList<>();
        private final Map<Integer, double[]> colours;
        private final List<Material> materials = new ArrayList<>(List.of(Material.DEFAULT));
        private final Map<String, Integer> materialOf = new HashMap<>();
        private final Map<String, Integer> skipped = new TreeMap<>();
        private long pieces;
        private int faceCount;

        Walk(StepFile file) {
            this.file = file;
            this.g = new StepGeometry(file);
            StepUnits u = StepUnits.of(file);
            this.units = u.millimetres() == 1 ? IgesMatrix.IDENTITY : IgesMatrix.scaleMove(u.millimetres(), 0, 0, 0);
            this.faces = new StepFaces(g, u.radians());
            this.colours = StepColours.of(file);
        }

        /** The material of face {@code id}: its colour's (one per distinct colour), else the default. */
        private int material(int id) {
            double[] rgb = colours.get(id);
            if (rgb == null) {
                return 0;
            }
            return materialOf.computeIfAbsent(java.util.Arrays.toString(rgb), k -> {
                materials.add(Material.diffuse(rgb[0], rgb[1], rgb[2]));
                return materials.size() - 1;
            });
        }

        IgesReader.Model run() throws InterruptedIOException {
            structure();
            for (Map.Entry<Integer, List<Child>> e : children.entrySet()) {
                childrenOfFrame.computeIfAbsent(frame(e.getKey()), k -> new ArrayList<>()).addAll(e.getValue());
                for (Child c : e.getValue()) {
                    placedAsChild.add(frame(c.rep()));
                }
            }
            Set<Integer> roots = new LinkedHashSet<>();
            for (int rep : facesOf.keySet()) {
                roots.add(frame(rep));
            }
            for (int rep : children.keySet()) {
                roots.add(frame(rep));
            }
            for (int root : roots) {
                if (!placedAsChild.contains(root)) {
                    place(root, units, 0);
                }
            }
            for (StepFile.Entity e : file.order) {
                if ((e.is("ADVANCED_FACE") || e.is("FACE_SURFACE")) && !drawn.contains(e.id())) {
                    draw(e.id(), units);
                }
            }
            if (surfaces.isEmpty()) {
                IgesReader.Model none = new IgesReader.Model(surfaces, surfaceMaterial, List.of(Material.DEFAULT), skipped);
                String what = skipped.isEmpty() ? "no faces" : none.summary();
                throw file.source.error(0, "no surface to draw (STEP ADVANCED_FACE): " + what);
            }
            return new IgesReader.Model(List.copyOf(surfaces), List.copyOf(surfaceMaterial), List.copyOf(materials),
                    skipped);
        }

        /** The representative of {@code rep}'s frame (representations joined without a transformation share one). */
        private int frame(int rep) {
            int r = rep;
            for (int k = 0; k < 10_000 && sameFrame.containsKey(r) && sameFrame.get(r) != r; k++) {
                r = sameFrame.get(r);
            }
            return r;
        }

        /** The representations, their faces, and how they are placed in one another. */
        private void structure() {
            for (StepFile.Entity e : file.order) {
                StepFile.Part rel = e.part("REPRESENTATION_RELATIONSHIP");
                if (rel != null || e.is("SHAPE_REPRESENTATION_RELATIONSHIP") && !e.complex()) {
                    relationship(e);
                }
            }
            for (StepFile.Entity e : file.order) {
                StepFile.Part rep = representation(e);
                if (rep != null && rep.params().size() >= 2 && rep.params().get(1) instanceof List<?> items) {
                    StepArgs a = new StepArgs(file, e, rep);
                    int frame = frame(e.id());
                    opened.clear();
                    for (Object o : items) {
                        StepFile.Entity item = a.target(o, "an item");
                        if (item.is("MAPPED_ITEM")) {
                            mapped(item, frame);
                        } else {
                            collectFaces(item, facesOf.computeIfAbsent(frame, k -> new LinkedHashSet<>()), 0);
                        }
                    }
                }
            }
        }

        private static StepFile.Part representation(StepFile.Entity e) {
            if (e.complex()) {
                return e.part("REPRESENTATION");
            }
            String t = e.type();
            return (t.endsWith("_REPRESENTATION") || t.equals("REPRESENTATION")) && !t.equals("DEFINITIONAL_REPRESENTATION")
                    ? e.parts().get(0) : null;
        }

        private void relationship(StepFile.Entity e) {
            StepFile.Part rel = e.part("REPRESENTATION_RELATIONSHIP");
            StepArgs a = new StepArgs(file, e, rel != null ? rel : e.parts().get(0)).require(4, "name, description, rep_1, rep_2");
            int rep1 = a.ref(2, "rep_1").id(), rep2 = a.ref(3, "rep_2").id();
            StepFile.Part t = e.part("REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION");
            if (t == null) {
                int f1 = frame(rep1), f2 = frame(rep2);
                if (f1 != f2) {
                    sameFrame.put(f2, f1);
                }
                return;
            }
            StepArgs ta = new StepArgs(file, e, t).require(1, "transformation_operator");
            StepFile.Entity idt = ta.ref(0, "transformation_operator", "ITEM_DEFINED_TRANSFORMATION");
            StepArgs ia = g.args(idt, "ITEM_DEFINED_TRANSFORMATION").require(4, "name, description, transform_item_1, transform_item_2");
            IgesMatrix m = onto(ia.ref(2, "transform_item_1", "AXIS2_PLACEMENT_3D"),
                    ia.ref(3, "transform_item_2", "AXIS2_PLACEMENT_3D"));
            children.computeIfAbsent(rep2, k -> new ArrayList<>()).add(new Child(rep1, m));
        }

        private void mapped(StepFile.Entity item, int parentFrame) {
            StepArgs a = g.args(item, "MAPPED_ITEM").require(3, "name, mapping_source, mapping_target");
            StepFile.Entity map = a.ref(1, "mapping_source", "REPRESENTATION_MAP");
            StepArgs ma = g.args(map, "REPRESENTATION_MAP").require(2, "mapping_origin, mapped_representation");
            StepFile.Entity target = a.ref(2, "mapping_target");
            if (!target.is("AXIS2_PLACEMENT_3D")) {
                skip("mapped item placed by a " + StepGeometry.kind(target));
                return;
            }
            IgesMatrix m = onto(ma.ref(0, "mapping_origin", "AXIS2_PLACEMENT_3D"), target);
            children.computeIfAbsent(parentFrame, k -> new ArrayList<>()).add(new Child(ma.ref(1, "mapped_representation").id(), m));
        }

        /** The map taking placement {@code from} onto placement {@code to}: {@code A(to) · A(from)⁻¹}. */
        private IgesMatrix onto(StepFile.Entity from, StepFile.Entity to) {
            double[] f = g.placement(from);
            IgesMatrix a = StepGeometry.frameMatrix(f);
            double ox = f[0], oy = f[1], oz = f[2];
            // the inverse of an orthonormal frame: the transposed rotation, then −Rᵀ·o
            IgesMatrix inverse = new IgesMatrix(new double[] {f[3], f[4], f[5], -(f[3] * ox + f[4] * oy + f[5] * oz),
                    f[6], f[7], f[8], -(f[6] * ox + f[7] * oy + f[8] * oz),
                    f[9], f[10], f[11], -(f[9] * ox + f[10] * oy + f[11] * oz)});
            return StepGeometry.frameMatrix(g.placement(to)).after(a.identity() ? IgesMatrix.IDENTITY : inverse);
        }

        /** The faces an item holds (through solids, shells and face sets). */
        private void collectFaces(StepFile.Entity item, Set<Integer> out, int depth) {
            if (item.is("ADVANCED_FACE") || item.is("FACE_SURFACE")) {
                out.add(item.id());
                return;
            }
            if (item.complex() || !CONTAINERS.contains(item.type()) || depth > MAX_DEPTH || !opened.add(item.id())) {
                return; // not a container, or one already opened (shared, or in a cycle)
            }
            collectRefs(item, item.parts().get(0).params(), out, depth);
        }

        private void collectRefs(StepFile.Entity item, List<?> params, Set<Integer> out, int depth) {
            for (Object o : params) {
                if (o instanceof StepFile.Ref r) {
                    collectFaces(file.resolve(r, item), out, depth + 1);
                } else if (o instanceof List<?> l) {
                    collectRefs(item, l, out, depth);
                }
            }
        }

        private void place(int frame, IgesMatrix m, int depth) throws InterruptedIOException {
            if (depth > MAX_DEPTH) {
                throw file.source.error(0, "assemblies nested more than " + MAX_DEPTH + " deep (a cycle through #"
                        + frame + "?)");
            }
            if (++placements > MAX_PLACEMENTS) {
                throw file.source.error(0, "the assemblies place more than " + MAX_PLACEMENTS + " representations");
            }
            for (int face : facesOf.getOrDefault(frame, Set.of())) {
                draw(face, m);
            }
            for (Child c : childrenOfFrame.getOrDefault(frame, List.of())) {
                place(frame(c.rep()), m.after(c.m()), depth + 1);
            }
        }

        private void skip(String what) {
            skipped.merge(what, 1, Integer::sum);
        }

        private void draw(int id, IgesMatrix m) throws InterruptedIOException {
            drawn.add(id);
            List<IgesMatrix> before = placedWith.computeIfAbsent(id, k -> new ArrayList<>(1));
            for (IgesMatrix b : before) {
                if (java.util.Arrays.equals(b.m(), m.m())) {
                    return; // the same face in the same place, reached through two representations
                }
            }
            before.add(m);
            if ((++faceCount & 255) == 0 && Thread.currentThread().isInterrupted()) {
                throw new InterruptedIOException("the read was cancelled");
            }
            StepFile.Entity e = file.entities.get(id);
            Object known = converted.get(id);
            if (known == null) {
                try {
                    known = faces.face(e);
                } catch (IgesEntities.Skip s) {
                    known = s.getMessage();
                } catch (ModelFormatException bad) {
                    throw bad;
                } catch (IllegalArgumentException bad) {
                    throw file.source.error(e.line(), "#" + id + " (" + e.type() + "): " + bad.getMessage());
                }
                converted.put(id, known);
            }
            if (known instanceof String reason) {
                skip("face " + reason);
                return;
            }
            IgesSurface.Trimmed t = (IgesSurface.Trimmed) known;
            FreeFormSurface f;
            try {
                f = t.surface().toFreeForm(t.trim(), m);
            } catch (IllegalArgumentException bad) {
                throw file.source.error(e.line(), "#" + id + " (" + e.type() + "): " + bad.getMessage());
            }
            pieces += f.pieceCount();
            int cap = file.source.limits().patches();
            if (pieces > cap) {
                throw file.source.error(e.line(), "#" + id + " (" + e.type() + "): a model may have at most " + cap
                        + " patches; this face makes " + f.pieceCount() + " more after " + (pieces - f.pieceCount()));
            }
            surfaces.add(f);
            surfaceMaterial.add(material(id));
        }
    }
}
