package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Material;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.PatchOrigin;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * Writes a scene's surfaces as IGES 5.3 (fixed ASCII form), in millimetres at scale 1: a free-form
 * surface whose pieces are all present and unchanged as one rational B-spline surface (128) with
 * its knots, every other patch as its own 128 over its parameter box; a trimmed one as a trimmed
 * surface (144) whose boundaries are curves on the surface (142) pointing to their
 * parameter-space curves (126, joined by a 102 composite when a loop has several). Numbers are
 * written in the shortest form that reads back to the same {@code double}, so reading the file
 * with {@link IgesReader} gives the same knots, points, weights and trim curves. A region of
 * several outer loops becomes one 144 an outer loop, each with every hole. A curve run backwards
 * is written as the same curve of the reversed parameter {@code −t}. A surface whose material is
 * not the default points its 128 and 144 directory colour fields at a colour definition (314) of
 * its diffuse colour, one 314 a colour, which {@link IgesReader} turns back into the same diffuse
 * material.
 */
public final class IgesWriter {

    private record Entity(int type, int form, String status, String label, int colour, List<String> params) {
        Entity(int type, int form, String status, String label, List<String> params) {
            this(type, form, status, label, 0, params);
        }

        Entity coloured(int colourField) {
            return new Entity(type, form, status, label, colourField, params);
        }
    }

    private final List<Entity> entities = new ArrayList<>();
    /** The material of the surface being written (its first patch's). */
    private Material material = Material.DEFAULT;
    /** The 314 written for each diffuse colour, by its channels. */
    private final Map<List<Double>, Integer> colourOf = new java.util.HashMap<>();

    private IgesWriter() {}

    /** Writes the surfaces of {@code scene}; its meshes are refused (IGES faces would lose them). */
    public static void write(Writer out, Scene scene) throws IOException {
        write(out, scene, WriteProgress.NONE);
    }

    /** As {@link #write(Writer, Scene)}, telling {@code progress} the patches made into entities (before the file is written). */
    public static void write(Writer out, Scene scene, WriteProgress progress) throws IOException {
        if (!scene.meshes().isEmpty()) {
            throw new IllegalArgumentException("the IGES writer saves free-form surfaces only but the model has "
                    + scene.meshes().size() + " triangle mesh(es); save the model as .obj");
        }
        IgesWriter w = new IgesWriter();
        w.surfaces(scene, progress);
        w.emit(out);
    }

    private void surfaces(Scene scene, WriteProgress progress) throws IOException {
        eachSurface(scene.patches(), k -> material = scene.materials().get(scene.patchMaterial(k)), progress,
                (p, q, knotsU, knotsV, countU, countV, points, weights, range, trim) ->
                        trimmed(bspline(p, q, knotsU, knotsV, countU, countV, points, weights, range), trim));
    }

    /**
     * The directory colour field for the current material: 0 (no colour) for the default, else
     * the negated pointer to a colour definition (314) of its diffuse colour, written once a
     * colour. Channels are written as percentages whose decimal text is the channel's shortest
     * decimal with the point moved two places, so {@link IgesParams#fraction} gives the same
     * {@code double} back; channels above 1 are written as 1 (314 allows 0..100).
     */
    private int colourField() {
        if (material.equals(Material.DEFAULT)) {
            return 0;
        }
        double r = Math.min(1, material.r()), g = Math.min(1, material.g()), b = Math.min(1, material.b());
        Integer known = colourOf.get(List.of(r, g, b));
        if (known == null) {
            List<String> f = new ArrayList<>();
            f.add("314");
            f.add(percent(r));
            f.add(percent(g));
            f.add(percent(b));
            known = add(new Entity(314, 0, "00000200", "COLOR", f));
            colourOf.put(List.of(r, g, b), known);
        }
        return -known;
    }

    /** {@code fraction} × 100 as exact decimal text, with a decimal point: {@code 0.85 → "85.0"}, {@code 0.123 → "12.3"}. */
    static String percent(double fraction) {
        String s = new java.math.BigDecimal(Double.toString(fraction)).movePointRight(2).stripTrailingZeros().toPlainString();
        return s.indexOf('.') < 0 ? s + ".0" : s;
    }

    /** Receives one B-spline surface to write: degrees, full knot vectors, net (u fastest), weights or null, range, trims or null. */
    interface SurfaceSink {
        void surface(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV, double[] points,
                     double[] weights, double[] range, TrimRegion trim);
    }

    /**
     * The surfaces a CAD writer (IGES, STEP) saves for {@code patches}: a free-form surface whose
     * pieces are all present, once, with its knots; every other patch as a Bézier B-spline over
     * its parameter box.
     */
    static void eachSurface(List<BezierPatch> patches, WriteProgress progress, SurfaceSink sink) throws IOException {
        eachSurface(patches, k -> { }, progress, sink);
    }

    /** {@link #eachSurface}, telling {@code firstPatch} the index of each surface's first patch before the surface. */
    static void eachSurface(List<BezierPatch> patches, java.util.function.IntConsumer firstPatch, WriteProgress progress,
                            SurfaceSink sink) throws IOException {
        Map<FreeFormSurface, BitSet> present = new IdentityHashMap<>();
        for (BezierPatch p : patches) {
            PatchOrigin o = p.origin();
            if (o != null) {
                present.computeIfAbsent(o.surface(), s -> new BitSet()).set(o.piece());
            }
        }
        Map<FreeFormSurface, Boolean> written = new IdentityHashMap<>();
        for (int k = 0; k < patches.size(); k++) {
            BezierPatch p = patches.get(k);
            PatchOrigin o = p.origin();
            if (o != null && present.get(o.surface()).cardinality() == o.pieceCount()) {
                if (written.put(o.surface(), Boolean.TRUE) == null) {
                    firstPatch.accept(k);
                    FreeFormSurface s = o.surface();
                    sink.surface(s.degreeU(), s.degreeV(), s.basis().knotVector(s.degreeU(), s.parmU()),
                            s.basis().knotVector(s.degreeV(), s.parmV()), s.countU(), s.countV(), s.points(),
                            s.weights(), s.range(), s.trim());
                }
            } else {
                PatchDomain d = p.domain();
                int n = p.degreeU(), m = p.degreeV();
                firstPatch.accept(k);
                sink.surface(n, m, bezierKnots(n, d.u0(), d.u1()), bezierKnots(m, d.v0(), d.v1()), n + 1, m + 1,
                        p.copyNet(), p.weights(), new double[] {d.u0(), d.u1(), d.v0(), d.v1()}, p.trim());
            }
            progress.patch(k + 1, patches.size());
        }
    }

    private static double[] bezierKnots(int degree, double from, double to) {
        double[] k = new double[2 * degree + 2];
        for (int i = 0; i < k.length; i++) {
            k[i] = i <= degree ? from : to;
        }
        return k;
    }

    /** A 128 entity, independent unless a 144 claims it; returns its directory pointer. */
    private int bspline(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV, double[] points,
                        double[] weights, double[] range) {
        List<String> f = new ArrayList<>();
        f.add("128");
        ints(f, countU - 1, countV - 1, p, q, 0, 0, weights == null ? 1 : 0, 0, 0);
        reals(f, knotsU);
        reals(f, knotsV);
        for (int k = 0; k < countU * countV; k++) {
            f.add(real(weights == null ? 1 : weights[k]));
        }
        reals(f, points);
        reals(f, range);
        return add(new Entity(128, 0, "00000000", "SURFACE", colourField(), f));
    }

    /** The 144 over surface {@code surface} (a pointer) for each outer loop, or nothing when untrimmed. */
    private void trimmed(int surface, TrimRegion trim) {
        if (trim == null) {
            return;
        }
        claim(surface);
        List<Integer> holes = new ArrayList<>();
        for (TrimLoop loop : trim.holes()) {
            holes.add(onSurface(surface, loop));
        }
        List<Integer> outers = new ArrayList<>();
        for (TrimLoop loop : trim.outer()) {
            outers.add(onSurface(surface, loop));
        }
        if (outers.isEmpty()) {
            outers.add(0);
        }
        for (int outer : outers) {
            List<String> f = new ArrayList<>();
            f.add("144");
            ints(f, surface, outer == 0 ? 0 : 1, holes.size(), outer);
            for (int h : holes) {
                f.add(Integer.toString(h));
            }
            add(new Entity(144, 0, "00000000", "TRIMSURF", colourField(), f));
        }
    }

    /** A surface's directory status made physically dependent (drawn through its 144). */
    private void claim(int pointer) {
        Entity e = entities.get((pointer - 1) / 2);
        entities.set((pointer - 1) / 2, new Entity(e.type, e.form, "00010000", e.label, e.colour, e.params));
    }

    /** The 142 for {@code loop} on {@code surface}; its parameter-space curves as 126 (joined by a 102). */
    private int onSurface(int surface, TrimLoop loop) {
        List<Integer> curves = new ArrayList<>();
        for (TrimPiece piece : loop.pieces()) {
            curves.add(curve(piece));
        }
        int b = curves.get(0);
        if (curves.size() > 1) {
            List<String> f = new ArrayList<>();
            f.add("102");
            f.add(Integer.toString(curves.size()));
            for (int c : curves) {
                f.add(Integer.toString(c));
            }
            b = add(new Entity(102, 0, "00010500", "LOOP", f));
        }
        List<String> f = new ArrayList<>();
        f.add("142");
        ints(f, 0, surface, b, 0, 1);
        return add(new Entity(142, 0, "00010000", "BOUNDARY", f));
    }

    /** A trim piece as a planar 126 in (u, v), reversed by {@code t → −t} when it runs backwards. */
    private int curve(TrimPiece piece) {
        TrimCurve c = piece.curve();
        double[] knots = c.knots(), pts = c.points(), w = c.weights();
        int n = c.pointCount();
        double from = piece.from(), to = piece.to();
        if (from > to) {
            double[] rk = new double[knots.length], rp = new double[pts.length];
            double[] rw = w == null ? null : new double[n];
            for (int k = 0; k < knots.length; k++) {
                rk[k] = -knots[knots.length - 1 - k];
            }
            for (int k = 0; k < n; k++) {
                rp[2 * k] = pts[2 * (n - 1 - k)];
                rp[2 * k + 1] = pts[2 * (n - 1 - k) + 1];
                if (rw != null) {
                    rw[k] = w[n - 1 - k];
                }
            }
            knots = rk;
            pts = rp;
            w = rw;
            from = -from;
            to = -to;
        }
        List<String> f = new ArrayList<>();
        f.add("126");
        ints(f, n - 1, c.degree(), 1, 0, w == null ? 1 : 0, 0);
        reals(f, knots);
        for (int k = 0; k < n; k++) {
            f.add(real(w == null ? 1 : w[k]));
        }
        for (int k = 0; k < n; k++) {
            f.add(real(pts[2 * k]));
            f.add(real(pts[2 * k + 1]));
            f.add("0.0");
        }
        reals(f, new double[] {from, to, 0, 0, 1});
        return add(new Entity(126, 0, "00010500", "TRIMCRV", f));
    }

    private int add(Entity e) {
        entities.add(e);
        return 2 * entities.size() - 1;
    }

    private static void ints(List<String> f, int... values) {
        for (int v : values) {
            f.add(Integer.toString(v));
        }
    }

    private static void reals(List<String> f, double[] values) {
        for (double v : values) {
            f.add(real(v));
        }
    }

    /** The shortest text that reads back to {@code v}, always with a decimal point (IGES reals). */
    static String real(double v) {
        return Double.toString(v);
    }

    private void emit(Writer out) throws IOException {
        IgesLines lines = new IgesLines(out);
        lines.start("Bezier Tracer IGES export: rational B-spline surfaces and their trims");
        lines.global(List.of("1H,", "1H;", hollerith("Bezier Tracer"), hollerith("model.igs"), hollerith("Bezier Tracer"),
                hollerith("Bezier Tracer"), "32", "38", "6", "308", "17", hollerith("Bezier Tracer"), "1.0", "2",
                hollerith("MM"), "1", "0.0", hollerith(today()), "1.0E-9", "0.0", hollerith(""), hollerith(""), "11",
                "0", hollerith(today())));
        List<List<String>> paramLines = new ArrayList<>();
        for (int k = 0; k < entities.size(); k++) {
            paramLines.add(IgesLines.wrap(entities.get(k).params));
        }
        int pd = 1;
        for (int k = 0; k < entities.size(); k++) {
            Entity e = entities.get(k);
            int count = paramLines.get(k).size();
            lines.directory(e.type, pd, e.status, e.colour, count, e.form, e.label);
            pd += count;
        }
        for (int k = 0; k < entities.size(); k++) {
            lines.parameters(paramLines.get(k), 2 * k + 1);
        }
        lines.terminate();
    }

    private static String hollerith(String s) {
        return s.length() + "H" + s;
    }

    private static String today() {
        return java.time.LocalDateTime.now(java.time.ZoneOffset.UTC)
                .format(java.time.format.DateTimeFormatter.ofPattern("yyyyMMdd.HHmmss", Locale.ROOT));
    }
}
