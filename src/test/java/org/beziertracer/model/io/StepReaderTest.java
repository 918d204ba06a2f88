package org.beziertracer.model.io;

import static org.beziertracer.model.io.IgesReaderTest.coxDeBoor;
import static org.beziertracer.model.io.IgesReaderTest.pieceAt;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.beziertracer.UserMessages;
import org.beziertracer.math.SplineReference;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The STEP reader on fixtures written by an independent Python script
 * ({@code step/make_fixtures.py}): every face's Bézier pieces against direct Cox–de Boor sums
 * of the B-spline read, the analytic surfaces (cylinder, cone, sphere, torus) against their
 * closed forms at the angles the trims name, units, assemblies and one-line errors.
 */
class StepReaderTest {

    static String fixture(String name) throws IOException, URISyntaxException {
        return Files.readString(Path.of(StepReaderTest.class.getResource("/step/" + name).toURI()));
    }

    static IgesReader.Model read(String text, String name) {
        try {
            return StepReader.readModel(TextSource.of(text, name));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    static List<FreeFormSurface> sampler() throws Exception {
        return read(fixture("sampler.stp"), "sampler.stp").surfaces();
    }

    @Test
    void everyFaceWithParameterSpaceTrimsIsReadAndTheOtherIsSkippedWithItsReason() throws Exception {
        IgesReader.Model m = read(fixture("sampler.stp"), "sampler.stp");
        assertEquals(8, m.surfaces().size(), m.surfaces().toString());
        // face 8 is bounded by one 3-D line there and back: projected, it encloses no area
        assertEquals("skipped 1 entity: 1 × face whose trims enclose no area", m.summary());
        Random rnd = new Random(35);
        for (FreeFormSurface s : m.surfaces()) {
            double[] r = s.range();
            for (int k = 0; k < 40; k++) {
                double u = SplineReference.inside(rnd, r[0], r[1]), v = SplineReference.inside(rnd, r[2], r[3]);
                Vec3 a = pieceAt(s, u, v), b = coxDeBoor(s, u, v);
                assertTrue(a.sub(b).length() < 1e-12 * Math.max(1, b.length()), s + " at (" + u + ", " + v + "): "
                        + a + " against " + b);
            }
        }
    }

    @Test
    void theRationalComplexFormAndTheSimpleFormKeepTheirNetsWeightsKnotsAndTrims() throws Exception {
        List<FreeFormSurface> s = sampler();
        FreeFormSurface quarter = s.get(0);
        assertEquals(2, quarter.degreeU());
        assertEquals(1, quarter.degreeV());
        assertArrayEquals(new double[] {0, 0, 0, 1, 1, 1}, quarter.parmU());
        assertArrayEquals(new double[] {1, 1, Math.sqrt(0.5), Math.sqrt(0.5), 1, 1},
                new double[] {quarter.weights()[0], quarter.weights()[3], quarter.weights()[1], quarter.weights()[4],
                        quarter.weights()[2], quarter.weights()[5]});
        assertArrayEquals(new double[] {2, 2, 3}, java.util.Arrays.copyOfRange(quarter.points(), 12, 15), "point (1, 1): row 1 of v");
        TrimLoop square = quarter.trim().outer().get(0);
        assertEquals(4, square.pieces().size());
        assertArrayEquals(new double[] {0.25, 0.25, 0.75, 0.25}, TrimLoop.ends(square.pieces().get(0)), 0);
        Random rnd = new Random(3);
        for (int k = 0; k < 100; k++) {
            Vec3 q = pieceAt(quarter, rnd.nextDouble(), rnd.nextDouble());
            assertEquals(2, Math.hypot(q.x(), q.y()), 1e-12, q.toString());
        }
        // the polynomial surface: its range is the rectangle of trimmed lines, and it is untrimmed
        FreeFormSurface poly = s.get(1);
        assertNull(poly.trim());
        assertNull(poly.weights());
        assertArrayEquals(new double[] {0.5, 2, 0, 1}, poly.range());
        assertArrayEquals(new double[] {0, 0, 0, 0, 2, 2, 2, 2}, poly.parmU());
        assertArrayEquals(new double[] {3, 2, 0.1 * 3 * 2 + 0.05 * 3 * 3}, java.util.Arrays.copyOfRange(poly.points(),
                3 * (2 * 4 + 3), 3 * (2 * 4 + 3) + 3), "point (3, 2)");
    }

    @Test
    void linesOnABSplineSurfaceGetTheirEndsFromTheVerticesProjectedOntoThem() throws Exception {
        FreeFormSurface tri = sampler().get(7);
        assertArrayEquals(new double[] {0, 2, 0, 1}, tri.range(), "the knot range");
        List<TrimPiece> loop = tri.trim().outer().get(0).pieces();
        double[][] corners = {{0.5, 0.2}, {1.8, 0.2}, {1.0, 0.9}};
        assertTrue(loop.size() >= 3, loop.toString());
        for (int k = 0; k < 3; k++) {
            double[] e = TrimLoop.ends(loop.get(loop.size() == 3 ? k : 2 * k));
            assertEquals(corners[k][0], e[0], 1e-9, "corner " + k);
            assertEquals(corners[k][1], e[1], 1e-9, "corner " + k);
        }
    }

    @Test
    void thePlaneKeepsItsRectangleAndItsCircularHole() throws Exception {
        FreeFormSurface plane = sampler().get(2);
        assertArrayEquals(new double[] {0, 4, 0, 3}, plane.range(), "the box of its trims");
        TrimRegion t = plane.trim();
        assertEquals(1, t.outer().size());
        assertEquals(1, t.holes().size());
        assertArrayEquals(new double[] {0, 0, 4, 0}, TrimLoop.ends(t.outer().get(0).pieces().get(0)), 0);
        double[] e = TrimLoop.ends(t.holes().get(0).pieces().get(0));
        assertEquals(1.5, e[0], 1e-15);
        assertEquals(1, e[1], 1e-15);
        Random rnd = new Random(8);
        for (int k = 0; k < 50; k++) {
            double u = 4 * rnd.nextDouble(), v = 3 * rnd.nextDouble();
            Vec3 p = pieceAt(plane, u, v);
            assertEquals(u, p.x(), 1e-12);
            assertEquals(v, p.y(), 1e-12);
            assertEquals(-1, p.z(), 0);
        }
    }

    /** The B-spline surface's u for the file's angle u over [u0, u1] (the reader's map, checked by the closed forms). */
    private static double s(double theta, double u0, double u1) {
        return StepSurface.angleParam(theta, u0, u1);
    }

    @Test
    void theAnalyticSurfacesMatchTheirClosedFormsAtEveryAngle() throws Exception {
        List<FreeFormSurface> f = sampler();
        Random rnd = new Random(42);
        double ca = 0.3, h = Math.PI / 2;
        for (int k = 0; k < 300; k++) {
            double a = rnd.nextDouble(), b = rnd.nextDouble();
            // cylinder: radius 1.5 about (5, 0, z), 0 ≤ z ≤ 2, the whole turn
            double th = 2 * Math.PI * a, z = 2 * b;
            assertClose(new Vec3(5 + 1.5 * Math.cos(th), 1.5 * Math.sin(th), z), pieceAt(f.get(3), s(th, 0, 2 * Math.PI), z));
            // cone: ρ = 1 + v tan 0.3 about (0, 10, z), u in [0, π], v in [0, 2]
            th = Math.PI * a;
            double rho = 1 + z * Math.tan(ca);
            assertClose(new Vec3(rho * Math.cos(th), 10 + rho * Math.sin(th), z), pieceAt(f.get(4), s(th, 0, Math.PI), z));
            // sphere: radius 2 about (0, 0, 10), u in [0, π/2], v in [0, π/4]
            th = h * a;
            double phi = Math.PI / 4 * b;
            assertClose(new Vec3(2 * Math.cos(phi) * Math.cos(th), 2 * Math.cos(phi) * Math.sin(th), 10 + 2 * Math.sin(phi)),
                    pieceAt(f.get(5), s(th, 0, h), s(phi, 0, Math.PI / 4)));
            // torus: R = 3, r = 1 about (10, 10, 0), u and v in [−π/2, π/2]
            th = -h + Math.PI * a;
            phi = -h + Math.PI * b;
            double rr = 3 + Math.cos(phi);
            assertClose(new Vec3(10 + rr * Math.cos(th), 10 + rr * Math.sin(th), Math.sin(phi)),
                    pieceAt(f.get(6), s(th, -h, h), s(phi, -h, h)));
        }
    }

    private static void assertClose(Vec3 expected, Vec3 actual) {
        assertTrue(expected.sub(actual).length() < 1e-12 * Math.max(1, expected.length()),
                "expected " + expected + ", found " + actual);
    }

    @Test
    void trimsOnAnglesBecomeTheBoxOfTheSurfaceExactly() throws Exception {
        List<FreeFormSurface> f = sampler();
        for (int k = 3; k <= 6; k++) {
            FreeFormSurface s = f.get(k);
            double[] r = s.range();
            TrimLoop outer = s.trim().outer().get(0);
            for (TrimPiece p : outer.pieces()) {
                double[] e = TrimLoop.ends(p);
                for (int q = 0; q < 4; q += 2) {
                    assertTrue((e[q] == r[0] || e[q] == r[1]) && (e[q + 1] == r[2] || e[q + 1] == r[3]),
                            s + ": a trim end (" + e[q] + ", " + e[q + 1] + ") off the corners of " + java.util.Arrays.toString(r));
                }
            }
        }
        // the cylinder's seam loop: bottom, seam at 2π, top backwards, seam at 0
        double[] r = f.get(3).range();
        assertArrayEquals(new double[] {0, 4, 0, 2}, r);
        List<TrimPiece> loop = f.get(3).trim().outer().get(0).pieces();
        assertEquals(4, loop.size());
        assertArrayEquals(new double[] {0, 0, 4, 0}, TrimLoop.ends(loop.get(0)), 0);
        assertArrayEquals(new double[] {4, 0, 4, 2}, TrimLoop.ends(loop.get(1)), 0);
        assertArrayEquals(new double[] {4, 2, 0, 2}, TrimLoop.ends(loop.get(2)), 0);
        assertArrayEquals(new double[] {0, 2, 0, 0}, TrimLoop.ends(loop.get(3)), 0);
    }

    @Test
    void aReversedFaceIsTransposedSoItsNormalTurns() throws Exception {
        String text = fixture("sampler.stp");
        int at = text.indexOf("ADVANCED_FACE", text.indexOf("PLANE("));
        int end = text.indexOf(";", at);
        String flipped = text.substring(0, at) + text.substring(at, end).replace(".T.)", ".F.)") + text.substring(end);
        FreeFormSurface plane = sampler().get(2), turned = read(flipped, "part.stp").surfaces().get(2);
        assertArrayEquals(new double[] {0, 3, 0, 4}, turned.range());
        assertArrayEquals(new double[] {0, 0, 0, 4}, TrimLoop.ends(turned.trim().outer().get(0).pieces().get(0)), 0);
        Vec3 du = pieceAt(turned, 0.5, 1).sub(pieceAt(turned, 0, 1)), dv = pieceAt(turned, 0, 1.5).sub(pieceAt(turned, 0, 1));
        assertTrue(du.cross(dv).z() < 0, "the normal points down now");
        assertClose(pieceAt(plane, 2.5, 1), pieceAt(turned, 1, 2.5));
    }

    @Test
    void inchesBecomeMillimetres() throws Exception {
        FreeFormSurface s = read(fixture("inches.stp"), "inches.stp").surfaces().get(0);
        Vec3 corner = pieceAt(s, 1, 1);
        assertEquals(25.4, corner.x(), 1e-12);
        assertEquals(25.4, corner.y(), 1e-12);
    }

    @Test
    void anAssemblyPlacesItsPartByEachTransformationAndTheMappedItem() throws Exception {
        List<FreeFormSurface> s = read(fixture("assembly.stp"), "assembly.stp").surfaces();
        assertEquals(3, s.size(), "two placements in the assembly and one mapped item");
        Vec3 a = pieceAt(s.get(0), 0.25, 0.5), b = pieceAt(s.get(1), 0.25, 0.5), c = pieceAt(s.get(2), 0.25, 0.5);
        assertClose(new Vec3(100.25, 0.5, 0), a);
        assertClose(new Vec3(-0.5, 50.25, 0), b); // turned a quarter about z: (u, v) → (−v, u)
        assertClose(new Vec3(0.25, 0.5, 7), c);
    }

    @Test
    void aFaceInTwoRepresentationsInTheSamePlaceIsDrawnOnce() throws Exception {
        String text = fixture("inches.stp");
        var m = java.util.regex.Pattern.compile("#(\\d+)=SHELL_BASED_SURFACE_MODEL").matcher(text);
        assertTrue(m.find());
        String twice = text.replace("ENDSEC;\nEND-ISO", "#9999=SHAPE_REPRESENTATION('again',(#" + m.group(1)
                + "),#8);\nENDSEC;\nEND-ISO");
        assertEquals(1, read(twice, "part.stp").surfaces().size());
    }

    @Test
    @Timeout(value = 20, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    void aShellThatListsItselfIsReadOnceNotForEver() throws Exception {
        String text = fixture("inches.stp");
        var m = java.util.regex.Pattern.compile("#(\\d+)=OPEN_SHELL\\('',\\((#\\d+)\\)\\)").matcher(text);
        assertTrue(m.find());
        String self = "#" + m.group(1);
        String looped = m.replaceFirst("#$1=OPEN_SHELL('',($2," + self + "," + self + "," + self + "))");
        assertEquals(1, read(looped, "part.stp").surfaces().size());
    }

    @Test
    void anAssemblyThatContainsItselfIsOneLineNotAHang() throws Exception {
        String text = fixture("assembly.stp");
        var m = java.util.regex.Pattern.compile("\\(REPRESENTATION_RELATIONSHIP\\('','',#(\\d+),#(\\d+)\\)"
                + "REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION\\(#(\\d+)\\)").matcher(text);
        assertTrue(m.find());
        String cycle = "#9999=(REPRESENTATION_RELATIONSHIP('','',#" + m.group(1) + ",#" + m.group(1)
                + ")REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(#" + m.group(3) + ")SHAPE_REPRESENTATION_RELATIONSHIP());\n";
        String looped = text.replace("ENDSEC;\nEND-ISO", cycle + "ENDSEC;\nEND-ISO");
        assertEquals("part.stp: assemblies nested more than 32 deep (a cycle through #" + m.group(1) + "?)",
                UserMessages.of(ModelFormatException.class, () -> read(looped, "part.stp")));
    }

    @Test
    void theFormatIsRegisteredForBothExtensions() {
        assertEquals(FileFormats.STEP, FileFormats.find("PART.STEP").orElseThrow());
        assertEquals(FileFormats.STEP, FileFormats.find("part.stp").orElseThrow());
    }

    @Test
    void aBrokenEntityIsOneLineNamingTheFileTheLineAndTheEntity() throws Exception {
        String text = fixture("sampler.stp").replace("B_SPLINE_SURFACE_WITH_KNOTS((3,3)", "B_SPLINE_SURFACE_WITH_KNOTS((3,2)");
        String msg = UserMessages.of(ModelFormatException.class, () -> read(text, "part.stp"));
        assertEquals("part.stp:21: #13 (BOUNDED_SURFACE+B_SPLINE_SURFACE+B_SPLINE_SURFACE_WITH_KNOTS+"
                + "GEOMETRIC_REPRESENTATION_ITEM+RATIONAL_B_SPLINE_SURFACE+REPRESENTATION_ITEM+SURFACE): "
                + "expected u knot multiplicities adding up to 6 (control points + degree + 1), found 5", msg);
        String wrong = fixture("sampler.stp").replaceFirst("CYLINDRICAL_SURFACE\\('',#\\d+,", "CYLINDRICAL_SURFACE('',#1,");
        String m2 = UserMessages.of(ModelFormatException.class, () -> read(wrong, "part.stp"));
        assertTrue(m2.matches("part\\.stp:\\d+: #\\d+ \\(CYLINDRICAL_SURFACE\\): position refers to #1, a "
                + "LENGTH_UNIT\\+NAMED_UNIT\\+SI_UNIT, expected AXIS2_PLACEMENT_3D"), m2);
    }

    @Test
    void aFileWithoutDrawableFacesSaysWhatItHeld() throws Exception {
        String text = StepFileTest.HEAD + "#1=CARTESIAN_POINT('',(0.,0.,0.));\n" + StepFileTest.TAIL;
        assertEquals("part.stp: no surface to draw (STEP ADVANCED_FACE): no faces",
                UserMessages.of(ModelFormatException.class, () -> read(text, "part.stp")));
    }
}
