package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.beziertracer.model.Material;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * Writes a scene's surfaces as a STEP AP214 file (ISO 10303-21 clear text, schema
 * {@code AUTOMOTIVE_DESIGN}), in millimetres: one product whose
 * {@code MANIFOLD_SURFACE_SHAPE_REPRESENTATION} holds a {@code SHELL_BASED_SURFACE_MODEL} of
 * one {@code OPEN_SHELL}, a face per surface (the surfaces {@link IgesWriter#eachSurface}
 * chooses). Each face is an {@code ADVANCED_FACE} on a {@code B_SPLINE_SURFACE_WITH_KNOTS} (the
 * complex instance with {@code RATIONAL_B_SPLINE_SURFACE} when it has weights), bounded by
 * {@code EDGE_LOOP}s whose edges are {@code EDGE_CURVE}s on a {@code SURFACE_CURVE}: its
 * {@code PCURVE} (the master representation, {@code .PCURVE_S1.}) holds the trim curve as a
 * {@code B_SPLINE_CURVE_WITH_KNOTS} in (u, v), inside a {@code TRIMMED_CURVE} by parameter
 * values when only part of it is used; its 3-D curve is the trim's exact image on the surface in
 * the same parameter ({@link CurveOnSurface}: a B-spline of degree {@code d·(p+q)}, of degree
 * {@code p} or {@code q} along an iso-parameter line), trimmed backwards when the piece runs
 * backwards; vertices are the surface's points at the ends.
 * A surface without an outer trim loop gets its parameter range as the outer loop: four lines
 * trimmed by parameter values, which {@link StepReader} reads back as the range. A region of
 * several outer loops becomes one face per outer loop, each with every hole (a face has one
 * outer bound). Points, directions and curves are written once and referred to wherever they
 * recur (neighbouring faces share their boundary points). Reals are written by {@link Double#toString}, the shortest text that reads back
 * to the same {@code double}, so {@link StepReader} gives back the same nets, weights, knots and
 * trims to the last bit. A surface whose material is not the default has its diffuse colour
 * written as a {@code STYLED_ITEM} on each of its faces (one style per colour, channels above 1
 * clamped), gathered in a {@code MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION}.
 *
 * <p>References: ISO 10303-21 (the file), ISO 10303-42 (geometry, topology), ISO 10303-214;
 * CAx-IF <i>Recommended Practices for AP203/AP214</i> (the product structure).
 */
public final class StepWriter {

    private final List<String> entities = new ArrayList<>();
    private final List<Integer> faces = new ArrayList<>();
    private int context2d;

    private StepWriter() {}

    /** Writes the surfaces of {@code scene}; its meshes are refused (a STEP face would lose them). */
    public static void write(Writer out, Scene scene) throws IOException {
        write(out, scene, WriteProgress.NONE);
    }

    /** As {@link #write(Writer, Scene)}, telling {@code progress} the patches made into faces (before the file is written). */
    public static void write(Writer out, Scene scene, WriteProgress progress) throws IOException {
        if (!scene.meshes().isEmpty()) {
            throw new IllegalArgumentException("the STEP writer saves free-form surfaces only but the model has "
                    + scene.meshes().size() + " triangle mesh(es); save the model as .obj");
        }
        StepWriter w = new StepWriter();
        int context3d = w.contexts();
        IgesWriter.eachSurface(scene.patches(), k -> w.material = scene.materials().get(scene.patchMaterial(k)), progress, w::face);
        w.product(context3d);
        w.styles(context3d);
        w.emit(out);
    }

    /** Geometry written once and referred to wherever it recurs (points shared by neighbouring faces, the range's lines). */
    private final java.util.Map<String, Integer> shared = new java.util.HashMap<>();

    private static final List<String> SHAREABLE = List.of("CARTESIAN_POINT(", "DIRECTION(", "VECTOR(", "LINE(",
            "TRIMMED_CURVE(", "B_SPLINE_CURVE_WITH_KNOTS(", "(BOUNDED_CURVE()", "DEFINITIONAL_REPRESENTATION(");

    /**
     * Adds an entity; a geometric one (a point, direction, curve: never a surface, whose faces
     * must stay apart, nor topology) already written with the same text is referred to again.
     */
    private int add(String text) {
        boolean shareable = false;
        for (String prefix : SHAREABLE) {
            shareable |= text.startsWith(prefix);
        }
        if (shareable) {
            Integer id = shared.get(text);
            if (id != null) {
                return id;
            }
        }
        entities.add(text);
        if (shareable) {
            shared.put(text, entities.size());
        }
        return entities.size();
    }

    private static String ref(int id) {
        return "#" + id;
    }

    private static String real(double v) {
        return Double.toString(v);
    }

    private static String reals(double[] v, int from, int count) {
        StringBuilder sb = new StringBuilder("(");
        for (int k = 0; k < count; k++) {
            sb.append(k == 0 ? "" : ",").append(real(v[from + k]));
        }
        return sb.append(')').toString();
    }

    private static String refs(List<Integer> ids) {
        StringBuilder sb = new StringBuilder("(");
        for (int k = 0; k < ids.size(); k++) {
            sb.append(k == 0 ? "" : ",").append(ref(ids.get(k)));
        }
        return sb.append(')').toString();
    }

    /** The units (mm, radian, steradian) and the 3-D and 2-D representation contexts; returns the 3-D one. */
    private int contexts() {
        int mm = add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))");
        int rad = add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))");
        int sr = add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())");
        int unc = add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07)," + ref(mm)
                + ",'distance_accuracy_value','confusion accuracy')");
        int ctx = add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((" + ref(unc)
                + "))GLOBAL_UNIT_ASSIGNED_CONTEXT((" + ref(mm) + "," + ref(rad) + "," + ref(sr)
                + "))REPRESENTATION_CONTEXT('3D',''))");
        context2d = add("(GEOMETRIC_REPRESENTATION_CONTEXT(2)PARAMETRIC_REPRESENTATION_CONTEXT()"
                + "REPRESENTATION_CONTEXT('2D SPACE',''))");
        return ctx;
    }

    /** The material of the surface being written (its first patch's). */
    private Material material = Material.DEFAULT;
    private final List<Integer> styled = new ArrayList<>();
    private final java.util.Map<Material, Integer> styleOf = new java.util.HashMap<>();

    /**
     * The presentation style of a material's diffuse colour, made once a colour (CAx-IF
     * recommended practice: PRESENTATION_STYLE_ASSIGNMENT → SURFACE_STYLE_USAGE(.BOTH.) →
     * SURFACE_SIDE_STYLE → SURFACE_STYLE_FILL_AREA → FILL_AREA_STYLE → FILL_AREA_STYLE_COLOUR →
     * COLOUR_RGB).
     */
    private int style(Material m) {
        Integer known = styleOf.get(m);
        if (known != null) {
            return known;
        }
        int rgb = add("COLOUR_RGB(''," + real(Math.min(1, m.r())) + "," + real(Math.min(1, m.g())) + ","
                + real(Math.min(1, m.b())) + ")");
        int fillColour = add("FILL_AREA_STYLE_COLOUR(''," + ref(rgb) + ")");
        int fill = add("FILL_AREA_STYLE('',(" + ref(fillColour) + "))");
        int area = add("SURFACE_STYLE_FILL_AREA(" + ref(fill) + ")");
        int side = add("SURFACE_SIDE_STYLE('',(" + ref(area) + "))");
        int usage = add("SURFACE_STYLE_USAGE(.BOTH.," + ref(side) + ")");
        int psa = add("PRESENTATION_STYLE_ASSIGNMENT((" + ref(usage) + "))");
        styleOf.put(m, psa);
        return psa;
    }

    /** The styled faces gathered in one presentation representation (AP214's colour container). */
    private void styles(int context3d) {
        if (!styled.isEmpty()) {
            add("MECHANICAL_DESIGN_GEOMETRIC_PRESENTATION_REPRESENTATION(''," + refs(styled) + "," + ref(context3d) + ")");
        }
    }

    /** The product, its definition and its shape, holding the shell of every face. */
    private void product(int context3d) {
        int app = add("APPLICATION_CONTEXT('automotive design')");
        add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000," + ref(app) + ")");
        int pc = add("PRODUCT_CONTEXT(''," + ref(app) + ",'mechanical')");
        int product = add("PRODUCT('model','model',''," + "(" + ref(pc) + "))");
        add("PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(" + ref(product) + "))");
        int formation = add("PRODUCT_DEFINITION_FORMATION('',''," + ref(product) + ")");
        int pdc = add("PRODUCT_DEFINITION_CONTEXT('part definition'," + ref(app) + ",'design')");
        int pd = add("PRODUCT_DEFINITION('design',''," + ref(formation) + "," + ref(pdc) + ")");
        int pds = add("PRODUCT_DEFINITION_SHAPE(''," + "''," + ref(pd) + ")");
        int shell = add("OPEN_SHELL(''," + refs(faces) + ")");
        int model = add("SHELL_BASED_SURFACE_MODEL('',(" + ref(shell) + "))");
        int origin = add("AXIS2_PLACEMENT_3D(''," + point(0, 0, 0) + "," + direction(0, 0, 1) + ","
                + direction(1, 0, 0) + ")");
        int rep = add("MANIFOLD_SURFACE_SHAPE_REPRESENTATION('model',(" + ref(model) + "," + ref(origin) + "),"
                + ref(context3d) + ")");
        add("SHAPE_DEFINITION_REPRESENTATION(" + ref(pds) + "," + ref(rep) + ")");
    }

    private String point(double... xyz) {
        return ref(add("CARTESIAN_POINT(''," + reals(xyz, 0, xyz.length) + ")"));
    }

    private String direction(double... xyz) {
        return ref(add("DIRECTION(''," + reals(xyz, 0, xyz.length) + ")"));
    }

    /** One surface: its B-spline, then a face per outer loop (or one bounded by its range). */
    private void face(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV, double[] points,
                      double[] weights, double[] range, TrimRegion trim) {
        SplinePoint at = new SplinePoint(p, q, knotsU, knotsV, countU, countV, points, weights);
        CurveOnSurface.Patches patches = CurveOnSurface.Patches.of(at);
        int surface = surface(p, q, knotsU, knotsV, countU, countV, points, weights);
        List<Integer> holes = new ArrayList<>();
        if (trim != null) {
            for (TrimLoop loop : trim.holes()) {
                holes.add(add("FACE_BOUND(''," + ref(loop(surface, loop, at, patches)) + ",.T.)"));
            }
        }
        List<Integer> outers = new ArrayList<>();
        if (trim != null) {
            for (TrimLoop loop : trim.outer()) {
                outers.add(loop(surface, loop, at, patches));
            }
        }
        if (outers.isEmpty()) {
            outers.add(rangeLoop(surface, range, at, patches));
        }
        for (int outer : outers) {
            List<Integer> bounds = new ArrayList<>();
            bounds.add(add("FACE_OUTER_BOUND(''," + ref(outer) + ",.T.)"));
            bounds.addAll(holes);
            int face = add("ADVANCED_FACE(''," + refs(bounds) + "," + ref(surface) + ",.T.)");
            faces.add(face);
            if (!material.equals(Material.DEFAULT)) {
                styled.add(add("STYLED_ITEM('colour',(" + ref(style(material)) + ")," + ref(face) + ")"));
            }
        }
    }

    /** The B-spline surface entity: control points by u then v, the rational complex form when weighted. */
    private int surface(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV, double[] points,
                        double[] weights) {
        StringBuilder net = new StringBuilder("(");
        StringBuilder w = new StringBuilder("(");
        for (int i = 0; i < countU; i++) {
            net.append(i == 0 ? "(" : ",(");
            w.append(i == 0 ? "(" : ",(");
            for (int j = 0; j < countV; j++) {
                int k = j * countU + i;
                net.append(j == 0 ? "" : ",").append(point(points[3 * k], points[3 * k + 1], points[3 * k + 2]));
                if (weights != null) {
                    w.append(j == 0 ? "" : ",").append(real(weights[k]));
                }
            }
            net.append(')');
            w.append(')');
        }
        net.append(')');
        w.append(')');
        String[] ku = distinct(knotsU), kv = distinct(knotsV);
        if (weights == null) {
            return add("B_SPLINE_SURFACE_WITH_KNOTS(''," + p + "," + q + "," + net + ",.UNSPECIFIED.,.F.,.F.,.F.,"
                    + ku[1] + "," + kv[1] + "," + ku[0] + "," + kv[0] + ",.UNSPECIFIED.)");
        }
        return add("(BOUNDED_SURFACE()B_SPLINE_SURFACE(" + p + "," + q + "," + net + ",.UNSPECIFIED.,.F.,.F.,.F.)"
                + "B_SPLINE_SURFACE_WITH_KNOTS(" + ku[1] + "," + kv[1] + "," + ku[0] + "," + kv[0] + ",.UNSPECIFIED.)"
                + "GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE(" + w + ")REPRESENTATION_ITEM('')SURFACE())");
    }

    /** The distinct knots {@code (k0,k1,…)} and their multiplicities {@code (m0,m1,…)}. */
    private static String[] distinct(double[] knots) {
        StringBuilder k = new StringBuilder("("), m = new StringBuilder("(");
        int i = 0;
        while (i < knots.length) {
            int j = i;
            while (j < knots.length && Double.compare(knots[j], knots[i]) == 0) {
                j++;
            }
            k.append(i == 0 ? "" : ",").append(real(knots[i]));
            m.append(i == 0 ? "" : ",").append(j - i);
            i = j;
        }
        return new String[] {k.append(')').toString(), m.append(')').toString()};
    }

    /** An EDGE_LOOP of the loop's pieces, consecutive edges sharing their vertex. */
    private int loop(int surface, TrimLoop loop, SplinePoint at, CurveOnSurface.Patches patches) {
        List<TrimPiece> pieces = loop.pieces();
        List<Integer> vertices = new ArrayList<>();
        for (TrimPiece piece : pieces) {
            double[] e = TrimLoop.ends(piece);
            vertices.add(vertex(at, e[0], e[1]));
        }
        List<Integer> edges = new ArrayList<>();
        for (int k = 0; k < pieces.size(); k++) {
            int curve = pieceCurve(pieces.get(k));
            edges.add(edge(surface, curve, vertices.get(k), vertices.get((k + 1) % pieces.size()),
                    curve3d(pieces.get(k), at, patches)));
        }
        return add("EDGE_LOOP(''," + refs(edges) + ")");
    }

    private int vertex(SplinePoint at, double u, double v) {
        double[] p = at.at(u, v);
        return add("VERTEX_POINT(''," + point(p) + ")");
    }

    /**
     * The oriented edge from vertex {@code v0} to {@code v1} whose geometry is a SURFACE_CURVE:
     * the PCURVE of {@code curve2d} as the master representation, and {@code curve3d}, its exact
     * image on the surface in the same parameter (AP214's advanced face wants a surface curve on
     * its edges).
     */
    private int edge(int surface, int curve2d, int v0, int v1, int curve3d) {
        int rep = add("DEFINITIONAL_REPRESENTATION('',(" + ref(curve2d) + ")," + ref(context2d) + ")");
        int pcurve = add("PCURVE(''," + ref(surface) + "," + ref(rep) + ")");
        int sc = add("SURFACE_CURVE(''," + ref(curve3d) + ",(" + ref(pcurve) + "),.PCURVE_S1.)");
        int ec = add("EDGE_CURVE(''," + ref(v0) + "," + ref(v1) + "," + ref(sc) + ",.T.)");
        return add("ORIENTED_EDGE('',*,*," + ref(ec) + ",.T.)");
    }

    /**
     * The 3-D curve of {@code piece} on the surface: {@link CurveOnSurface#compose} over the
     * piece's parameters (a fit within {@link CurveOnSurface#FIT_TOLERANCE} when the exact degree
     * would pass {@link CurveOnSurface#MAX_DEGREE}), trimmed backwards by parameter values when
     * the piece runs backwards, so it has the pcurve's parameter and direction.
     */
    private int curve3d(TrimPiece piece, SplinePoint at, CurveOnSurface.Patches patches) {
        double lo = Math.min(piece.from(), piece.to()), hi = Math.max(piece.from(), piece.to());
        CurveOnSurface.Curve3 c = CurveOnSurface.compose(patches, piece.curve(), lo, hi);
        if (c == null) {
            c = CurveOnSurface.fit(at, piece.curve(), lo, hi);
        }
        int n = c.count();
        StringBuilder pts = new StringBuilder("(");
        double[] xyz = c.points();
        for (int k = 0; k < n; k++) {
            pts.append(k == 0 ? "" : ",").append(point(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]));
        }
        int curve = bspline(c.degree(), c.knots(), pts.append(')').toString(), c.weights());
        return piece.from() < piece.to() ? curve : trimmed(curve, piece.from(), piece.to());
    }

    /** A B_SPLINE_CURVE_WITH_KNOTS of the written points {@code pts}, the rational complex form when weighted. */
    private int bspline(int degree, double[] knots, String pts, double[] w) {
        String[] kn = distinct(knots);
        return w == null
                ? add("B_SPLINE_CURVE_WITH_KNOTS(''," + degree + "," + pts + ",.UNSPECIFIED.,.F.,.F.," + kn[1] + ","
                + kn[0] + ",.UNSPECIFIED.)")
                : add("(BOUNDED_CURVE()B_SPLINE_CURVE(" + degree + "," + pts + ",.UNSPECIFIED.,.F.,.F.)"
                + "B_SPLINE_CURVE_WITH_KNOTS(" + kn[1] + "," + kn[0] + ",.UNSPECIFIED.)CURVE()"
                + "GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE(" + reals(w, 0, w.length)
                + ")REPRESENTATION_ITEM(''))");
    }

    /** A trim piece's curve in (u, v): the B-spline, trimmed by parameter values unless the whole of it runs forward. */
    private int pieceCurve(TrimPiece piece) {
        TrimCurve c = piece.curve();
        int n = c.pointCount();
        double[] uv = c.points(), w = c.weights();
        StringBuilder pts = new StringBuilder("(");
        for (int k = 0; k < n; k++) {
            pts.append(k == 0 ? "" : ",").append(point(uv[2 * k], uv[2 * k + 1]));
        }
        pts.append(')');
        int curve = bspline(c.degree(), c.knots(), pts.toString(), w);
        if (piece.from() == c.start() && piece.to() == c.end()) {
            return curve;
        }
        return trimmed(curve, piece.from(), piece.to());
    }

    private int trimmed(int basis, double from, double to) {
        return add("TRIMMED_CURVE(''," + ref(basis) + ",(PARAMETER_VALUE(" + real(from) + ")),(PARAMETER_VALUE("
                + real(to) + "))," + (from < to ? ".T." : ".F.") + ",.PARAMETER.)");
    }

    /** The rectangle {@code u0 u1 v0 v1} as four lines trimmed by parameter values (u along the first and third). */
    private int rangeLoop(int surface, double[] r, SplinePoint at, CurveOnSurface.Patches patches) {
        int[] v = {vertex(at, r[0], r[2]), vertex(at, r[1], r[2]), vertex(at, r[1], r[3]), vertex(at, r[0], r[3])};
        int alongU0 = line(0, r[2], 1, 0), alongV1 = line(r[1], 0, 0, 1), alongU1 = line(0, r[3], 1, 0);
        int alongV0 = line(r[0], 0, 0, 1);
        int c0 = curve3d(iso(r[0], r[2], r[1], r[2], false), at, patches);
        int c1 = curve3d(iso(r[1], r[2], r[1], r[3], false), at, patches);
        int c2 = curve3d(iso(r[0], r[3], r[1], r[3], true), at, patches);
        int c3 = curve3d(iso(r[0], r[2], r[0], r[3], true), at, patches);
        List<Integer> edges = List.of(edge(surface, trimmed(alongU0, r[0], r[1]), v[0], v[1], c0),
                edge(surface, trimmed(alongV1, r[2], r[3]), v[1], v[2], c1),
                edge(surface, trimmed(alongU1, r[1], r[0]), v[2], v[3], c2),
                edge(surface, trimmed(alongV0, r[3], r[2]), v[3], v[0], c3));
        return add("EDGE_LOOP(''," + refs(edges) + ")");
    }

    /**
     * The iso-parameter line from {@code (u0, v0)} to {@code (u1, v1)} as a degree-1 piece whose
     * parameter is the varying coordinate (the LINE's parameter), run backwards when {@code back}.
     */
    private static TrimPiece iso(double u0, double v0, double u1, double v1, boolean back) {
        double t0 = u0 == u1 ? v0 : u0, t1 = u0 == u1 ? v1 : u1;
        TrimCurve c = new TrimCurve(org.beziertracer.model.SplineBasis.BSPLINE, 1, new double[] {t0, t0, t1, t1},
                new double[] {u0, v0, u1, v1}, null);
        return back ? new TrimPiece(c, t1, t0) : new TrimPiece(c, t0, t1);
    }

    private int line(double u, double v, double du, double dv) {
        return add("LINE(''," + point(u, v) + "," + ref(add("VECTOR(''," + direction(du, dv) + ",1.)")) + ")");
    }

    private void emit(Writer out) throws IOException {
        String now = java.time.LocalDateTime.now(java.time.ZoneOffset.UTC).withNano(0)
                .format(java.time.format.DateTimeFormatter.ISO_LOCAL_DATE_TIME.withLocale(Locale.ROOT));
        out.write("ISO-10303-21;\nHEADER;\n");
        out.write("FILE_DESCRIPTION(('Bezier Tracer STEP export: B-spline faces with parameter-space trims'),'2;1');\n");
        out.write("FILE_NAME('model.stp','" + now + "',(''),(''),'Bezier Tracer','Bezier Tracer','');\n");
        out.write("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n");
        for (int k = 0; k < entities.size(); k++) {
            out.write("#" + (k + 1) + "=" + entities.get(k) + ";\n");
        }
        out.write("ENDSEC;\nEND-ISO-10303-21;\n");
    }
}
