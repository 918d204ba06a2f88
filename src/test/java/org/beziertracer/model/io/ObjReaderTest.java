package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;

import org.beziertracer.UserMessages;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.junit.jupiter.api.Test;

class ObjReaderTest {

    private static final String VERTICES = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\n";
    private static final BezierPatch BILINEAR = new BezierPatch(1, 1, new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1});

    /** The one-line message of the parse error {@code text} must give (checked by {@link UserMessages}). */
    private static String fails(String text, String fileName) {
        return UserMessages.of(ModelFormatException.class, () -> ObjReader.read(text, fileName));
    }

    private static void assertMessage(String msg, String prefix, String... parts) {
        assertTrue(msg.startsWith(prefix), () -> "message should start with \"" + prefix + "\": " + msg);
        for (String part : parts) {
            assertTrue(msg.contains(part), () -> "message should contain \"" + part + "\": " + msg);
        }
        assertTrue(!msg.contains("\n"), () -> "message should be one line: " + msg);
    }

    /** Control grid of (K·n+1)×(L·m+1) points, vertex (i,j) at (i, j, 10i+j), u fastest. */
    private static String grid(int n, int m, int segmentsU, int segmentsV) {
        int pointsU = segmentsU * n + 1, pointsV = segmentsV * m + 1;
        StringBuilder sb = new StringBuilder();
        for (int j = 0; j < pointsV; j++) {
            for (int i = 0; i < pointsU; i++) {
                sb.append("v ").append(i).append(' ').append(j).append(' ').append(10 * i + j).append('\n');
            }
        }
        sb.append("cstype bezier\ndeg ").append(n).append(' ').append(m).append("\nsurf 0 ").append(segmentsU)
                .append(" 0 ").append(segmentsV);
        for (int k = 1; k <= pointsU * pointsV; k++) {
            sb.append(' ').append(k);
        }
        sb.append("\nparm u");
        for (int a = 0; a <= segmentsU; a++) {
            sb.append(' ').append(a);
        }
        sb.append("\nparm v");
        for (int b = 0; b <= segmentsV; b++) {
            sb.append(' ').append(b);
        }
        return sb.append("\nend\n").toString();
    }

    @Test
    void aSingleBicubicSurfaceReadsWithUFastest() {
        List<BezierPatch> patches = ObjReader.read(grid(3, 3, 1, 1), "one.obj");
        assertEquals(1, patches.size());
        BezierPatch p = patches.get(0);
        assertEquals(3, p.degreeU());
        assertEquals(3.0, p.get(3, 0, 0));
        assertEquals(31.0, p.get(3, 1, 2));
    }

    @Test
    void severalParmSegmentsSplitIntoOnePatchPerSegment() {
        int n = 2, m = 1, segmentsU = 2, segmentsV = 3;
        String text = grid(n, m, segmentsU, segmentsV);
        List<BezierPatch> patches = ObjReader.read(text, "segments.obj");
        assertEquals(segmentsU * segmentsV, patches.size(), text);
        for (int b = 0; b < segmentsV; b++) {
            for (int a = 0; a < segmentsU; a++) {
                BezierPatch p = patches.get(b * segmentsU + a);
                assertEquals(n, p.degreeU());
                assertEquals(m, p.degreeV());
                for (int j = 0; j <= m; j++) {
                    for (int i = 0; i <= n; i++) {
                        int gi = a * n + i, gj = b * m + j;
                        String where = "segment (" + a + "," + b + ") point (" + i + "," + j + ")";
                        assertEquals(gi, p.get(i, j, 0), where);
                        assertEquals(gj, p.get(i, j, 1), where);
                        assertEquals(10 * gi + gj, p.get(i, j, 2), where);
                    }
                }
            }
        }
    }

    @Test
    void neighbouringSegmentsShareTheirBoundaryRow() {
        List<BezierPatch> patches = ObjReader.read(grid(3, 3, 2, 1), "shared.obj");
        for (int j = 0; j <= 3; j++) {
            for (int c = 0; c < 3; c++) {
                assertEquals(patches.get(0).get(3, j, c), patches.get(1).get(0, j, c), "row " + j);
            }
        }
    }

    @Test
    void negativeIndicesAndSlashFormsAndContinuationsAreRead() throws URISyntaxException, java.io.IOException {
        Path file = Path.of(getClass().getResource("mixed.obj").toURI());
        assertEquals(List.of(BILINEAR), FileFormats.OBJ.read(file).scene().patches());
    }

    @Test
    void negativeIndicesCountFromTheVerticesDefinedSoFar() {
        String text = VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 -4 -3 -2 -1\nend\nv 9 9 9\n";
        assertEquals(List.of(BILINEAR), ObjReader.read(text, "neg.obj"));
    }

    @Test
    void aSurfWithoutParmIsOneSegment() {
        assertEquals(List.of(BILINEAR),
                ObjReader.read(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1/1 2/2/2 3//3 4\nend\n", "p.obj"));
    }

    @Test
    void commentsAreIgnoredEvenAtTheEndOfALine() {
        String text = "# header\n" + VERTICES + "cstype bezier # type\ndeg 1 1\n"
                + "surf 0 1 0 1 1 2 \\  # continued\n 3 4\nend # done\n";
        assertEquals(List.of(BILINEAR), ObjReader.read(text, "c.obj"));
    }

    @Test
    void aVertexIndexOutOfRangeNamesItsLine() {
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 17\nend\n", "range.obj"),
                "range.obj:7: ", "expected a vertex index for control point 4 of the surf in 1..4 or -4..-1",
                "found \"17\"");
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 -5\nend\n", "range.obj"),
                "range.obj:7: ", "found \"-5\"");
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 0 1 2 3\nend\n", "range.obj"),
                "range.obj:7: ", "control point 1", "found \"0\"");
        assertMessage(fails("cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", "none.obj"),
                "none.obj:3: ", "no vertex (v) is defined");
    }

    @Test
    void theWrongNumberOfControlPointsIsAnError() {
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3\nend\n", "count.obj"),
                "count.obj:7: ", "expected 4 control-point indices for a degree 1x1 surf", "found 3");
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 2 0 1 1 2 3 4\nparm u 0 1 2\nend\n",
                "count.obj"), "count.obj:7: ", "expected 6 control-point indices", "2x1 segments");
    }

    @Test
    void unsupportedElementsGiveAnUnsupportedErrorWithTheLine() {
        String[][] cases = {
                {"cstype bmatrix\n", "unsupported: cstype bmatrix"},
                {"cstype rat cardinal\n", "unsupported: cstype rat cardinal"},
                {"cstype taylor\n", "unsupported: cstype taylor"},
                {"bmat u 1 0 0 1\n", "unsupported: bmat"},
        };
        for (String[] c : cases) {
            assertMessage(fails(VERTICES + c[0], "u.obj"), "u.obj:5: ", c[1]);
        }
    }

    @Test
    void aSurfaceRestrictedToPartOfItsParmRangeIsThatPartOfThePatch() {
        String text = VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 0.5 0 1 1 2 3 4\nparm u 0 1\nparm v 0 1\nend\n";
        BezierPatch p = ObjReader.read(text, "part.obj").get(0);
        assertEquals(new PatchDomain(0, 0.5, 0, 1, null), p.domain());
        assertArrayEquals(new double[] {0, 0, 0, 0.5, 0, 0, 0, 1, 0, 0.5, 1, 0.5}, p.copyNet());
        // beyond the parm range it is an error naming the surf line
        String wide = VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1.25 1 2 3 4\nend\n";
        assertMessage(fails(wide, "part.obj"), "part.obj:7: ", "surf range v[0,1.25] inside the parameter range [0,1]");
    }

    @Test
    void aFileWithoutSurfacesOrFacesIsAnError() {
        assertMessage(fails(VERTICES + "l 1 2\n", "poly.obj"), "poly.obj:5: ", "expected at least one Bézier surface",
                "or face (f)", "found none");
        assertMessage(fails("", "empty.obj"), "empty.obj:1: ", "expected at least one Bézier surface",
                "found an empty file");
    }

    @Test
    void aTruncatedSurfIsAnError() {
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 3 4\nparm u 0 1\n", "cut.obj"),
                "cut.obj:8: ", "expected end for the surf at line 7", "found end of file");
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 1 2 \\\n", "cut.obj"),
                "cut.obj:7: ", "expected end for the surf at line 7", "found end of file");
    }

    @Test
    void badVerticesAndDegreesNameTheirLine() {
        assertMessage(fails("v 0 0 0\nv 1 abc 0\n", "v.obj"), "v.obj:2: ",
                "expected a number for the y coordinate of vertex 2", "found \"abc\"");
        assertMessage(fails("v 0 0 0\nv 1 NaN 0\n", "v.obj"), "v.obj:2: ",
                "expected a finite number for the y coordinate of vertex 2", "found \"NaN\"");
        assertMessage(fails("v 0 0 inf\n", "v.obj"), "v.obj:1: ", "expected a finite number for the z coordinate");
        assertMessage(fails("v 0 0\n", "v.obj"), "v.obj:1: ", "expected 3 coordinates", "found 2 values");
        assertMessage(fails("cstype bezier\ndeg 40 3\n", "d.obj"), "d.obj:2: ", "degree 40 out of range 1..15");
        assertMessage(fails("cstype bezier\ndeg 3 -1\n", "d.obj"), "d.obj:2: ", "degree -1 out of range 1..15");
        assertMessage(fails(VERTICES + "cstype bezier\ndeg 1\nsurf 0 1 0 1 1 2 3 4\nend\n", "d.obj"), "d.obj:7: ",
                "expected deg n m (two degrees) before surf");
        assertMessage(fails(VERTICES + "deg 1 1\nsurf 0 1 0 1 1 2 3 4\nend\n", "d.obj"), "d.obj:6: ",
                "expected cstype bezier or bspline before surf");
    }

    @Test
    void anUnknownStatementIsAnError() {
        assertMessage(fails("v 0 0 0\nvertex 1 2 3\n", "k.obj"), "k.obj:2: ", "expected an OBJ statement",
                "found \"vertex\"");
    }

    @Test
    void errorLinesPointAtTheFirstLineOfAContinuedStatement() {
        String text = VERTICES + "cstype bezier\ndeg 1 1\nsurf 0 1 0 1 \\\n 1 2 \\\n 3 99\nend\n";
        assertMessage(fails(text, "cont.obj"), "cont.obj:7: ", "found \"99\"");
    }

    @Test
    void theWeightOfAVertexIsReadButIgnored() {
        BezierPatch p = ObjReader.read("v 0 0 0 1\nv 1 0 0 2\nv 0 1 0\nv 1 1 1\ncstype bezier\ndeg 1 1\n"
                + "surf 0 1 0 1 1 2 3 4\nend\n", "w.obj").get(0);
        assertArrayEquals(BILINEAR.copyNet(), p.copyNet());
    }
}
