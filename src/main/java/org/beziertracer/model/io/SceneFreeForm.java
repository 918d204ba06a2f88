package org.beziertracer.model.io;

import java.util.ArrayList;
import java.util.List;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;

/**
 * The free-form keys of an inline patch in a scene file ({@code docs/scene-file.md}):
 * {@code "weights"} (a rational patch), {@code "domain"} ({@code [u0, u1, v0, v1]}, the patch's
 * part of its surface's parameters) and {@code "trim"}, the trim loops in those parameters:
 * <pre>
 * "trim": { "outer": [LOOP, …], "holes": [LOOP, …] }
 * LOOP:   [ { "curve": CURVE, "from": 0, "to": 4 }, … ]
 * CURVE:  { "basis": "bspline", "degree": 2, "parm": [0, 0, 0, 1, …], "points": [[u, v], …], "weights": [1, …] }
 * </pre>
 * Read with the same checks as the OBJ statements, every error naming its JSON path; written so
 * that reading gives equal patches. Stateless.
 */
final class SceneFreeForm {
    private SceneFreeForm() {}

    /** The inline patch at {@code p} with net {@code net}, and its weights, domain and trim when given. */
    static BezierPatch patch(JsonNode p, int n, int m, double[] net) {
        int count = (n + 1) * (m + 1);
        double[] weights = p.has("weights") ? p.get("weights").asNumbers(count) : null;
        TrimRegion trim = p.has("trim") ? trim(p.get("trim")) : null;
        PatchDomain domain = trim == null ? null : new PatchDomain(0, 1, 0, 1, trim);
        if (p.has("domain")) {
            double[] d = p.get("domain").asNumbers(4);
            domain = SceneReader.build(p.get("domain"), () -> new PatchDomain(d[0], d[1], d[2], d[3], trim));
        }
        PatchDomain dom = domain;
        return SceneReader.build(p.has("weights") ? p.get("weights") : p,
                () -> new BezierPatch(n, m, net, weights, dom, null));
    }

    private static TrimRegion trim(JsonNode t) {
        t.object("outer", "holes");
        List<TrimLoop> outer = loops(t, "outer"), holes = loops(t, "holes");
        return SceneReader.build(t, () -> new TrimRegion(outer, holes));
    }

    private static List<TrimLoop> loops(JsonNode t, String key) {
        List<TrimLoop> out = new ArrayList<>();
        if (!t.has(key)) {
            return out;
        }
        for (JsonNode loop : t.get(key).array()) {
            List<TrimPiece> pieces = new ArrayList<>();
            for (JsonNode piece : loop.array()) {
                piece.object("curve", "from", "to");
                TrimCurve curve = curve(piece.require("curve"));
                double from = piece.require("from").asDouble(), to = piece.require("to").asDouble();
                pieces.add(SceneReader.build(piece, () -> new TrimPiece(curve, from, to)));
            }
            out.add(SceneReader.build(loop, () -> new TrimLoop(pieces)));
        }
        return out;
    }

    private static TrimCurve curve(JsonNode c) {
        c.object("basis", "degree", "parm", "points", "weights");
        JsonNode basisNode = c.require("basis");
        SplineBasis basis = switch (basisNode.asString()) {
            case "bezier" -> SplineBasis.BEZIER;
            case "bspline" -> SplineBasis.BSPLINE;
            default -> throw basisNode.expected("\"bezier\" or \"bspline\"");
        };
        int degree = c.require("degree").asInt();
        double[] parm = numbers(c.require("parm"));
        List<JsonNode> pts = c.require("points").array();
        double[] points = new double[2 * pts.size()];
        for (int k = 0; k < pts.size(); k++) {
            System.arraycopy(pts.get(k).asNumbers(2), 0, points, 2 * k, 2);
        }
        double[] weights = c.has("weights") ? c.get("weights").asNumbers(pts.size()) : null;
        return SceneReader.build(c, () -> new TrimCurve(basis, degree, parm, points, weights));
    }

    private static double[] numbers(JsonNode list) {
        List<JsonNode> items = list.array();
        double[] out = new double[items.size()];
        for (int k = 0; k < out.length; k++) {
            out[k] = items.get(k).asDouble();
        }
        return out;
    }

    /** Adds the free-form keys of {@code p} (those it has) to its inline object {@code o}. */
    static void write(JsonObject o, BezierPatch p) {
        if (p.isRational()) {
            o.add("weights", SceneWriter.numbers(p.weights()));
        }
        PatchDomain d = p.domain();
        if (d.u0() != 0 || d.u1() != 1 || d.v0() != 0 || d.v1() != 1) {
            o.add("domain", SceneWriter.numbers(d.u0(), d.u1(), d.v0(), d.v1()));
        }
        if (p.trim() != null) {
            JsonObject trim = new JsonObject();
            trim.add("outer", loops(p.trim().outer()));
            trim.add("holes", loops(p.trim().holes()));
            o.add("trim", trim);
        }
    }

    private static JsonArray loops(List<TrimLoop> loops) {
        JsonArray out = new JsonArray();
        for (TrimLoop loop : loops) {
            JsonArray pieces = new JsonArray();
            for (TrimPiece piece : loop.pieces()) {
                JsonObject o = new JsonObject();
                o.add("curve", curve(piece.curve()));
                o.add("from", SceneWriter.number(piece.from()));
                o.add("to", SceneWriter.number(piece.to()));
                pieces.add(o);
            }
            out.add(pieces);
        }
        return out;
    }

    private static JsonObject curve(TrimCurve c) {
        JsonObject o = new JsonObject();
        o.addProperty("basis", c.basis().objName());
        o.addProperty("degree", c.degree());
        o.add("parm", SceneWriter.numbers(c.parm()));
        JsonArray points = new JsonArray();
        double[] uv = c.points();
        for (int k = 0; k < uv.length; k += 2) {
            points.add(SceneWriter.numbers(uv[k], uv[k + 1]));
        }
        o.add("points", points);
        if (c.rational()) {
            o.add("weights", SceneWriter.numbers(c.weights()));
        }
        return o;
    }
}
