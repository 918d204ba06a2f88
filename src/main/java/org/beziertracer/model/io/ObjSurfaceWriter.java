package org.beziertracer.model.io;

import java.io.IOException;
import java.io.Writer;
import java.util.BitSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.Mesh;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.PatchOrigin;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * One run of {@link ObjWriter}: numbers vertices, parameter vertices and {@code curv2} curves as
 * it goes and writes {@code cstype} only when it changes.
 *
 * <p>A free-form surface whose Bézier pieces are all in the list, unchanged
 * ({@link BezierPatch#origin()}), is written back as it was read, once, where its first piece
 * is: {@code cstype [rat] bezier|bspline}, its control points (with weights when rational), its
 * {@code parm} values, range and trim loops. Every other patch is written as its own Bézier
 * surface over its {@link PatchDomain} (so a piece keeps its parameters and its trim loops),
 * {@code cstype rat bezier} with {@code v x y z w} when it is rational. Trim curves are written
 * once each, as {@code vp} points and a {@code curv2 … end} block, before the first surface that
 * uses them. A control point several surfaces share (the same bits) is one {@code v} line,
 * written before the first surface that uses it ({@link SharedVertices}). The scene's meshes
 * follow the surfaces as {@code v}, {@code vt}, {@code vn} and {@code f} statements.
 */
final class ObjSurfaceWriter {
    private final Writer out;
    private final StringBuilder sb = new StringBuilder(256);
    private final Map<TrimCurve, Integer> curveNumbers = new IdentityHashMap<>();
    private final SharedVertices shared = new SharedVertices();
    private int nextVertex = 1, nextParamVertex = 1, nextTexture = 1, nextNormal = 1;
    /** The vertex numbers of the surface being written, u fastest. */
    private int[] refs = new int[16];
    private String cstype = "bezier";

    ObjSurfaceWriter(Writer out) {
        this.out = out;
    }

    void write(List<BezierPatch> patches) throws IOException {
        write(patches, List.of(), WriteProgress.NONE);
    }

    /** The patches, then each mesh's vertices and faces ({@link #mesh}). */
    void write(List<BezierPatch> patches, List<Mesh> meshes, WriteProgress progress) throws IOException {
        sb.append("# Bézier Tracer: ").append(patches.size()).append(" Bézier patches");
        if (!meshes.isEmpty()) {
            long triangles = meshes.stream().mapToLong(Mesh::triangleCount).sum();
            sb.append(", ").append(triangles).append(" triangles of faces");
        }
        sb.append('\n');
        sb.append("cstype bezier\n");
        flush();
        Map<FreeFormSurface, BitSet> present = new IdentityHashMap<>();
        for (BezierPatch p : patches) {
            PatchOrigin o = p.origin();
            if (o != null) {
                present.computeIfAbsent(o.surface(), s -> new BitSet()).set(o.piece());
            }
        }
        Map<FreeFormSurface, Boolean> written = new IdentityHashMap<>();
        int number = 1;
        for (BezierPatch p : patches) {
            PatchOrigin o = p.origin();
            if (o != null && present.get(o.surface()).cardinality() == o.pieceCount()) {
                if (written.put(o.surface(), Boolean.TRUE) == null) {
                    surface(o.surface(), number);
                }
            } else {
                patch(p, number);
            }
            progress.patch(number, patches.size());
            number++;
        }
        for (int k = 0; k < meshes.size(); k++) {
            mesh(meshes.get(k), k + 1);
        }
        out.flush();
    }

    /**
     * A mesh as polygon statements: a {@code v} per vertex, a {@code vt} and a {@code vn} per
     * vertex when it has uvs and normals, and an {@code f} per triangle naming each corner's
     * v (and vt, vn) by its 1-based number in the file, so that reading gives the mesh back.
     */
    private void mesh(Mesh m, int number) throws IOException {
        sb.append("# mesh ").append(number).append(": ").append(m.vertexCount()).append(" vertices, ")
                .append(m.triangleCount()).append(" triangles\n");
        int firstV = nextVertex, firstVt = nextTexture, firstVn = nextNormal;
        int n = m.vertexCount();
        for (int k = 0; k < n; k++) {
            sb.append("v ").append(NumberText.format(m.position(k, 0))).append(' ')
                    .append(NumberText.format(m.position(k, 1))).append(' ')
                    .append(NumberText.format(m.position(k, 2))).append('\n');
            flushSome();
        }
        nextVertex += n;
        if (m.hasUvs()) {
            for (int k = 0; k < n; k++) {
                sb.append("vt ").append(NumberText.format(m.uv(k, 0))).append(' ')
                        .append(NumberText.format(m.uv(k, 1))).append('\n');
                flushSome();
            }
            nextTexture += n;
        }
        if (m.hasNormals()) {
            for (int k = 0; k < n; k++) {
                sb.append("vn ").append(NumberText.format(m.normal(k, 0))).append(' ')
                        .append(NumberText.format(m.normal(k, 1))).append(' ')
                        .append(NumberText.format(m.normal(k, 2))).append('\n');
                flushSome();
            }
            nextNormal += n;
        }
        for (int t = 0; t < m.triangleCount(); t++) {
            sb.append('f');
            for (int c = 0; c < 3; c++) {
                int v = m.triangleVertex(t, c);
                sb.append(' ').append(firstV + v);
                if (m.hasUvs() || m.hasNormals()) {
                    sb.append('/');
                    if (m.hasUvs()) {
                        sb.append(firstVt + v);
                    }
                    if (m.hasNormals()) {
                        sb.append('/').append(firstVn + v);
                    }
                }
            }
            sb.append('\n');
            flushSome();
        }
        flush();
    }

    /** Writes the buffer out once it holds a few kilobytes. */
    private void flushSome() throws IOException {
        if (sb.length() > 1 << 14) {
            flush();
        }
    }

    private void patch(BezierPatch p, int number) throws IOException {
        int n = p.degreeU(), m = p.degreeV();
        PatchDomain d = p.domain();
        curves(d.trim());
        sb.append("# patch ").append(number).append('\n');
        cstype(p.isRational() ? "rat bezier" : "bezier");
        double[] net = p.copyNet(), w = p.weights();
        vertices(net, w, p.pointCount());
        sb.append("deg ").append(n).append(' ').append(m).append('\n');
        surf(d.u0(), d.u1(), d.v0(), d.v1(), n + 1, m + 1);
        sb.append("parm u ").append(NumberText.format(d.u0())).append(' ').append(NumberText.format(d.u1()));
        sb.append("\nparm v ").append(NumberText.format(d.v0())).append(' ').append(NumberText.format(d.v1()));
        sb.append('\n');
        trims(d.trim());
        sb.append("end\n");
        flush();
    }

    private void surface(FreeFormSurface s, int number) throws IOException {
        curves(s.trim());
        sb.append("# surface from patch ").append(number).append(": ").append(s).append('\n');
        cstype((s.rational() ? "rat " : "") + s.basis().objName());
        double[] pts = s.points(), w = s.weights(), range = s.range();
        vertices(pts, w, s.countU() * s.countV());
        sb.append("deg ").append(s.degreeU()).append(' ').append(s.degreeV()).append('\n');
        surf(range[0], range[1], range[2], range[3], s.countU(), s.countV());
        values("parm u", s.parmU());
        values("parm v", s.parmV());
        trims(s.trim());
        sb.append("end\n");
        flush();
    }

    /** A {@code surf} line over the vertices just numbered ({@link #vertices}), one row of u per line. */
    private void surf(double u0, double u1, double v0, double v1, int countU, int countV) {
        sb.append("surf ").append(NumberText.format(u0)).append(' ').append(NumberText.format(u1)).append(' ')
                .append(NumberText.format(v0)).append(' ').append(NumberText.format(v1));
        for (int j = 0; j < countV; j++) {
            if (j > 0) {
                sb.append(" \\\n    ");
            }
            for (int i = 0; i < countU; i++) {
                sb.append(' ').append(refs[j * countU + i]);
            }
        }
        sb.append('\n');
    }

    /**
     * Numbers the {@code count} control points into {@link #refs}, writing a {@code v} line for
     * each point not written before (a point patches share is written once).
     */
    private void vertices(double[] xyz, double[] w, int count) {
        if (refs.length < count) {
            refs = new int[count];
        }
        for (int k = 0; k < count; k++) {
            double wk = w == null ? 1 : w[k];
            int number = shared.intern(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2], wk);
            if (number < 0) {
                number = -number;
                sb.append("v ").append(NumberText.format(xyz[3 * k])).append(' ')
                        .append(NumberText.format(xyz[3 * k + 1])).append(' ').append(NumberText.format(xyz[3 * k + 2]));
                if (w != null) {
                    sb.append(' ').append(NumberText.format(wk));
                }
                sb.append('\n');
                nextVertex++;
            }
            refs[k] = number;
        }
    }

    /** The {@code curv2} blocks of the region's curves not written yet. */
    private void curves(TrimRegion region) throws IOException {
        if (region == null) {
            return;
        }
        for (List<TrimLoop> loops : List.of(region.outer(), region.holes())) {
            for (TrimLoop loop : loops) {
                for (TrimPiece piece : loop.pieces()) {
                    if (!curveNumbers.containsKey(piece.curve())) {
                        curve(piece.curve());
                    }
                }
            }
        }
    }

    private void curve(TrimCurve c) throws IOException {
        double[] pts = c.points(), w = c.weights();
        int first = nextParamVertex;
        for (int k = 0; k < c.pointCount(); k++) {
            sb.append("vp ").append(NumberText.format(pts[2 * k])).append(' ').append(NumberText.format(pts[2 * k + 1]));
            if (w != null) {
                sb.append(' ').append(NumberText.format(w[k]));
            }
            sb.append('\n');
            nextParamVertex++;
        }
        cstype((c.rational() ? "rat " : "") + c.basis().objName());
        sb.append("deg ").append(c.degree()).append("\ncurv2");
        for (int k = 0; k < c.pointCount(); k++) {
            sb.append(' ').append(first + k);
        }
        sb.append('\n');
        values("parm u", c.parm());
        sb.append("end\n");
        curveNumbers.put(c, curveNumbers.size() + 1);
        flush();
    }

    private void trims(TrimRegion region) {
        if (region == null) {
            return;
        }
        for (TrimLoop loop : region.outer()) {
            loop("trim", loop);
        }
        for (TrimLoop loop : region.holes()) {
            loop("hole", loop);
        }
    }

    private void loop(String keyword, TrimLoop loop) {
        sb.append(keyword);
        for (TrimPiece piece : loop.pieces()) {
            sb.append(' ').append(NumberText.format(piece.from())).append(' ').append(NumberText.format(piece.to()))
                    .append(' ').append(curveNumbers.get(piece.curve()));
        }
        sb.append('\n');
    }

    private void values(String head, double[] values) {
        sb.append(head);
        for (double x : values) {
            sb.append(' ').append(NumberText.format(x));
        }
        sb.append('\n');
    }

    private void cstype(String type) {
        if (!type.equals(cstype)) {
            sb.append("cstype ").append(type).append('\n');
            cstype = type;
        }
    }

    private void flush() throws IOException {
        out.write(sb.toString());
        sb.setLength(0);
    }
}
