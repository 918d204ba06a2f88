package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/** Rational, B-spline and trimmed surfaces in OBJ files: reading, malformed input, writing back. */
class ObjFreeFormTest {

    private static final double H = Math.sqrt(0.5);

    /** A unit square plate (bilinear) trimmed to [0.25,0.75]² with a circular hole of radius 0.1. */
    static final String TRIMMED = """
            v -1 -1 0
            v 1 -1 0
            v -1 1 0
            v 1 1 0
            vp 0.25 0.25
            vp 0.75 0.25
            vp 0.75 0.75
            vp 0.25 0.75
            cstype bspline
            deg 1
            curv2 1 2 3 4 1
            parm u 0 0 1 2 3 4 4
            end
            """ + circleCurve(0.5, 0.5, 0.1) + """
            cstype bezier
            deg 1 1
            surf 0 1 0 1 1 2 3 4
            trim 0 4 1
            hole 0 1 -1
            end
            """;

    /** The rational quadratic B-spline circle as vp points and a curv2 block. */
    static String circleCurve(double cx, double cy, double r) {
        double[] unit = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
        StringBuilder sb = new StringBuilder();
        for (int k = 0; k < 9; k++) {
            sb.append("vp ").append(cx + r * unit[2 * k]).append(' ').append(cy + r * unit[2 * k + 1]).append(' ')
                    .append(k % 2 == 0 ? 1 : H).append('\n');
        }
        return sb.append("cstype rat bspline\ndeg 2\ncurv2 -9 -8 -7 -6 -5 -4 -3 -2 -1\n")
                .append("parm u 0 0 0 0.25 0.25 0.5 0.5 0.75 0.75 1 1 1\nend\n").toString();
    }

    /** A NURBS unit sphere: degree 2x2, 9x5 points, 4x2 rational Bézier pieces, u in [0,4], v in [0,2]. */
    static String sphere() {
        double[] circle = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
        double[] profile = {0, -1, 1, -1, 1, 0, 1, 1, 0, 1};
        StringBuilder sb = new StringBuilder();
        for (int j = 0; j < 5; j++) {
            for (int i = 0; i < 9; i++) {
                double w = (i % 2 == 0 ? 1 : H) * (j % 2 == 0 ? 1 : H);
                sb.append("v ").append(profile[2 * j] * circle[2 * i]).append(' ').append(profile[2 * j] * circle[2 * i + 1])
                        .append(' ').append(profile[2 * j + 1]).append(' ').append(w).append('\n');
            }
        }
        sb.append("cstype rat bspline\ndeg 2 2\nsurf 0 4 0 2");
        for (int k = 1; k <= 45; k++) {
            sb.append(' ').append(k);
        }
        return sb.append("\nparm u 0 0 0 1 1 2 2 3 3 4 4 4\nparm v 0 0 0 1 1 2 2 2\nend\n").toString();
    }

    @Test
    void aNurbsSphereReadsAsRationalPiecesInItsKnotRange() {
        List<BezierPatch> pieces = ObjReader.read(sphere(), "sphere.obj");
        assertEquals(8, pieces.size());
        FreeFormSurface s = pieces.get(0).origin().surface();
        assertTrue(s.rational());
        assertEquals(SplineBasis.BSPLINE, s.basis());
        for (BezierPatch p : pieces) {
            assertTrue(p.isRational());
            assertEquals(2, p.degreeU());
            assertSame(s, p.origin().surface());
        }
        assertEquals(new PatchDomain(3, 4, 1, 2, null), pieces.get(7).domain());
    }

    @Test
    void trimCurvesHolesAndNegativeCurveIndicesAreRead() {
        List<BezierPatch> patches = ObjReader.read(TRIMMED, "plate.obj");
        assertEquals(1, patches.size());
        TrimRegion trim = patches.get(0).trim();
        assertNotNull(trim);
        assertEquals(1, trim.outer().size());
        assertEquals(1, trim.holes().size());
        TrimCurve square = trim.outer().get(0).pieces().get(0).curve();
        TrimCurve circle = trim.holes().get(0).pieces().get(0).curve();
        assertEquals(SplineBasis.BSPLINE, square.basis());
        assertNull(square.weights());
        assertTrue(circle.rational());
        assertEquals(9, circle.pointCount());
    }

    @Test
    void readWriteReadGivesTheSameSurfacesAndPatches() {
        for (String text : List.of(sphere(), TRIMMED, ObjReaderTestGrid.GRID)) {
            List<BezierPatch> first = ObjReader.read(text, "a.obj");
            String written = ObjWriter.toString(first);
            List<BezierPatch> second = ObjReader.read(written, "b.obj");
            assertEquals(first, second, written);
            assertEquals(first.get(0).origin().surface(), second.get(0).origin().surface(), written);
            assertEquals(written, ObjWriter.toString(second), "writing is stable");
        }
    }

    @Test
    void theOriginalBSplineIsWrittenBackNotItsPieces() {
        String written = ObjWriter.toString(ObjReader.read(sphere(), "sphere.obj"));
        assertTrue(written.contains("cstype rat bspline\n"), written);
        assertTrue(written.contains("parm u 0 0 0 1 1 2 2 3 3 4 4 4\n"), written);
        assertEquals(1, written.split("\nsurf ").length - 1, written);
    }

    @Test
    void anEditedPieceIsWrittenAsARationalBezierPieceWithItsDomainAndTrims() {
        List<BezierPatch> pieces = new ArrayList<>(ObjReader.read(sphere(), "sphere.obj"));
        pieces.set(2, pieces.get(2).withPoint(1, 1, 0.5, 0.5, 0.5));
        String written = ObjWriter.toString(pieces);
        List<BezierPatch> back = ObjReader.read(written, "edited.obj");
        assertEquals(pieces, back);
        assertEquals(8, written.split("\nsurf ").length - 1, "every piece on its own now:\n" + written);
        assertTrue(written.contains("cstype rat bezier\n"), written);

        List<BezierPatch> plate = new ArrayList<>(ObjReader.read(TRIMMED, "plate.obj"));
        plate.set(0, plate.get(0).withPoint(0, 0, -1, -1, 0.25));
        List<BezierPatch> plateBack = ObjReader.read(ObjWriter.toString(plate), "plate2.obj");
        assertEquals(plate, plateBack);
        assertNotNull(plateBack.get(0).trim());
    }

    // ------------------------------------------------------------------ malformed input

    private static void fails(String text, String where, String... parts) {
        ModelFormatException e = assertThrows(ModelFormatException.class, () -> ObjReader.read(text, "bad.obj"),
                () -> "expected an error for:\n" + text);
        String msg = e.getMessage();
        assertTrue(msg.startsWith("bad.obj:" + where + ": "), () -> "expected bad.obj:" + where + ": … but got " + msg);
        for (String part : parts) {
            assertTrue(msg.contains(part), () -> "expected \"" + part + "\" in: " + msg);
        }
        assertTrue(!msg.contains("\n") && !msg.contains("null") && !msg.contains("Exception"), msg);
    }

    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";

    @Test
    void badWeightsNameTheirLine() {
        fails("v 0 0 0 0\n", "1", "expected a positive weight for vertex 1", "found \"0\"");
        fails("v 0 0 0\nv 0 0 0 -2\n", "2", "positive weight for vertex 2");
        fails("v 0 0 0 NaN\n", "1", "expected a finite number for the weight of vertex 1");
        fails("v 0 0 0 1e999\n", "1", "finite number for the weight");
        fails("vp 0 0 -1\n", "1", "expected a positive weight for parameter vertex 1");
        fails("vp 0 0 inf\n", "1", "finite number for the weight of parameter vertex 1");
    }

    @Test
    void badKnotVectorsNameTheParmLine() {
        String head = SQUARE + "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\n";
        fails(head + "parm u 0 0 1 0.5\nparm v 0 0 1 1\nend\n", "8", "knots that never decrease", "\"0.5\" after \"1\"");
        fails(head + "parm u 0 0 0 1 1\nparm v 0 0 1 1\nend\n", "8", "at most degree + 1 = 2 times", "\"0\" 3 times");
        fails(head + "parm u 0 0 1 1 1\nparm v 0 0 1 1\nend\n", "8", "at most degree + 1 = 2 times");
        // a surface's point count and knot vectors must agree: the surf line says how
        fails(head + "parm u 0 0 0.5 1 1\nparm v 0 0 1 1\nend\n", "7", "(5−1−1)·(4−1−1) = 6 control-point indices",
                "found 4", "wrong length");
        // a curve's knot vector: the parm line
        fails("vp 0 0\nvp 1 0\nvp 1 1\ncstype bspline\ndeg 1\ncurv2 1 2 3\nparm u 0 0 1 1\nend\n" + SQUARE,
                "7", "parm u: expected 5 knots (3 control points + degree 1 + 1), found 4");
        fails(SQUARE + "cstype bspline\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm v 0 0 1 1\nend\n", "7",
                "expected parm u (the knot vector)");
    }

    @Test
    void aSurfRangeOutsideTheKnotsIsAnError() {
        fails(SQUARE + "cstype bspline\ndeg 1 1\nsurf -1 1 0 1 1 2 3 4\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n", "7",
                "surf range u[-1,1] inside the parameter range [0,1] of parm u", "found it outside");
        fails(SQUARE + "cstype bspline\ndeg 1 1\nsurf 0 1 1 1 1 2 3 4\nparm u 0 0 1 1\nparm v 0 0 1 1\nend\n", "7",
                "found it empty");
    }

    @Test
    void trimProblemsNameTheTrimLine() {
        String curves = "vp 0.2 0.2\nvp 0.8 0.2\nvp 0.8 0.8\ncstype bezier\ndeg 1\ncurv2 1 2\nend\ncurv2 2 3\nend\n";
        String surf = SQUARE + "deg 1 1\nsurf 0 1 0 1 1 2 3 4\n";
        fails(curves + surf + "trim 0 1 1 0 1 2\nend\n", "16", "expected a closed trim loop", "gap of");
        fails(curves + surf + "trim 0 1 1 0 1 3\nend\n", "16", "curv2 index in 1..2 or -2..-1", "index out of range");
        fails(curves + surf + "trim 0 1 1 0 1 -3\nend\n", "16", "index out of range");
        fails(curves + surf + "trim 0 2 1\nend\n", "16", "curve 1 (curv2 1) of the trim",
                "inside [0.0, 1.0]");
        fails(curves + surf + "trim 0 1 1 0 1\nend\n", "16", "one or more triples");
        fails(curves + SQUARE + "trim 0 1 1\n", "14", "expected trim inside a surf … end block");
    }

    @Test
    void aTrimBeforeItsCurv2IsNamedAsSuch() {
        String surf = SQUARE + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\ntrim 0 1 1 0 1 2\nend\n";
        String later = "vp 0.2 0.2\nvp 0.8 0.2\ndeg 1\ncurv2 1 2\nend\ncurv2 2 1\nend\n";
        fails(surf + later, "8", "curv2 1, which is defined only after it");
        fails(surf, "8", "no curv2 is defined before this line", "\"1\"", "the file has 0 curv2 statements");
    }

    @Test
    void curveStatementsNeedACurveDegreeAndABlock() {
        fails("vp 0 0\nvp 1 1\ncstype bezier\ncurv2 1 2\nend\n", "4", "expected deg n before curv2, found no deg statement");
        fails("vp 0 0\nvp 1 1\ncstype bezier\ndeg 1\ncurv2 1 3\nend\n", "5",
                "parameter-vertex index for control point 2 of the curv2 in 1..2");
        fails("vp 0 0\nvp 1 1\ncstype bezier\ndeg 1\ncurv2 1 2\nparm v 0 1\nend\n", "6", "expected parm u followed");
        fails("vp 0 0\ncstype rat bezier extra\n", "2", "expected cstype [rat] bezier|bspline");
        fails("vp 0 0 0 0\n", "1", "expected u v (and an optional weight) after vp");
    }

    @Test
    void aSurfaceDegreeBeforeACurv2GivesTheCurveItsUDegree() {
        // the spec asks only the first degree of a curve and reads on (CAD tools leave deg 1 1 standing)
        String curves = "vp 0.2 0.2\nvp 0.8 0.2\nvp 0.8 0.8\nvp 0.2 0.8\ncstype bezier\ndeg 1 1\n"
                + "curv2 1 2 3 4 1\nparm u 0 1 2 3 4\nend\n";
        String surf = SQUARE + "surf 0 1 0 1 1 2 3 4\ntrim 0 4 1\nend\n";
        BezierPatch p = ObjReader.read(curves + surf, "deg.obj").get(0);
        assertEquals(1, p.domain().trim().outer().get(0).pieces().get(0).curve().degree());
        // deg 2 2: a quadratic curve of 3 points
        String quadratic = "vp 0.2 0.2\nvp 0.8 0.2\nvp 0.8 0.8\ncstype bezier\ndeg 2 2\ncurv2 1 2 3\nend\n";
        assertEquals(1, ObjReader.readModel(quadratic + SQUARE + "deg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", "q.obj")
                .patches().size());
    }

    @Test
    void aOneDimensionalParameterVertexIsUnsupportedNotMalformed() {
        fails("vp 0.5\n", "1", "unsupported: vp u (1-D parameter vertices)");
        fails("vp 0.5 1\nvp 0.25\n", "2", "unsupported: vp u (1-D parameter vertices)");
    }

    @Test
    void supersededGeometryStatementsAreNamedAsSuch() {
        for (String keyword : new String[] {"bsp", "bzp", "cdc", "cdp", "res"}) {
            ModelFormatException e = assertThrows(ModelFormatException.class,
                    () -> ObjReader.read("v 0 0 0\n" + keyword + " 1 2\n", "old.obj"));
            String msg = e.getMessage();
            assertTrue(msg.startsWith("old.obj:2: unsupported: " + keyword + " (a superseded geometry statement"), msg);
            assertFalse(msg.contains("attribute"), msg);
        }
    }

    @Test
    void aKnotRepeatedTooOftenIsCountedWhole() {
        String net = SQUARE + "cstype bspline\ndeg 1 3\n";
        // six times -2.00 in parm v of a cubic direction: the whole run is counted, not the first too many
        fails(net + "surf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1\nparm v -2.00 -2.00 -2.00 -2.00 -2.00 -2.00 1 1\nend\n",
                "9", "expected each knot at most degree + 1 = 4 times in parm v, found \"-2.00\" 6 times");
        fails(net + "surf 0 1 0 1 1 2 3 4\nparm u 0 0 1 1\nparm v 0 1 1 1 1 1\nend\n",
                "9", "at most degree + 1 = 4 times in parm v, found \"1\" 5 times");
    }
}
