package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;

import org.beziertracer.geometry.Patches;
import org.beziertracer.math.SplineReference;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.api.Test;

/**
 * The IGES reader on {@code iges/sampler.igs}, written by an independent Python script
 * ({@code make_fixtures.py}) with one entity of each kind: every surface is checked against its
 * closed form (a cylinder, a cone-free tabulated quarter cylinder, planes) and, at random
 * (u, v), the Bézier pieces against direct Cox–de Boor sums of the B-spline it read.
 */
class IgesReaderTest {

    private static IgesReader.Model sampler() throws IOException, URISyntaxException {
        return read(Path.of(IgesReaderTest.class.getResource("/iges/sampler.igs").toURI()));
    }

    private static IgesReader.Model read(Path file) throws IOException {
        return IgesReader.readModel(TextSource.of(Files.readString(file), file.getFileName().toString()));
    }

    static IgesReader.Model read(String text) {
        try {
            return IgesReader.readModel(TextSource.of(text, "part.igs"));
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** The surface point at (u, v) of the surface's own parameters, through its Bézier pieces. */
    static Vec3 pieceAt(FreeFormSurface s, double u, double v) {
        for (BezierPatch p : s.toPatches()) {
            var d = p.domain();
            if (u >= d.u0() && u <= d.u1() && v >= d.v0() && v <= d.v1()) {
                return Patches.evaluate(p, (u - d.u0()) / (d.u1() - d.u0()), (v - d.v0()) / (d.v1() - d.v0()));
            }
        }
        throw new AssertionError("no piece holds (" + u + ", " + v + ")");
    }

    /** The same point by Cox–de Boor on the knots, points and weights read. */
    static Vec3 coxDeBoor(FreeFormSurface s, double u, double v) {
        double[] h = SplinePoint.homogeneous(s.points(), s.weights());
        double[] r = SplineReference.surface(s.basis().knotVector(s.degreeU(), s.parmU()), s.degreeU(),
                s.basis().knotVector(s.degreeV(), s.parmV()), s.degreeV(), s.countU(), s.countV(), h, 4, u, v);
        return new Vec3(r[0] / r[3], r[1] / r[3], r[2] / r[3]);
    }

    @Test
    void theSkippedSummaryIsTheDocumentsNoteNamingTheFile() throws Exception {
        Path file = Path.of(IgesReaderTest.class.getResource("/iges/sampler.igs").toURI());
        assertEquals(java.util.List.of(file + ": skipped 2 entities: 1 × 116 (point), 1 × 212 (note)"),
                FileFormats.IGES.read(file).notes());
    }

    @Test
    void everySurfaceOfTheSamplerIsReadWithItsMatrixColourAndTrims() throws Exception {
        IgesReader.Model m = sampler();
        // 128 in a 124, 144, 120, 122, the 128 of the 408 instance, 108
        assertEquals(6, m.surfaces().size(), m.surfaces().toString());
        assertEquals("skipped 2 entities: 1 × 116 (point), 1 × 212 (note)", m.summary());
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
    void closedFormsHold() throws Exception {
        List<FreeFormSurface> s = sampler().surfaces();
        Random rnd = new Random(5);
        for (int k = 0; k < 200; k++) {
            double u = rnd.nextDouble(), v = rnd.nextDouble();
            // the quarter cylinder of radius 2, height 3, moved by (10, 0, 0) by its 124
            Vec3 q = pieceAt(s.get(0), u, v);
            assertEquals(2, Math.hypot(q.x() - 10, q.y()), 1e-12);
            assertTrue(q.z() >= 0 && q.z() <= 3 && q.x() >= 10 - 1e-12 && q.y() >= -1e-12, q.toString());
            // 120: the line x = 1, 0 ≤ z ≤ 2 turned about the z axis: the cylinder of radius 1
            double[] r = s.get(2).range();
            Vec3 c = pieceAt(s.get(2), r[0] + u * (r[1] - r[0]), r[2] + v * (r[3] - r[2]));
            assertEquals(1, Math.hypot(c.x(), c.y()), 1e-12, c.toString());
            assertTrue(c.z() >= -1e-12 && c.z() <= 2 + 1e-12);
            // 122: the quarter arc of radius 3 swept up by 4
            Vec3 t = pieceAt(s.get(3), u, v);
            assertEquals(3, Math.hypot(t.x(), t.y()), 1e-12, t.toString());
            assertEquals(4 * v, t.z(), 1e-12);
            // 408: the unit square scaled by 2 and moved up by 100
            Vec3 i = pieceAt(s.get(4), u, v);
            assertEquals(100, i.z(), 0);
            assertEquals(2 * u, i.x(), 1e-12);
            assertEquals(2 * v, i.y(), 1e-12);
            // 108: the plane z = −1
            double[] pr = s.get(5).range();
            assertEquals(-1, pieceAt(s.get(5), pr[0] + u * (pr[1] - pr[0]), pr[2] + v * (pr[3] - pr[2])).z(), 1e-12);
        }
        // the 120 turns a whole turn: its first and last v rows meet
        double[] r = s.get(2).range();
        assertTrue(pieceAt(s.get(2), r[0], r[2]).sub(pieceAt(s.get(2), r[0], r[3])).length() < 1e-12);
    }

    @Test
    void theTrimmedSurfaceKeepsItsSquareOuterLoopItsCircularHoleAndItsColour() throws Exception {
        IgesReader.Model m = sampler();
        FreeFormSurface plate = m.surfaces().get(1);
        TrimRegion trim = plate.trim();
        assertNotNull(trim);
        assertEquals(1, trim.outer().size());
        assertEquals(1, trim.holes().size());
        TrimLoop outer = trim.outer().get(0);
        assertEquals(4, outer.pieces().size(), "the 102's four lines");
        assertArrayEquals(new double[] {1, 1, 3, 1}, TrimLoop.ends(outer.pieces().get(0)), 0);
        double[] hole = TrimLoop.ends(trim.holes().get(0).pieces().get(0));
        assertArrayEquals(new double[] {2.5, 2, 2.5, 2}, hole, 1e-15, "a full circle starts and ends at (2.5, 2)");
        var material = m.materials().get(m.surfaceMaterial().get(1));
        assertArrayEquals(new double[] {0.5, 0.25, 1}, new double[] {material.r(), material.g(), material.b()}, 0);
        assertEquals(0, m.surfaceMaterial().get(0), "no colour: the default material");
        assertNull(m.surfaces().get(0).trim());
        // the bounded plane's trim is its circle of radius 1 around the origin, in the plane's frame
        TrimLoop disk = m.surfaces().get(5).trim().outer().get(0);
        double[] e = TrimLoop.ends(disk.pieces().get(0));
        assertEquals(1, Math.hypot(e[0], e[1]), 1e-15);
    }

    @Test
    void unitsAndModelScaleGiveMillimetres() throws Exception {
        // inches (25.4 mm) at model scale 2: a model unit is 12.7 mm
        FreeFormSurface s = read(Path.of(IgesReaderTest.class.getResource("/iges/inches.igs").toURI())).surfaces().get(0);
        Vec3 corner = pieceAt(s, 1, 1);
        assertEquals(12.7, corner.x(), 1e-12);
        assertEquals(12.7, corner.y(), 1e-12);
    }

    @Test
    void theFormatIsRegisteredForBothExtensions() throws Exception {
        Path file = Path.of(IgesReaderTest.class.getResource("/iges/sampler.igs").toURI());
        assertEquals(FileFormats.IGES, FileFormats.find("PART.IGES").orElseThrow());
        var doc = SceneFiles.load(file.toString());
        long pieces = sampler().surfaces().stream().mapToLong(FreeFormSurface::pieceCount).sum();
        assertEquals(pieces, doc.scene().patches().size());
    }

    @Test
    void aFileWithoutSurfacesSaysWhatItHeld() throws Exception {
        String text = Files.readString(Path.of(IgesReaderTest.class.getResource("/iges/sampler.igs").toURI()));
        // keep only the point (116) and the note (212): every other directory entry becomes a null entity (0)
        StringBuilder sb = new StringBuilder();
        for (String line : text.split("\n")) {
            if (line.charAt(72) == 'D') {
                String type = line.substring(0, 8).trim();
                if (!type.equals("116") && !type.equals("212")) {
                    line = "       0" + line.substring(8);
                }
            }
            sb.append(line).append('\n');
        }
        ModelFormatException e = assertThrows(ModelFormatException.class, () -> read(sb.toString()));
        assertEquals("part.igs: no surface to draw (IGES entities 108, 120, 122, 128, 143, 144 or 408): "
                + "skipped 2 entities: 1 × 116 (point), 1 × 212 (note)", e.getMessage());
    }
}
