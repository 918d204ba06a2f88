package org.beziertracer.model.io;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.Scene;

/**
 * Reads Wavefront OBJ free-form geometry — Bézier and B-spline surfaces, rational or not, with
 * trim loops and holes — and polygon faces, which load as one triangle mesh beside the surfaces.
 *
 * <h2>Supported</h2>
 * <ul>
 *   <li>{@code v x y z [w]} — the weight {@code w} (default 1, positive and finite) counts for
 *       rational surfaces; {@code vp u v [w]} — parameter-space vertices of trim curves;</li>
 *   <li>{@code cstype [rat] bezier|bspline}, {@code deg n m} (a surface) or {@code deg n} (a
 *       curve), each 1..15;</li>
 *   <li>{@code surf s0 s1 t0 t1 i1 i2 …} — vertex references may be 1-based, negative (relative
 *       to the vertices defined so far: {@code -1} is the last one) or in the {@code v/vt/vn},
 *       {@code v/vt} and {@code v//vn} forms, of which only {@code v} is used; control points are
 *       listed with <b>u varying fastest</b>;</li>
 *   <li>{@code parm u …} and {@code parm v …}: a B-spline's knot vectors, or a Bézier surface's
 *       segment breakpoints (K+1 values for K segments; none means one segment on [0,1]);</li>
 *   <li>{@code curv2 vp1 vp2 …} … {@code parm u …} … {@code end}: a 2-D trim curve, numbered from 1
 *       in file order; {@code trim u0 u1 c …} and {@code hole u0 u1 c …} inside a surf block:
 *       an outer loop or a hole made of curve pieces (a negative {@code c} counts back);</li>
 *   <li>{@code end}; {@code #} comments; a trailing backslash continues a statement on the next
 *       line;</li>
 *   <li>{@code call FILE.obj}: the named file, relative to the calling one, read in place (one
 *       vertex list across the files); cycles, nesting deeper than 8 and arguments are refused
 *       ({@link ObjCalls});</li>
 *   <li>{@code vt u [v [w]]}, {@code vn x y z} and {@code f} (or {@code fo}) faces of 3 or more
 *       corners {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn} (1-based or negative):
 *       every face of the file goes into one {@link Mesh}, cut into fans of triangles
 *       ({@link ObjFaces}), with uvs when every corner names a {@code vt} and normals when every
 *       corner names a {@code vn}.</li>
 * </ul>
 * Each surface is kept as read ({@link org.beziertracer.model.FreeFormSurface}) and becomes its
 * Bézier pieces by knot insertion, in the order v piece major, u piece fastest; each piece
 * reports its part of the surface's parameter range (the {@code surf} range, which may be any
 * part of the knot range) and carries the trim loops. What CAD tools write beside the surfaces
 * and is not drawn — 3-D curves ({@code curv} … {@code end}), special curves and points
 * ({@code scrv}, {@code sp}), connectivity ({@code con}), points and lines ({@code p},
 * {@code l}) — is skipped and counted in one note ({@link Model#notes()}, {@link ObjSkipped});
 * grouping statements ({@code g}, {@code o}, {@code s}, {@code usemtl}, {@code mtllib}, …) and
 * display hints ({@code ctech}, {@code stech}) are skipped without a note. Basis-matrix,
 * Cardinal and Taylor forms get a one-line "unsupported: …" error with the line number. A file
 * without any surface or face is an error.
 *
 * <p>Every error is a one-line {@link ModelFormatException} whose line number is the first
 * physical line of the statement ({@link ObjFreeForm} lists the free-form ones). The caps of
 * {@link ReadLimits} hold: lines, statements (continuation lines joined: at most
 * {@value #STATEMENT_LINES} lines' worth), vertices (and parameter vertices) and patches; a surf
 * is counted before its patches are built. Files are opened through {@link FileFormats#OBJ}.
 * Stateless and thread-safe.
 */
public final class ObjReader {
    private ObjReader() {}

    private static final Set<String> SKIPPED = Set.of("g", "o", "s", "mg",
            "usemtl", "mtllib", "lod", "shadow_obj", "trace_obj", "bevel", "c_interp", "d_interp", "maplib",
            "usemap", "ctech", "stech", "csh");
    private static final Set<String> UNSUPPORTED = Set.of("bmat", "step", "bsp", "bzp", "cdc", "cdp", "res");

    /** A statement joined from continuation lines may hold this many lines' worth of characters. */
    static final int STATEMENT_LINES = 4;

    /** Reads OBJ text; for tests and in-memory use. */
    public static List<BezierPatch> read(String text, String fileName) {
        try {
            return read(TextSource.of(text, fileName));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * What an OBJ file holds: its surfaces' Bézier patches, its faces' mesh (null without faces)
     * and the notes of the read (what it skipped, {@link ObjSkipped}; empty when nothing).
     */
    public record Model(List<BezierPatch> patches, Mesh mesh, List<String> notes) {
        public Model {
            notes = List.copyOf(notes);
        }
    }

    /**
     * The patches and the mesh of {@code text} as a scene, both with material 0 (the reader
     * {@link FileFormats#OBJ} declares).
     */
    static Scene readScene(TextSource text, Path baseDir, List<String> notes) throws IOException {
        Model model = readModel(text, baseDir);
        notes.addAll(model.notes());
        Scene.Builder b = Scene.builder().patches(model.patches());
        if (model.mesh() != null) {
            b.addMesh(model.mesh(), 0);
        }
        return b.build();
    }

    /**
     * Reads OBJ text: surfaces and faces.
     *
     * @throws ModelFormatException for any syntax, range, cap or unsupported-element problem,
     *                              naming {@link TextSource#fileName()}
     */
    public static Model readModel(TextSource text) throws IOException {
        return readModel(text, null);
    }

    /**
     * Reads OBJ text whose {@code call} statements name files relative to {@code baseDir} (null:
     * the working directory); {@link ObjCalls}.
     *
     * @throws ModelFormatException for any problem, naming the file (the called one for a problem in it)
     */
    public static Model readModel(TextSource text, Path baseDir) throws IOException {
        HeapEstimates.requireObj(text); // a file too big for the heap is refused before parsing
        return new Parser(text, baseDir, true).parse();
    }

    /**
     * {@link #readModel(TextSource, Path)} with the in-place paths (plain {@code v}, {@code surf}
     * and {@code f} statements parsed where they lie) on or off, for the tests that hold the two paths to the
     * same result; {@code inPlaceCounts[0..2]} receive how many vertices, surfs and faces took
     * the in-place path.
     */
    static Model readModel(TextSource text, boolean inPlace, int[] inPlaceCounts) throws IOException {
        Parser parser = new Parser(text, null, inPlace);
        try {
            return parser.parse();
        } finally {
            if (parser.inPlace != null) {
                inPlaceCounts[0] = parser.inPlace.vertexCount;
                inPlaceCounts[1] = parser.inPlace.surfCount;
                inPlaceCounts[2] = parser.inPlace.faceCount;
            }
        }
    }

    /** {@link #readModel(TextSource)} of in-memory text; for tests. */
    public static Model readModel(String text, String fileName) {
        try {
            return readModel(TextSource.of(text, fileName));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Reads OBJ text; the patches of its surfaces (none for a file of faces only, whose mesh
     * {@link #readModel(TextSource)} returns).
     *
     * @throws ModelFormatException for any syntax, range, cap or unsupported-element problem,
     *                              naming {@link TextSource#fileName()}
     */
    public static List<BezierPatch> read(TextSource text) throws IOException {
        return readModel(text).patches();
    }

    /** One parse: the vertex tables and the free-form state ({@link ObjFreeForm}). */
    private static final class Parser {
        private final TextSource text;
        private final ReadLimits limits;
        private final String topFile;
        private final ObjCalls calls;
        /** The file being read (a called one while its statements are read). */
        private String file;
        private final ObjVertices vertices = new ObjVertices();
        private final ObjFreeForm freeForm;
        private final ObjFaces faces;
        private final ObjSkipped skipped = new ObjSkipped();
        private int line;
        /** The coordinates of the vertex being read. */
        private final double[] xyz = new double[3];
        /** The statements read without strings; null: every statement takes the string path (the tests' reference). */
        private final ObjInPlace inPlace;

        Parser(TextSource text, Path baseDir, boolean inPlace) {
            this.text = text;
            this.limits = text.limits();
            this.file = text.fileName();
            this.topFile = file;
            this.calls = new ObjCalls(file, baseDir);
            this.freeForm = new ObjFreeForm(file, vertices, limits);
            this.faces = new ObjFaces(file, limits);
            this.inPlace = inPlace ? new ObjInPlace(vertices, freeForm, faces, limits) : null;
        }

        Model parse() throws IOException {
            int physical = readAll(text);
            line = Math.max(physical, 1);
            freeForm.finish(line);
            List<BezierPatch> patches = freeForm.patches();
            if (patches.isEmpty() && !faces.any()) {
                throw error("expected at least one Bézier surface (cstype bezier, deg n m, surf … end) or face (f), found "
                        + (physical == 0 ? "an empty file" : "none"));
            }
            String note = skipped.note(topFile);
            return new Model(patches, faces.mesh(vertices), note == null ? List.of() : List.of(note));
        }

        /**
         * Reads the statements of {@code text} (the file opened, or a called one); its last line
         * number. Lines are read where they lie ({@link TextSource#nextLine()}): what
         * {@link ObjInPlace} reads is parsed from the characters; any other statement becomes a
         * string and goes through {@link #statement}.
         */
        private int readAll(TextSource text) throws IOException {
            int physical = 0;
            StringBuilder statement = new StringBuilder();
            int statementLine = 0;
            long statementCap = (long) STATEMENT_LINES * limits.lineChars();
            while (text.nextLine()) {
                physical = text.lineNumber();
                char[] a = text.lineChars();
                int from = text.lineStart(), end = commentAt(a, from, text.lineEnd());
                while (end > from && Character.isWhitespace(a[end - 1])) {
                    end--; // String.stripTrailing, in place
                }
                if (statement.length() == 0) {
                    statementLine = physical;
                }
                if (statement.length() + (end - from) > statementCap) {
                    line = statementLine;
                    throw error("statement longer than " + statementCap + " characters (joined continuation"
                            + " lines), the most a statement may hold");
                }
                if (end > from && a[end - 1] == '\\') {
                    statement.append(a, from, end - from - 1).append(' ');
                    continue;
                }
                line = statementLine;
                if (statement.length() == 0) { // a statement of one line (nearly all): read in place
                    while (from < end && Character.isWhitespace(a[from])) {
                        from++;
                    }
                    if (from < end && (inPlace == null || !inPlace.statement(a, from, end, line))) {
                        statement(inPlace != null ? inPlace.fields(a, from, end) : Fields.of(new String(a, from, end - from)));
                    }
                } else {
                    statement.append(a, from, end - from);
                    String s = statement.toString().strip();
                    statement.setLength(0);
                    if (!s.isEmpty()) {
                        char[] c = s.toCharArray();
                        if (inPlace == null || !inPlace.vertex(c, 0, c.length)) {
                            statement(Fields.of(s));
                        }
                    }
                }
            }
            if (statement.length() > 0 && !statement.toString().isBlank()) {
                line = statementLine;
                statement(Fields.of(statement.toString()));
            }
            return physical;
        }

        /** Where a {@code #} comment starts in {@code a[from..to)}, else {@code to}. */
        private static int commentAt(char[] a, int from, int to) {
            for (int i = from; i < to; i++) {
                if (a[i] == '#') {
                    return i;
                }
            }
            return to;
        }

        /** {@code call FILE.obj}: the file's statements, read in place ({@link ObjCalls}). */
        private void call(String[] t) throws IOException {
            TextSource called = calls.enter(t, line, limits);
            int callLine = line;
            try {
                named(calls.current());
                readAll(called);
            } finally {
                calls.leave();
                named(calls.current());
                line = callLine;
            }
        }

        /** Errors from now on name {@code name}. */
        private void named(String name) {
            file = name;
            freeForm.file(name);
            faces.file(name);
        }

        private void statement(String[] t) throws IOException {
            String keyword = t[0];
            if (ObjSkipped.counts(keyword)) {
                skipped.add(keyword);
                if (!keyword.equals("curv")) {
                    return; // a curv opens a block (parm, end) the free-form state reads past
                }
            }
            if (freeForm.skipping() || ObjFreeForm.KEYWORDS.contains(keyword)) {
                freeForm.statement(t, line);
                return;
            }
            switch (keyword) {
                case "v" -> vertex(t);
                case "vt" -> faces.textureVertex(t, line);
                case "vn" -> faces.normal(t, line);
                case "f", "fo" -> faces.face(t, line, vertices.count());
                case "call" -> call(t);
                default -> other(keyword);
            }
        }

        private void other(String keyword) {
            if (UNSUPPORTED.contains(keyword)) {
                throw error("unsupported: " + keyword + " (" + explain(keyword)
                        + "); Bézier and B-spline surfaces, curv2 trim curves, trim and hole are read");
            }
            if (!SKIPPED.contains(keyword)) {
                throw error("expected an OBJ statement (v, vp, cstype, deg, surf, curv2, parm, trim, hole, end, f, …), found "
                        + NumberText.describe(keyword));
            }
        }

        private static String explain(String keyword) {
            return switch (keyword) {
                case "bmat", "step" -> "basis-matrix surfaces";
                case "bsp" -> "a superseded geometry statement of older OBJ versions: a B-spline patch";
                case "bzp" -> "a superseded geometry statement of older OBJ versions: a Bézier patch";
                case "cdc" -> "a superseded geometry statement of older OBJ versions: a Cardinal curve";
                case "cdp" -> "a superseded geometry statement of older OBJ versions: a Cardinal patch";
                default -> "a superseded geometry statement of older OBJ versions: the resolution of bsp, bzp, "
                        + "cdc and cdp";
            };
        }

        private void vertex(String[] t) {
            if (t.length < 4 || t.length > 5) {
                throw error("expected 3 coordinates (and an optional weight) after v, found " + (t.length - 1)
                        + " values");
            }
            if (vertices.count() >= limits.vertices()) {
                throw error("a file may have at most " + limits.vertices() + " vertices; this is one more");
            }
            int index = vertices.count() + 1;
            for (int c = 0; c < 3; c++) {
                xyz[c] = NumberText.finiteOrNaN(t[c + 1]);
                if (Double.isNaN(xyz[c])) { // the message only when it is needed: this runs for every vertex
                    NumberText.parseFinite(t[c + 1], "the " + "xyz".charAt(c) + " coordinate of vertex " + index,
                            file, line);
                }
            }
            double w = t.length == 5 ? freeForm.weight(t[4], "vertex " + index, line) : 1;
            vertices.add(xyz[0], xyz[1], xyz[2], w);
        }

        private ModelFormatException error(String detail) {
            return new ModelFormatException(file, line, detail);
        }
    }
}
