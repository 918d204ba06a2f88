package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.beziertracer.geometry.TrimCurves;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/**
 * Faces trimmed by 3-D edge curves only ({@link EdgeProjection}): files our writer made, with
 * every pcurve taken out (each edge's geometry its 3-D curve), trim the same region as the
 * pcurves did, at random (u, v) away from a thin band along the trims; and a small hand-written
 * file of a plane and a B-spline face bounded by bare 3-D lines and a circle.
 */
class EdgeProjectionTest {

    private static final Pattern SURFACE_CURVE = Pattern.compile("#(\\d+)=SURFACE_CURVE\\('',(#\\d+),\\(#\\d+\\),\\.PCURVE_S1\\.\\);");

    /** The file with each EDGE_CURVE's SURFACE_CURVE replaced by its 3-D curve: no pcurve is left in use. */
    static String withoutPcurves(String text) {
        Map<String, String> curve3d = new HashMap<>();
        Matcher m = SURFACE_CURVE.matcher(text);
        while (m.find()) {
            curve3d.put("#" + m.group(1), m.group(2));
        }
        StringBuilder out = new StringBuilder();
        for (String line : text.split("\n", -1)) {
            if (line.contains("=EDGE_CURVE(")) {
                Matcher e = Pattern.compile(",(#\\d+),\\.T\\.\\);$").matcher(line);
                assertTrue(e.find(), line);
                line = line.substring(0, e.start()) + "," + curve3d.get(e.group(1)) + ",.T.);";
            }
            out.append(line).append('\n');
        }
        return out.substring(0, out.length() - 1);
    }

    /** The band along the trims (in parameters, relative to the range) where the polyline and the curve may disagree. */
    private static final double BAND = 1e-4;

    @Test
    void facesTrimmedByTheirWrittenEdgeCurvesOnlyTrimLikeThePcurves() {
        Random rnd = new Random(144);
        double[] scratch = new double[TrimCurves.SCRATCH_LENGTH];
        int checked = 0;
        for (int trial = 0; trial < 24; trial++) {
            FreeFormSurface s = StepWriterTest.randomSurface(rnd, 1 + trial % 3);
            String text = StepWriterTest.write(new Scene(s.toPatches()));
            String bare = withoutPcurves(text);
            assertTrue(!bare.equals(text));
            List<FreeFormSurface> exact = StepReaderTest.read(text, "model.stp").surfaces();
            IgesReader.Model model = StepReaderTest.read(bare, "model.stp");
            List<FreeFormSurface> projected = model.surfaces();
            assertEquals(exact.size(), projected.size(), "trial " + trial + ": " + model.skipped());
            for (int f = 0; f < exact.size(); f++) {
                TrimRegion a = exact.get(f).trim(), b = projected.get(f).trim();
                assertNotNull(b, "trial " + trial);
                TrimCurves ta = TrimCurves.of(a), tb = TrimCurves.of(b);
                List<double[]> lines = ta.polylines(400);
                double[] r = exact.get(f).range();
                double size = Math.max(r[1] - r[0], r[3] - r[2]);
                for (int k = 0; k < 400; k++) {
                    double u = r[0] + (r[1] - r[0]) * rnd.nextDouble(), v = r[2] + (r[3] - r[2]) * rnd.nextDouble();
                    if (near(lines, u, v, BAND * size)) {
                        continue;
                    }
                    assertEquals(ta.contains(u, v, scratch), tb.contains(u, v, scratch),
                            "trial " + trial + ", face " + f + " at (" + u + ", " + v + ")");
                    checked++;
                }
                // the projected loops run through the same vertices
                for (int l = 0; l < a.outer().size(); l++) {
                    double[] ea = TrimLoop.ends(a.outer().get(l).pieces().get(0));
                    double[] eb = TrimLoop.ends(b.outer().get(l).pieces().get(0));
                    assertEquals(ea[0], eb[0], 1e-9 * size, "trial " + trial);
                    assertEquals(ea[1], eb[1], 1e-9 * size, "trial " + trial);
                }
            }
        }
        assertTrue(checked > 5000, "checked " + checked);
    }

    private static boolean near(List<double[]> lines, double u, double v, double d) {
        for (double[] l : lines) {
            for (int k = 0; k + 3 < l.length; k += 2) {
                double ax = l[k], ay = l[k + 1], bx = l[k + 2], by = l[k + 3];
                double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
                double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((u - ax) * dx + (v - ay) * dy) / len2));
                if (Math.hypot(ax + t * dx - u, ay + t * dy - v) <= d) {
                    return true;
                }
            }
        }
        return false;
    }

    @Test
    void aHandWrittenFileOfBareThreeDEdgesIsRead() throws Exception {
        Path file = Path.of(EdgeProjectionTest.class.getResource("/step/edges3d.stp").toURI());
        IgesReader.Model m = StepReader.readModel(TextSource.of(Files.readString(file), "edges3d.stp"));
        assertTrue(m.skipped().isEmpty(), "skipped: " + m.skipped());
        List<FreeFormSurface> s = m.surfaces();
        assertEquals(2, s.size());
        double[] scratch = new double[TrimCurves.SCRATCH_LENGTH];
        // the plane: a 4 × 2 rectangle with a hole of radius 0.5 about (1, 1), in the plane's (x, y)
        TrimCurves plane = TrimCurves.of(s.get(0).trim());
        assertTrue(plane.contains(0.2, 0.2, scratch));
        assertTrue(plane.contains(3.5, 1.5, scratch));
        assertTrue(!plane.contains(1.1, 1.1, scratch), "inside the hole");
        assertTrue(!plane.contains(1.0, 1.45, scratch), "inside the hole");
        assertTrue(plane.contains(1.0, 1.55, scratch), "outside the hole");
        // the bilinear B-spline (x = 10 u, y = 10 v): a triangle of lines through (1,1), (9,1), (1,9) in model space
        TrimCurves tri = TrimCurves.of(s.get(1).trim());
        assertTrue(tri.contains(0.2, 0.2, scratch));
        assertTrue(tri.contains(0.11, 0.78, scratch));
        assertTrue(!tri.contains(0.55, 0.5, scratch), "beyond the hypotenuse");
        assertTrue(!tri.contains(0.05, 0.5, scratch), "left of the triangle");
    }

    @Test
    void anIgesTrimmedSurfaceWhoseCurvesAreInModelSpaceOnlyIsProjected() throws Exception {
        Path file = Path.of(EdgeProjectionTest.class.getResource("/iges/edges3d.igs").toURI());
        IgesReader.Model m = IgesReader.readModel(TextSource.of(Files.readString(file), "edges3d.igs"));
        assertTrue(m.skipped().isEmpty(), "skipped: " + m.skipped());
        assertEquals(1, m.surfaces().size());
        TrimRegion t = m.surfaces().get(0).trim();
        assertEquals(1, t.outer().size());
        assertEquals(1, t.holes().size());
        double[] scratch = new double[TrimCurves.SCRATCH_LENGTH];
        TrimCurves c = TrimCurves.of(t);
        // the square (2,2)..(8,8) of x = 10 u, y = 10 v, less the circle of radius 1 about (5,5)
        assertTrue(c.contains(0.3, 0.3, scratch));
        assertTrue(c.contains(0.5, 0.61, scratch), "just outside the hole");
        assertTrue(!c.contains(0.5, 0.59, scratch), "just inside the hole");
        assertTrue(!c.contains(0.19, 0.5, scratch), "left of the square");
        assertTrue(!c.contains(0.5, 0.81, scratch), "above the square");
        // the projected circle lies on the circle to the stated tolerance
        for (double[] line : TrimCurves.of(new TrimRegion(List.of(), t.holes())).polylines(64)) {
            for (int k = 0; k < line.length; k += 2) {
                assertEquals(0.1, Math.hypot(line[k] - 0.5, line[k + 1] - 0.5), 1e-6, "at (" + line[k] + ", " + line[k + 1] + ")");
            }
        }
    }

    /** Every piece of {@code loop} a straight line of two points along u or v. */
    private static void assertIsoLines(TrimLoop loop, String what) {
        for (var piece : loop.pieces()) {
            double[] p = piece.curve().points();
            assertEquals(1, piece.curve().degree(), what);
            assertEquals(4, p.length, what + ": a polyline of " + p.length / 2 + " points, not a line");
            assertTrue(p[0] == p[2] || p[1] == p[3], what + ": neither u nor v constant " + java.util.Arrays.toString(p));
        }
    }

    @Test
    void parallelsAndMeridiansOfRevolvedSurfacesComeOutAsExactIsoParameterLines() throws Exception {
        Path file = Path.of(EdgeProjectionTest.class.getResource("/step/analytic3d.stp").toURI());
        IgesReader.Model m = StepReader.readModel(TextSource.of(Files.readString(file), "analytic3d.stp"));
        // the cylinder: outer band and window, in the B-spline's parameters (the angle mapped onto the arcs)
        TrimRegion cylinder = m.surfaces().get(0).trim();
        assertIsoLines(cylinder.outer().get(0), "cylinder outer loop");
        assertIsoLines(cylinder.holes().get(0), "cylinder window");
        double[] box = new double[] {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY};
        for (var piece : cylinder.holes().get(0).pieces()) {
            double[] p = piece.curve().points();
            for (int k = 0; k < p.length; k += 2) {
                box[0] = Math.min(box[0], p[k]);
                box[1] = Math.max(box[1], p[k]);
                box[2] = Math.min(box[2], p[k + 1]);
                box[3] = Math.max(box[3], p[k + 1]);
            }
        }
        double tight = 1e-12;
        assertEquals(StepSurface.angleParam(2, 0, 2 * Math.PI), box[0], tight);
        assertEquals(StepSurface.angleParam(3, 0, 2 * Math.PI), box[1], tight);
        assertEquals(1, box[2], 0, "the parallel z = 1 exactly");
        assertEquals(2, box[3], 0, "the parallel z = 2 exactly");
        // the sphere patch's parallels and meridians, and the revolution's parallels and seam
        assertIsoLines(m.surfaces().get(1).trim().outer().get(0), "sphere patch");
        assertIsoLines(m.surfaces().get(2).trim().outer().get(0), "revolution band");
        // the tilted circle is no iso-line: a polyline through points of the circle
        TrimLoop hole = m.surfaces().get(1).trim().holes().get(0);
        assertTrue(hole.pieces().get(0).curve().points().length > 40, "the tilted circle's polyline");
        // the IGES 120's window of model-space curves
        Path iges = Path.of(EdgeProjectionTest.class.getResource("/iges/revolved3d.igs").toURI());
        IgesReader.Model cone = IgesReader.readModel(TextSource.of(Files.readString(iges), "revolved3d.igs"));
        assertIsoLines(cone.surfaces().get(0).trim().holes().get(0), "IGES cone window");
    }
}
