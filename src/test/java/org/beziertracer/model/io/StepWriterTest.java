package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.math.SplineReference;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Scene;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/**
 * Scene → STEP → scene gives the same surfaces to the last bit: nets, weights, knots, ranges and
 * trims, for the built-in models and for seeded random rational B-splines with every kind of trim
 * (none, outer loops, holes only, pieces run backwards, parts of a curve).
 */
class StepWriterTest {

    static String write(Scene scene) {
        StringWriter out = new StringWriter();
        try {
            StepWriter.write(out, scene);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toString();
    }

    static List<FreeFormSurface> roundTrip(Scene scene) {
        return StepReaderTest.read(write(scene), "model.stp").surfaces();
    }

    /** The distinct free-form surfaces behind {@code patches}, in order; null for a patch without one. */
    private static List<FreeFormSurface> origins(List<BezierPatch> patches) {
        Map<FreeFormSurface, Boolean> seen = new IdentityHashMap<>();
        List<FreeFormSurface> out = new ArrayList<>();
        for (BezierPatch p : patches) {
            if (p.origin() == null) {
                out.add(null);
            } else if (seen.put(p.origin().surface(), true) == null) {
                out.add(p.origin().surface());
            }
        }
        return out;
    }

    @Test
    void everyBuiltInModelComesBackBitForBit() throws Exception {
        for (BuiltIns.BuiltIn b : BuiltIns.ALL) {
            if (b.holds() != FileFormat.Holds.MODEL) {
                continue;
            }
            List<BezierPatch> patches = b.load().scene().patches();
            List<FreeFormSurface> back = roundTrip(new Scene(patches));
            List<FreeFormSurface> origins = origins(patches);
            assertEquals(origins.size(), back.size(), b.name());
            int patch = 0;
            for (int k = 0; k < origins.size(); k++) {
                if (origins.get(k) != null) {
                    assertEquals(asBSpline(origins.get(k)), back.get(k), b.name() + " surface " + k);
                    patch += origins.get(k).toPatches().size();
                    continue;
                }
                // a Bézier patch comes back as a one-piece B-spline whose piece is the patch
                BezierPatch original = patches.get(patch++), read = back.get(k).toPatches().get(0);
                assertArrayEquals(original.copyNet(), read.copyNet(), 0, b.name() + " patch " + k);
                assertArrayEquals(original.weights(), read.weights(), 0, b.name() + " patch " + k);
                assertEquals(original.domain(), read.domain(), b.name() + " patch " + k);
            }
        }
    }

    /** The same surface with B-spline knot vectors in place of Bézier breakpoints (what STEP holds). */
    static FreeFormSurface asBSpline(FreeFormSurface s) {
        TrimRegion t = s.trim();
        if (t != null) {
            t = new TrimRegion(t.outer().stream().map(StepWriterTest::asBSpline).toList(),
                    t.holes().stream().map(StepWriterTest::asBSpline).toList());
        }
        return new FreeFormSurface(SplineBasis.BSPLINE, s.degreeU(), s.degreeV(), s.basis().knotVector(s.degreeU(), s.parmU()),
                s.basis().knotVector(s.degreeV(), s.parmV()), s.countU(), s.countV(), s.points(), s.weights(), s.range(), t);
    }

    private static TrimLoop asBSpline(TrimLoop loop) {
        return new TrimLoop(loop.pieces().stream().map(p -> new TrimPiece(new TrimCurve(SplineBasis.BSPLINE,
                p.curve().degree(), p.curve().knots(), p.curve().points(), p.curve().weights()), p.from(), p.to())).toList());
    }

    @Test
    void randomRationalBSplinesWithEveryKindOfTrimComeBackBitForBit() {
        Random rnd = new Random(214);
        for (int trial = 0; trial < 60; trial++) {
            FreeFormSurface s = randomSurface(rnd, trial % 5);
            String text = write(new Scene(s.toPatches()));
            List<FreeFormSurface> back;
            try {
                back = StepReaderTest.read(text, "model.stp").surfaces();
            } catch (ModelFormatException e) {
                int line = e.line();
                throw new AssertionError(e.getMessage() + ": " + text.lines().skip(line - 1).findFirst().orElse(""));
            }
            int expected = s.trim() == null || s.trim().outer().isEmpty() ? 1 : s.trim().outer().size();
            assertEquals(expected, back.size(), "trial " + trial + ": " + s);
            if (expected == 1) {
                assertEquals(s, back.get(0), "trial " + trial + ": " + s);
            } else {
                for (int k = 0; k < expected; k++) {
                    TrimRegion one = new TrimRegion(List.of(s.trim().outer().get(k)), s.trim().holes());
                    assertEquals(one, back.get(k).trim(), "trial " + trial + ", outer loop " + k);
                    assertArrayEquals(s.points(), back.get(k).points(), 0);
                }
            }
        }
    }

    /** A random rational B-spline over its knot range (u, v in its knots), trimmed as {@code kind} says. */
    static FreeFormSurface randomSurface(Random rnd, int kind) {
        int p = 1 + rnd.nextInt(4), q = 1 + rnd.nextInt(4);
        int nu = p + 1 + rnd.nextInt(4), nv = q + 1 + rnd.nextInt(4);
        double[] ku = SplineReference.randomKnots(rnd, p, nu, rnd.nextBoolean());
        double[] kv = SplineReference.randomKnots(rnd, q, nv, rnd.nextBoolean());
        double[] pts = new double[3 * nu * nv], w = new double[nu * nv];
        for (int k = 0; k < pts.length; k++) {
            pts[k] = (rnd.nextDouble() - 0.5) * Math.pow(10, rnd.nextInt(7) - 3);
        }
        for (int k = 0; k < w.length; k++) {
            w[k] = 0.1 + 3 * rnd.nextDouble();
        }
        double u0 = ku[p], u1 = ku[nu], v0 = kv[q], v1 = kv[nv];
        double[] range = {u0, u1, v0, v1};
        if (kind == 4) { // untrimmed, a smaller range
            range = new double[] {u0 + (u1 - u0) * rnd.nextDouble() / 3, u1 - (u1 - u0) * rnd.nextDouble() / 3,
                    v0 + (v1 - v0) * rnd.nextDouble() / 3, v1 - (v1 - v0) * rnd.nextDouble() / 3};
        }
        double cu = (u0 + u1) / 2, cv = (v0 + v1) / 2, r = Math.min(u1 - u0, v1 - v0) / 8;
        TrimRegion trim = switch (kind) {
            case 1 -> new TrimRegion(List.of(TrimLoop.polygon(u0 + r, v0 + r, u1 - r, v0 + r, u1 - r, v1 - r, u0 + r, v1 - r)),
                    List.of(TrimLoop.circle(cu, cv, r, false)));
            case 2 -> new TrimRegion(List.of(), List.of(halves(cu, cv, r), reversed(TrimLoop.circle(cu + 2 * r, cv, r / 2, true))));
            case 3 -> new TrimRegion(List.of(TrimLoop.circle(cu - 2 * r, cv, r, true), TrimLoop.circle(cu + 2 * r, cv, r, true)),
                    List.of(TrimLoop.circle(cu - 2 * r, cv, r / 3, true)));
            default -> null;
        };
        return new FreeFormSurface(SplineBasis.BSPLINE, p, q, ku, kv, nu, nv, pts, rnd.nextInt(4) == 0 ? null : w, range, trim);
    }

    /** A circle written as two pieces of one curve, [0, 2] and [2, 4] (a part of a curve each). */
    private static TrimLoop halves(double cu, double cv, double r) {
        TrimCurve c = TrimLoop.circle(cu, cv, r, true).pieces().get(0).curve();
        return new TrimLoop(List.of(new TrimPiece(c, 0, 2), new TrimPiece(c, 2, 4)));
    }

    /** The loop run backwards (each piece {@code from > to}). */
    private static TrimLoop reversed(TrimLoop loop) {
        List<TrimPiece> out = new ArrayList<>();
        for (int k = loop.pieces().size() - 1; k >= 0; k--) {
            TrimPiece p = loop.pieces().get(k);
            out.add(new TrimPiece(p.curve(), p.to(), p.from()));
        }
        return new TrimLoop(out);
    }

    @Test
    void theFileIsAp214WithAProductAndOneShell() {
        String text = write(new Scene(Models.sphere().patches()));
        assertTrue(text.startsWith("ISO-10303-21;\nHEADER;\n"), text.substring(0, 40));
        assertTrue(text.contains("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));"));
        for (String entity : List.of("PRODUCT_DEFINITION_SHAPE(", "SHAPE_DEFINITION_REPRESENTATION(", "OPEN_SHELL(",
                "MANIFOLD_SURFACE_SHAPE_REPRESENTATION(", "RATIONAL_B_SPLINE_SURFACE(", "ADVANCED_FACE(", "PCURVE(",
                "SURFACE_CURVE('',", ".PCURVE_S1.)",
                "SI_UNIT(.MILLI.,.METRE.)")) {
            assertTrue(text.contains(entity), entity);
        }
        assertTrue(text.endsWith("ENDSEC;\nEND-ISO-10303-21;\n"));
        // every edge lies on a surface curve (AP214's advanced face), never on a bare pcurve
        List<String> edges = text.lines().filter(l -> l.contains("=EDGE_CURVE(")).toList();
        assertTrue(edges.size() >= 4, "edges: " + edges.size());
        assertTrue(edges.stream().allMatch(l -> text.contains("#" + l.replaceAll(".*,#(\\d+),\\.T\\.\\);$", "$1") + "=SURFACE_CURVE(")),
                "an edge whose geometry is not a SURFACE_CURVE");
    }

    @Test
    void aMeshIsRefusedWithOneLine() throws Exception {
        Scene withMesh = SceneFiles.load("src/test/resources/fuzz/seeds/obj/" + meshSeed()).scene();
        String msg = UserMessages.of(IllegalArgumentException.class, () -> StepWriter.write(new StringWriter(), withMesh));
        assertTrue(msg.startsWith("the STEP writer saves free-form surfaces only but the model has "), msg);
    }

    private static String meshSeed() throws IOException {
        try (var files = java.nio.file.Files.list(java.nio.file.Path.of("src/test/resources/fuzz/seeds/obj"))) {
            for (java.nio.file.Path f : files.sorted().toList()) {
                if (java.nio.file.Files.readString(f).lines().anyMatch(l -> l.startsWith("f "))) {
                    return f.getFileName().toString();
                }
            }
        }
        throw new AssertionError("no OBJ seed with faces");
    }
}
