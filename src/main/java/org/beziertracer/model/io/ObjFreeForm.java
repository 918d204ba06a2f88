package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * The free-form statements of one OBJ parse ({@link ObjReader} hands them over one by one):
 * {@code vp}, {@code cstype [rat] bezier|bspline}, {@code deg}, {@code surf}, {@code curv2},
 * {@code parm}, {@code trim}, {@code hole} and {@code end}. Each {@code surf … end} block becomes
 * a {@link FreeFormSurface} and its Bézier pieces ({@link FreeFormSurface#toPatches()}); each
 * {@code curv2 … end} block a {@link TrimCurve}, numbered from 1 in file order.
 *
 * <p>Every error is a one-line {@link ModelFormatException} naming the statement's line: a knot
 * vector that decreases or repeats a knot more than degree + 1 times (the {@code parm} line), a
 * knot vector or point count that does not fit (the {@code parm} line of a curve, the
 * {@code surf} line of a surface), a surface range outside the knot range, a {@code trim} whose
 * curves do not close, a {@code curv2} index out of range, a {@code trim} that names a curve
 * defined only after it (reported once the rest of the file shows the curve exists).
 */
final class ObjFreeForm {

    /** Statements handled here. */
    static final Set<String> KEYWORDS = Set.of("vp", "cstype", "deg", "surf", "curv2", "curv", "parm", "trim", "hole",
            "end");
    private static final double[] DEFAULT_PARM = {0, 1};

    private String file;
    private final ObjVertices vertices;
    private final ReadLimits limits;
    private final List<BezierPatch> patches = new ArrayList<>();
    private final List<TrimCurve> curves = new ArrayList<>();
    private SplineBasis basis;
    private boolean rational;
    private int degreeU, degreeV; // degreeV == 0: a curve degree (one value)
    private Block block;
    private int line;
    /** A trim that named a curve not defined yet: its line and index; then only curv2 are counted. */
    private int forwardLine;
    private long forwardIndex;
    private int curvesBefore, curvesAfter;

    ObjFreeForm(String file, ObjVertices vertices, ReadLimits limits) {
        this.file = file;
        this.vertices = vertices;
        this.limits = limits;
    }

    /** Errors from now on name {@code name} (the file a {@code call} reads, then the caller again). */
    void file(String name) {
        this.file = name;
    }

    /** The Bézier patches of every surface read so far. */
    List<BezierPatch> patches() { return patches; }

    /** True after a forward curve reference: the rest of the file is only scanned for {@code curv2}. */
    boolean skipping() { return forwardLine > 0; }

    void statement(String[] t, int lineNumber) {
        line = lineNumber;
        if (skipping()) {
            if (t[0].equals("curv2")) {
                curvesAfter++;
            }
            return;
        }
        switch (t[0]) {
            case "vp" -> paramVertex(t);
            case "cstype" -> cstype(t);
            case "deg" -> degree(t);
            case "surf" -> surf(t);
            case "curv2" -> curv2(t);
            case "curv" -> curv();
            case "parm" -> parm(t);
            case "trim" -> trim(t, false);
            case "hole" -> trim(t, true);
            default -> end();
        }
    }

    /** End of file at {@code lastLine}: reports a pending forward reference or an open block. */
    void finish(int lastLine) {
        if (skipping()) {
            line = forwardLine;
            if (forwardIndex <= curvesBefore + curvesAfter) {
                throw error("expected a curv2 defined before this trim, found curv2 " + forwardIndex
                        + ", which is defined only after it (a curve must come before the trim that uses it)");
            }
            throw error(curveRange(curvesBefore) + "found \"" + forwardIndex + "\": index out of range (the file has "
                    + (curvesBefore + curvesAfter) + " curv2 statements)");
        }
        line = lastLine;
        if (block != null) {
            throw error("expected end for the " + block.keyword() + " at line " + block.line + ", found end of file");
        }
    }

    // ------------------------------------------------------------------ state statements

    private void paramVertex(String[] t) {
        if (t.length == 2) {
            throw error("unsupported: vp u (1-D parameter vertices); trim curves need vp u v [w]");
        }
        if (t.length < 3 || t.length > 4) {
            throw error("expected u v (and an optional weight) after vp, found " + (t.length - 1) + " values");
        }
        if (vertices.paramCount() >= limits.vertices()) {
            throw error("a file may have at most " + limits.vertices() + " parameter vertices; this is one more");
        }
        int index = vertices.paramCount() + 1;
        double u = NumberText.parseFinite(t[1], "the u coordinate of parameter vertex " + index, file, line);
        double v = NumberText.parseFinite(t[2], "the v coordinate of parameter vertex " + index, file, line);
        double w = t.length == 4 ? weight(t[3], "parameter vertex " + index, line) : 1;
        vertices.addParam(u, v, w);
    }

    /** A weight on line {@code at}: positive and finite, or a one-line error. */
    double weight(String token, String what, int at) {
        double w = NumberText.parseFinite(token, "the weight of " + what, file, at);
        if (!(w > 0)) {
            throw new ModelFormatException(file, at, "expected a positive weight for " + what + ", found "
                    + NumberText.describe(token));
        }
        return w;
    }

    private void cstype(String[] t) {
        boolean rat = t.length > 1 && t[1].equals("rat");
        String type = t.length > (rat ? 2 : 1) ? t[rat ? 2 : 1] : "";
        String all = String.join(" ", java.util.Arrays.copyOfRange(t, 1, t.length));
        if (t.length != (rat ? 3 : 2)) {
            throw error("expected cstype [rat] bezier|bspline, found " + NumberText.describe(all));
        }
        switch (type) {
            case "bezier" -> basis = SplineBasis.BEZIER;
            case "bspline" -> basis = SplineBasis.BSPLINE;
            case "bmatrix", "cardinal", "taylor" -> throw error("unsupported: cstype " + all
                    + " (basis-matrix, Cardinal and Taylor forms); expected cstype [rat] bezier|bspline");
            default -> throw error("expected cstype [rat] bezier|bspline, found " + NumberText.describe(all));
        }
        rational = rat;
    }

    private void degree(String[] t) {
        if (t.length < 2 || t.length > 3) {
            throw error("expected deg n m (two degrees) or deg n (a curve), found " + (t.length - 1) + " values");
        }
        degreeU = parseDegree(t[1], "u");
        degreeV = t.length == 3 ? parseDegree(t[2], "v") : 0;
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

    // ------------------------------------------------------------------ blocks

    private void surf(String[] t) {
        openBlock("surf");
        if (degreeU == 0 || degreeV == 0) {
            throw error("expected deg n m (two degrees) before surf, found "
                    + (degreeU == 0 ? "no deg statement" : "a curve degree (one value)"));
        }
        if (t.length < 6) {
            throw error("expected surf s0 s1 t0 t1 followed by control-point indices, found "
                    + (t.length - 1) + " values");
        }
        Block b = new Block("surf", line, basis, rational, degreeU, degreeV);
        String[] names = {"s0", "s1", "t0", "t1"};
        for (int k = 0; k < 4; k++) {
            b.range[k] = NumberText.parseFinite(t[k + 1], "the parameter " + names[k] + " of surf", file, line);
        }
        b.refs = new int[t.length - 5];
        for (int k = 0; k < b.refs.length; k++) {
            b.refs[k] = reference(t[k + 5], k + 1, vertices.count(), "a vertex index", "surf", "vertex (v)");
        }
        block = b;
    }

    /**
     * {@link #surf} of a statement in place — {@code a[start[k]..end[k])} for its {@code fields}
     * fields, the first {@code surf} — when every check passes and every index is a plain whole
     * number ({@code [+-]?\d{1,18}}, no {@code v/vt} form): the same block as the string path
     * makes. Otherwise false, having changed nothing: the caller then takes the string path, which
     * reads the other forms or reports the problem.
     */
    boolean plainSurf(char[] a, int[] start, int[] end, int fields, int lineNumber) {
        if (skipping() || block != null || basis == null || degreeU == 0 || degreeV == 0 || fields < 6) {
            return false;
        }
        double s0 = NumberText.finiteOrNaN(a, start[1], end[1]), s1 = NumberText.finiteOrNaN(a, start[2], end[2]);
        double t0 = NumberText.finiteOrNaN(a, start[3], end[3]), t1 = NumberText.finiteOrNaN(a, start[4], end[4]);
        if (Double.isNaN(s0) || Double.isNaN(s1) || Double.isNaN(t0) || Double.isNaN(t1)) {
            return false;
        }
        int defined = vertices.count();
        int[] refs = new int[fields - 5];
        for (int k = 0; k < refs.length; k++) {
            int index = ObjVertices.resolve(NumberText.wholeOrMin(a, start[k + 5], end[k + 5]), defined);
            if (index < 0) {
                return false;
            }
            refs[k] = index;
        }
        line = lineNumber;
        Block b = new Block("surf", line, basis, rational, degreeU, degreeV);
        b.range[0] = s0;
        b.range[1] = s1;
        b.range[2] = t0;
        b.range[3] = t1;
        b.refs = refs;
        block = b;
        return true;
    }

    private void curv2(String[] t) {
        openBlock("curv2");
        // a curve needs only the first degree: after deg n m it is of degree n (the spec reads on)
        if (degreeU == 0) {
            throw error("expected deg n before curv2, found no deg statement");
        }
        if (t.length < 3) {
            throw error("expected curv2 followed by at least 2 parameter-vertex indices, found " + (t.length - 1));
        }
        Block b = new Block("curv2", line, basis, rational, degreeU, 0);
        b.refs = new int[t.length - 1];
        for (int k = 0; k < b.refs.length; k++) {
            b.refs[k] = reference(t[k + 1], k + 1, vertices.paramCount(), "a parameter-vertex index", "curv2",
                    "parameter vertex (vp)");
        }
        block = b;
    }

    /**
     * A 3-D curve ({@code curv u0 u1 v1 v2 …} … {@code end}): not drawn, so its block is read past
     * (its {@code parm} lines unchecked); {@link ObjReader} counts it for the note.
     */
    private void curv() {
        if (block != null) {
            throw error("expected end for the " + block.keyword() + " at line " + block.line + ", found curv");
        }
        block = Block.skipped("curv", line);
    }

    private void openBlock(String keyword) {
        if (block != null) {
            throw error("expected end for the " + block.keyword() + " at line " + block.line + ", found " + keyword);
        }
        if (basis == null) {
            throw error("expected cstype bezier or bspline before " + keyword + ", found " + keyword + " without it");
        }
    }

    /** Resolves a {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn} reference to a 0-based index. */
    private int reference(String token, int position, int defined, String what, String statement, String kind) {
        int slash = token.indexOf('/');
        String v = slash >= 0 ? token.substring(0, slash) : token;
        if (!NumberText.isWhole(v)) {
            throw error("expected " + expected(what, position, statement) + ", found " + NumberText.describe(token));
        }
        if (defined == 0) {
            throw error("expected " + expected(what, position, statement) + ", found " + NumberText.describe(token) + " but no " + kind
                    + " is defined before this line");
        }
        int index = ObjVertices.resolve(NumberText.parseWhole(v), defined);
        if (index < 0) {
            throw error("expected " + expected(what, position, statement) + " in 1.." + defined + " or -" + defined
                    + "..-1, found " + NumberText.describe(token) + ": index out of range");
        }
        return index;
    }

    /** What a control-point reference should be, for messages only (built when one is thrown). */
    private static String expected(String what, int position, String statement) {
        return what + " for control point " + position + " of the " + statement;
    }

    private void parm(String[] t) {
        if (block == null) {
            throw error("expected parm inside a surf or curv2 … end block, found parm outside one");
        }
        if (block.skipped) {
            return;
        }
        boolean isU = t.length > 1 && t[1].equals("u");
        if (t.length < 4 || !(isU || t[1].equals("v")) || (!isU && block.degreeV == 0)) {
            throw error("expected parm u" + (block.degreeV == 0 ? "" : "|v")
                    + " followed by at least two parameter values, found " + NumberText.describe(String.join(" ", t)));
        }
        int degree = isU ? block.degreeU : block.degreeV;
        double[] values = new double[t.length - 2];
        int run = 1;
        for (int k = 0; k < values.length; k++) {
            values[k] = NumberText.parseFinite(t[k + 2], "parameter value " + (k + 1) + " of parm " + t[1], file, line);
            if (k == 0) {
                continue;
            }
            if (block.basis == SplineBasis.BEZIER ? !(values[k] > values[k - 1]) : values[k] < values[k - 1]) {
                throw error("expected " + (block.basis == SplineBasis.BEZIER ? "increasing parameter values"
                        : "knots that never decrease") + " in parm " + t[1] + ", found "
                        + NumberText.describe(t[k + 2]) + " after " + NumberText.describe(t[k + 1]));
            }
            run = values[k] == values[k - 1] ? run + 1 : 1;
            if (run > degree + 1) {
                throw error("expected each knot at most degree + 1 = " + (degree + 1) + " times in parm " + t[1]
                        + ", found " + NumberText.describe(t[k + 2]) + " " + (run + repeats(t, k + 3, values[k]))
                        + " times");
            }
        }
        if (isU) {
            block.parmU = values;
            block.parmULine = line;
        } else {
            block.parmV = values;
            block.parmVLine = line;
        }
    }

    /** How many tokens from {@code from} on repeat the value {@code knot} (the rest of a run, for its count). */
    private static int repeats(String[] t, int from, double knot) {
        int n = 0;
        while (from + n < t.length && NumberText.finiteOrNaN(t[from + n]) == knot) {
            n++;
        }
        return n;
    }

    private void trim(String[] t, boolean hole) {
        String keyword = t[0];
        if (block == null || block.degreeV == 0) {
            throw error("expected " + keyword + " inside a surf … end block, found " + keyword + " outside one");
        }
        if (t.length < 4 || (t.length - 1) % 3 != 0) {
            throw error("expected " + keyword + " u0 u1 curv2d (one or more triples), found " + (t.length - 1) + " values");
        }
        List<TrimPiece> pieces = new ArrayList<>();
        for (int k = 1; k < t.length; k += 3) {
            int piece = (k + 2) / 3;
            double from = NumberText.parseFinite(t[k], "u0 of curve " + piece + " of the " + keyword, file, line);
            double to = NumberText.parseFinite(t[k + 1], "u1 of curve " + piece + " of the " + keyword, file, line);
            if (!NumberText.isWhole(t[k + 2])) {
                throw error("expected a curv2 index for curve " + piece + " of the " + keyword + ", found "
                        + NumberText.describe(t[k + 2]));
            }
            long reference = NumberText.parseWhole(t[k + 2]);
            if (reference > curves.size()) {
                forwardLine = line;
                forwardIndex = reference;
                curvesBefore = curves.size();
                return;
            }
            int index = ObjVertices.resolve(reference, curves.size());
            if (index < 0) {
                throw error(curveRange(curves.size()) + "found " + NumberText.describe(t[k + 2]) + ": index out of range");
            }
            try {
                pieces.add(new TrimPiece(curves.get(index), from, to));
            } catch (IllegalArgumentException e) {
                throw error("curve " + piece + " (curv2 " + (index + 1) + ") of the " + keyword + ": " + e.getMessage());
            }
        }
        try {
            (hole ? block.holes : block.outer).add(new TrimLoop(pieces));
        } catch (IllegalArgumentException e) {
            throw error(e.getMessage());
        }
    }

    private static String curveRange(int defined) {
        return defined == 0 ? "expected a curv2 index, but no curv2 is defined before this line; "
                : "expected a curv2 index in 1.." + defined + " or -" + defined + "..-1 (the curv2 statements before "
                + "this line), ";
    }

    private void end() {
        if (block == null) {
            throw error("expected end only after a surf or curv2, found end without one");
        }
        Block b = block;
        block = null;
        if (b.skipped) {
            return;
        }
        if (b.degreeV == 0) {
            curves.add(ObjBlocks.curve(b, vertices, file));
            return;
        }
        FreeFormSurface surface = ObjBlocks.surface(b, vertices, file);
        long made = surface.pieceCount();
        if (patches.size() + made > limits.patches()) {
            line = b.line;
            throw error("a model may have at most " + limits.patches() + " patches; this surf makes " + made
                    + " more after " + patches.size());
        }
        patches.addAll(surface.toPatches());
    }

    private ModelFormatException error(String detail) {
        return new ModelFormatException(file, line, detail);
    }

    /** An open {@code surf} or {@code curv2} block: its statement and the body read so far. */
    static final class Block {
        final String keyword;
        final int line;
        final SplineBasis basis;
        final boolean rational;
        final int degreeU, degreeV;
        final double[] range = new double[4];
        int[] refs;
        double[] parmU, parmV;
        int parmULine, parmVLine;
        final List<TrimLoop> outer = new ArrayList<>(), holes = new ArrayList<>();
        /** True for a block read past without building anything ({@code curv}). */
        final boolean skipped;

        Block(String keyword, int line, SplineBasis basis, boolean rational, int degreeU, int degreeV) {
            this(keyword, line, basis, rational, degreeU, degreeV, false);
        }

        private Block(String keyword, int line, SplineBasis basis, boolean rational, int degreeU, int degreeV,
                      boolean skipped) {
            this.skipped = skipped;
            this.keyword = keyword;
            this.line = line;
            this.basis = basis;
            this.rational = rational;
            this.degreeU = degreeU;
            this.degreeV = degreeV;
        }

        /** A block read past: its {@code parm} lines are not checked and its {@code end} builds nothing. */
        static Block skipped(String keyword, int line) {
            return new Block(keyword, line, null, false, 0, 0, true);
        }

        String keyword() { return keyword; }

        TrimRegion trim() {
            return outer.isEmpty() && holes.isEmpty() ? null : new TrimRegion(outer, holes);
        }

        static double[] orDefault(double[] parm) {
            return parm != null ? parm : DEFAULT_PARM;
        }
    }
}
