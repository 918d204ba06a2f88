package org.beziertracer.model.io;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Scene;

/**
 * Reads the Bézier subset of Wavefront OBJ free-form geometry.
 *
 * <h2>Supported</h2>
 * <ul>
 *   <li>{@code v x y z [w]} — the weight {@code w} only matters for rational surfaces, which are
 *       unsupported, so it is read and ignored;</li>
 *   <li>{@code cstype bezier}, {@code deg n m} (each 1..15);</li>
 *   <li>{@code surf s0 s1 t0 t1 i1 i2 …} — vertex references may be 1-based, negative (relative
 *       to the vertices defined so far: {@code -1} is the last one) or in the {@code v/vt/vn},
 *       {@code v/vt} and {@code v//vn} forms, of which only {@code v} is used;
 *       control points are listed with <b>u varying fastest</b>;</li>
 *   <li>{@code parm u p0 p1 … pK} and {@code parm v q0 … qL}: K segments in u and L in v. The
 *       surf then lists {@code (K·n+1)(L·m+1)} control points, neighbouring segments sharing
 *       their boundary row. Such a surface is <b>split into K×L separate
 *       {@link BezierPatch}es</b>, each its own patch in the scene, in the order segment
 *       {@code (a,b)} → index {@code b·K + a} (u segment fastest). Without {@code parm}
 *       statements the surface is one segment each way. The parameter values themselves only
 *       count the segments: each segment is reparametrised to {@code [0,1]²};</li>
 *   <li>{@code end}; {@code #} comments; a trailing backslash continues a statement on the next
 *       line.</li>
 * </ul>
 * Polygon and grouping statements ({@code f}, {@code vt}, {@code vn}, {@code g}, {@code o},
 * {@code s}, {@code usemtl}, {@code mtllib}, …) and display hints ({@code ctech},
 * {@code stech}) are skipped. Rational, B-spline, basis-matrix, Cardinal and Taylor surfaces,
 * curves, trimming ({@code trim}, {@code hole}, {@code scrv}, {@code sp}) and connectivity
 * get a one-line "unsupported: …" error with the line number; so does a surf whose
 * {@code s0 s1}/{@code t0 t1} range is narrower than its {@code parm} range. A file without any
 * surface is an error.
 *
 * <p>Every error is a one-line {@link ModelFormatException} whose line number is the first
 * physical line of the statement. The caps of {@link ReadLimits} hold: lines, statements
 * (continuation lines joined: at most {@value #STATEMENT_LINES} lines' worth), vertices and
 * patches; a surf is counted before its patches are built. Files are opened through
 * {@link FileFormats#OBJ}. Stateless and thread-safe.
 */
public final class ObjReader {
    private ObjReader() {}

    private static final Set<String> SKIPPED = Set.of("f", "fo", "p", "l", "vt", "vn", "vp", "g", "o", "s", "mg",
            "usemtl", "mtllib", "lod", "shadow_obj", "trace_obj", "bevel", "c_interp", "d_interp", "maplib",
            "usemap", "ctech", "stech", "call", "csh");
    private static final Set<String> UNSUPPORTED = Set.of("curv", "curv2", "trim", "hole", "scrv", "sp", "con",
            "bmat", "step", "bsp", "bzp", "cdc", "cdp", "res");

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

    /** The patches of {@code text} as a scene (the reader {@link FileFormats#OBJ} declares). */
    static Scene readScene(TextSource text) throws IOException {
        return new Scene(read(text));
    }

    /**
     * Reads OBJ text.
     *
     * @throws ModelFormatException for any syntax, range, cap or unsupported-element problem,
     *                              naming {@link TextSource#fileName()}
     */
    public static List<BezierPatch> read(TextSource text) throws IOException {
        return new Parser(text).parse();
    }

    /** One parse: the vertex table, the current cstype/deg state and the open surf. */
    private static final class Parser {
        private final TextSource text;
        private final ReadLimits limits;
        private final String file;
        private final List<BezierPatch> patches = new ArrayList<>();
        private double[] vertices = new double[3 * 64];
        private int vertexCount;
        private boolean bezier;
        private int degreeU;
        private int degreeV;
        private int line;
        private Surf surf;

        Parser(TextSource text) {
            this.text = text;
            this.limits = text.limits();
            this.file = text.fileName();
        }

        List<BezierPatch> parse() throws IOException {
            int physical = 0;
            String raw;
            StringBuilder statement = new StringBuilder();
            int statementLine = 0;
            long statementCap = (long) STATEMENT_LINES * limits.lineChars();
            while ((raw = text.readLine()) != null) {
                physical = text.lineNumber();
                int hash = raw.indexOf('#');
                String content = (hash >= 0 ? raw.substring(0, hash) : raw).stripTrailing();
                if (statement.length() == 0) {
                    statementLine = physical;
                }
                if (statement.length() + content.length() > statementCap) {
                    line = statementLine;
                    throw error("statement longer than " + statementCap + " characters (joined continuation"
                            + " lines), the most a statement may hold");
                }
                if (content.endsWith("\\")) {
                    statement.append(content, 0, content.length() - 1).append(' ');
                    continue;
                }
                statement.append(content);
                line = statementLine;
                String s = statement.toString().strip();
                statement.setLength(0);
                if (!s.isEmpty()) {
                    statement(s.split("\\s+"));
                }
            }
            if (statement.length() > 0 && !statement.toString().isBlank()) {
                line = statementLine;
                statement(statement.toString().strip().split("\\s+"));
            }
            line = Math.max(physical, 1);
            if (surf != null) {
                throw error("expected end for the surf at line " + surf.line + ", found end of file");
            }
            if (patches.isEmpty()) {
                throw error("expected at least one Bézier surface (cstype bezier, deg n m, surf … end), found "
                        + (physical == 0 ? "an empty file" : "none"));
            }
            return patches;
        }

        private void statement(String[] t) {
            String keyword = t[0];
            switch (keyword) {
                case "v" -> vertex(t);
                case "cstype" -> cstype(t);
                case "deg" -> degree(t);
                case "surf" -> surf(t);
                case "parm" -> parm(t);
                case "end" -> end();
                default -> {
                    if (UNSUPPORTED.contains(keyword)) {
                        throw error("unsupported: " + keyword + " (" + explain(keyword)
                                + "); only untrimmed Bézier surfaces are read");
                    }
                    if (!SKIPPED.contains(keyword)) {
                        throw error("expected an OBJ statement (v, cstype, deg, surf, parm, end, …), found "
                                + NumberText.describe(keyword));
                    }
                }
            }
        }

        private static String explain(String keyword) {
            return switch (keyword) {
                case "curv", "curv2" -> "free-form curves";
                case "trim", "hole", "scrv", "sp" -> "trimmed surfaces";
                case "con" -> "surface connectivity";
                case "bmat", "step" -> "basis-matrix surfaces";
                default -> "free-form attribute";
            };
        }

        private void vertex(String[] t) {
            if (t.length < 4 || t.length > 5) {
                throw error("expected 3 coordinates (and an optional weight) after v, found " + (t.length - 1)
                        + " values");
            }
            if (vertexCount >= limits.vertices()) {
                throw error("a file may have at most " + limits.vertices() + " vertices; this is one more");
            }
            int index = vertexCount + 1;
            if (3 * vertexCount + 3 > vertices.length) {
                vertices = Arrays.copyOf(vertices, vertices.length * 2);
            }
            for (int c = 0; c < 3; c++) {
                vertices[3 * vertexCount + c] = NumberText.parseFinite(t[c + 1],
                        "the " + "xyz".charAt(c) + " coordinate of vertex " + index, file, line);
            }
            if (t.length == 5) {
                NumberText.parseFinite(t[4], "the weight of vertex " + index, file, line);
            }
            vertexCount++;
        }

        private void cstype(String[] t) {
            String type = String.join(" ", Arrays.copyOfRange(t, 1, t.length));
            if (type.equals("bezier")) {
                bezier = true;
                return;
            }
            if (t.length > 1 && t[1].equals("rat")) {
                throw error("unsupported: cstype " + Echo.cut(type) + " (rational surfaces); expected cstype bezier");
            }
            if (Set.of("bspline", "bmatrix", "cardinal", "taylor").contains(type)) {
                throw error("unsupported: cstype " + type + "; expected cstype bezier");
            }
            throw error("expected cstype bezier, found " + NumberText.describe(type));
        }

        private void degree(String[] t) {
            if (t.length < 2 || t.length > 3) {
                throw error("expected deg n m (two degrees), found " + (t.length - 1) + " values");
            }
            degreeU = parseDegree(t[1], "u");
            degreeV = t.length == 3 ? parseDegree(t[2], "v") : 0; // one value: a curve degree
        }

        private int parseDegree(String token, String direction) {
            if (!NumberText.isWhole(token)) {
                throw error("expected the " + direction + " degree (a whole number 1.." + BezierPatch.MAX_DEGREE
                        + "), found " + NumberText.describe(token));
            }
            long d = NumberText.parseWhole(token);
            if (d < 1 || d > BezierPatch.MAX_DEGREE) {
                throw error("expected the " + direction + " degree, found " + NumberText.describe(token)
                        + ": degree " + token + " out of range 1.." + BezierPatch.MAX_DEGREE);
            }
            return (int) d;
        }

        private void surf(String[] t) {
            if (surf != null) {
                throw error("expected end for the surf at line " + surf.line + ", found surf");
            }
            if (!bezier) {
                throw error("expected cstype bezier before surf, found surf without it");
            }
            if (degreeU == 0 || degreeV == 0) {
                throw error("expected deg n m (two degrees) before surf, found "
                        + (degreeU == 0 ? "no deg statement" : "a curve degree (one value)"));
            }
            if (t.length < 6) {
                throw error("expected surf s0 s1 t0 t1 followed by control-point indices, found "
                        + (t.length - 1) + " values");
            }
            Surf s = new Surf(line, degreeU, degreeV);
            String[] names = {"s0", "s1", "t0", "t1"};
            for (int k = 0; k < 4; k++) {
                s.range[k] = NumberText.parseFinite(t[k + 1], "the parameter " + names[k] + " of surf", file, line);
            }
            s.refs = new int[t.length - 5];
            for (int k = 0; k < s.refs.length; k++) {
                s.refs[k] = vertexRef(t[k + 5], k + 1);
            }
            surf = s;
        }

        /** Resolves a {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn} reference to a 0-based vertex. */
        private int vertexRef(String token, int position) {
            int slash = token.indexOf('/');
            String v = slash >= 0 ? token.substring(0, slash) : token;
            String what = "a vertex index for control point " + position + " of the surf";
            if (!NumberText.isWhole(v)) {
                throw error("expected " + what + ", found " + NumberText.describe(token));
            }
            long index = NumberText.parseWhole(v);
            if (vertexCount == 0) {
                throw error("expected " + what + ", found " + NumberText.describe(token)
                        + " but no vertex (v) is defined before this line");
            }
            if (index >= 1 && index <= vertexCount) {
                return (int) index - 1;
            }
            if (index <= -1 && index >= -vertexCount) {
                return (int) (vertexCount + index);
            }
            throw error("expected " + what + " in 1.." + vertexCount + " or -" + vertexCount + "..-1, found "
                    + NumberText.describe(token) + ": index out of range");
        }

        private void parm(String[] t) {
            if (surf == null) {
                throw error("expected parm inside a surf … end block, found parm outside one");
            }
            if (t.length < 4 || !(t[1].equals("u") || t[1].equals("v"))) {
                throw error("expected parm u|v followed by at least two parameter values, found "
                        + NumberText.describe(String.join(" ", t)));
            }
            double[] values = new double[t.length - 2];
            for (int k = 0; k < values.length; k++) {
                values[k] = NumberText.parseFinite(t[k + 2], "parameter value " + (k + 1) + " of parm " + t[1], file, line);
                if (k > 0 && !(values[k] > values[k - 1])) {
                    throw error("expected increasing parameter values in parm " + t[1] + ", found "
                            + NumberText.describe(t[k + 2]) + " after " + NumberText.describe(t[k + 1]));
                }
            }
            if (t[1].equals("u")) {
                surf.parmU = values;
            } else {
                surf.parmV = values;
            }
        }

        private void end() {
            if (surf == null) {
                throw error("expected end only after a surf, found end without one");
            }
            Surf s = surf;
            surf = null;
            line = s.line;
            int segmentsU = s.parmU == null ? 1 : s.parmU.length - 1;
            int segmentsV = s.parmV == null ? 1 : s.parmV.length - 1;
            checkRange("u", s.range[0], s.range[1], s.parmU);
            checkRange("v", s.range[2], s.range[3], s.parmV);
            long pointsU = (long) segmentsU * s.n + 1;
            long pointsV = (long) segmentsV * s.m + 1;
            long made = (long) segmentsU * segmentsV;
            if (patches.size() + made > limits.patches()) {
                throw error("a model may have at most " + limits.patches() + " patches; this surf makes " + made
                        + " more after " + patches.size());
            }
            if (pointsU * pointsV != s.refs.length) {
                throw error("expected " + pointsU * pointsV + " control-point indices for a degree " + s.n + "x" + s.m
                        + " surf of " + segmentsU + "x" + segmentsV + " segments ((" + segmentsU + "·" + s.n + "+1)("
                        + segmentsV + "·" + s.m + "+1)), found " + s.refs.length
                        + (s.parmU == null || s.parmV == null ? " (parm u / parm v give the segment counts)" : ""));
            }
            // Split the K×L segment grid into separate patches, u segment fastest
            for (int b = 0; b < segmentsV; b++) {
                for (int a = 0; a < segmentsU; a++) {
                    double[] net = new double[(s.n + 1) * (s.m + 1) * 3];
                    for (int j = 0; j <= s.m; j++) {
                        for (int i = 0; i <= s.n; i++) {
                            int ref = s.refs[(int) ((b * s.m + j) * pointsU + a * s.n + i)];
                            System.arraycopy(vertices, 3 * ref, net, 3 * (j * (s.n + 1) + i), 3);
                        }
                    }
                    patches.add(new BezierPatch(s.n, s.m, net));
                }
            }
        }

        private static final double[] DEFAULT_PARM = {0, 1};

        private void checkRange(String direction, double lo, double hi, double[] parmOrNull) {
            double[] parm = parmOrNull != null ? parmOrNull : DEFAULT_PARM; // no parm: the domain is [0,1]
            if ((lo != parm[0] || hi != parm[parm.length - 1])) {
                throw error("unsupported: surf range " + direction + "[" + NumberText.format(lo) + ","
                        + NumberText.format(hi) + "] differs from parm " + direction + " ["
                        + NumberText.format(parm[0]) + "," + NumberText.format(parm[parm.length - 1])
                        + "] (a surface restricted to part of its domain); expected the full range");
            }
        }

        private ModelFormatException error(String detail) {
            return new ModelFormatException(file, line, detail);
        }
    }

    /** A surf statement waiting for its {@code parm} lines and {@code end}. */
    private static final class Surf {
        final int line;
        final int n;
        final int m;
        final double[] range = new double[4];
        int[] refs;
        double[] parmU;
        double[] parmV;

        Surf(int line, int n, int m) {
            this.line = line;
            this.n = n;
            this.m = m;
        }
    }
}
