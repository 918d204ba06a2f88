package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Random;

import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.IgesReader;
import org.beziertracer.model.io.StepReader;
import org.beziertracer.model.io.TextSource;
import org.junit.jupiter.api.Test;

/**
 * Faces on analytic surfaces and surfaces of revolution whose edges carry 3-D curves only
 * ({@code step/analytic3d.stp}, {@code iges/revolved3d.igs}, from the fixture scripts): the
 * curves projected onto the exact NURBS trim what the closed-form shapes say. Seeded random rays
 * from the axis (or the centre) hit at the closed-form distance where the face is, and pass
 * through the holes and beyond the parallels; rays within {@link #MARGIN} of a trim are not
 * asked. The faces that cannot be made are listed as skipped with their reasons.
 */
class ProjectedTrimTracingTest {

    private static final double T = 1e-7, MARGIN = 1e-4;
    private static final int RAYS = 400;

    private static String resource(String path) throws Exception {
        var url = ProjectedTrimTracingTest.class.getResource(path);
        return new String(url.openStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
    }

    private static IgesReader.Model step() throws Exception {
        return StepReader.readModel(TextSource.of(resource("/step/analytic3d.stp"), "analytic3d.stp"));
    }

    private static SceneIntersector traced(FreeFormSurface s) {
        return SceneIntersector.build(new Scene(s.toPatches()), IntersectOptions.defaults());
    }

    private static boolean near(double x, double edge) {
        return Math.abs(x - edge) < MARGIN;
    }

    @Test
    void aCylinderBetweenTwoParallelsHasTheWindowsOfItsArcsAndMeridians() throws Exception {
        SceneIntersector cylinder = traced(step().surfaces().get(0));
        TraceContext ctx = cylinder.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(3501);
        int through = 0, throughSecond = 0;
        for (int k = 0; k < RAYS; k++) {
            double th = 2 * Math.PI * rnd.nextDouble(), z = 0.01 + 2.98 * rnd.nextDouble();
            // the windows θ ∈ (2, 3), z ∈ (1, 2) and θ ∈ (4, 4.5), z ∈ (1.2, 1.8) seen from the axis; asked
            // more often than their share
            if (k % 3 == 0) {
                th = 1.9 + 1.2 * rnd.nextDouble();
                z = 0.9 + 1.2 * rnd.nextDouble();
            } else if (k % 3 == 1) {
                th = 3.9 + 0.7 * rnd.nextDouble();
                z = 1.1 + 0.8 * rnd.nextDouble();
            }
            if (near(th, 2) || near(th, 3) || near(z, 1) || near(z, 2) || near(th, 4) || near(th, 4.5)
                    || near(z, 1.2) || near(z, 1.8)) {
                continue;
            }
            boolean second = th > 4 && th < 4.5 && z > 1.2 && z < 1.8;
            boolean inWindow = th > 2 && th < 3 && z > 1 && z < 2 || second;
            throughSecond += second ? 1 : 0;
            boolean met = cylinder.closestHit(ctx, 0, 0, z, Math.cos(th), Math.sin(th), 0, 0, 100, hit);
            assertEquals(!inWindow, met, "ray at θ " + th + ", z " + z);
            if (met) {
                assertEquals(2, hit.t, T, "ray at θ " + th + ", z " + z);
            }
            through += inWindow ? 1 : 0;
        }
        assertTrue(through > 80 && throughSecond > 40, "rays through the windows: " + through + ", the second "
                + throughSecond);
    }

    @Test
    void aSpherePatchHasTheHoleOfItsTiltedCircle() throws Exception {
        SceneIntersector sphere = traced(step().surfaces().get(1));
        TraceContext ctx = sphere.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(3502);
        double[] n = {Math.cos(0.15) * Math.cos(0.1), Math.cos(0.15) * Math.sin(0.1), Math.sin(0.15)};
        int holes = 0, outside = 0;
        for (int k = 0; k < RAYS; k++) {
            double u = -1.2 + 2.6 * rnd.nextDouble(), lat = -0.8 + 1.9 * rnd.nextDouble();
            double[] d = {Math.cos(lat) * Math.cos(u), Math.cos(lat) * Math.sin(u), Math.sin(lat)};
            double angle = Math.acos(Math.min(1, d[0] * n[0] + d[1] * n[1] + d[2] * n[2]));
            if (near(u, -1) || near(u, 1.2) || near(lat, -0.6) || near(lat, 0.9) || near(angle, 0.3)) {
                continue;
            }
            boolean onPatch = u > -1 && u < 1.2 && lat > -0.6 && lat < 0.9, inHole = angle < 0.3;
            boolean met = sphere.closestHit(ctx, 10, 0, 0, d[0], d[1], d[2], 0, 100, hit);
            String what = "ray at u " + u + ", latitude " + lat + " (" + angle + " from the hole's centre)";
            assertEquals(onPatch && !inHole, met, what);
            if (met) {
                assertEquals(2, hit.t, T, what);
            }
            holes += inHole ? 1 : 0;
            outside += onPatch ? 0 : 1;
        }
        assertTrue(holes > 15 && outside > 50, "rays through the hole " + holes + ", beside the patch " + outside);
    }

    @Test
    void aSurfaceOfRevolutionIsTrimmedByItsTwoParallels() throws Exception {
        FreeFormSurface face = step().surfaces().get(2);
        double[] r = face.range();
        SceneIntersector rev = traced(face);
        TraceContext ctx = rev.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(3503);
        int beyond = 0;
        for (int k = 0; k < RAYS; k++) {
            double th = 2 * Math.PI * rnd.nextDouble(), z = 0.02 + 1.96 * rnd.nextDouble();
            if (near(z, 0.5) || near(z, 1.5)) {
                continue;
            }
            boolean between = z > 0.5 && z < 1.5;
            boolean met = rev.closestHit(ctx, 0, 0, z, Math.cos(th), Math.sin(th), 0, 0, 100, hit);
            assertEquals(between, met, "ray at θ " + th + ", z " + z);
            if (met) {
                assertEquals(1 + 1.5 * z - 0.625 * z * z, hit.t, T, "ray at θ " + th + ", z " + z);
            }
            beyond += between ? 0 : 1;
        }
        assertTrue(beyond > 100, "rays beyond the parallels: " + beyond);
        // the B-spline is the whole profile (z from 0 to 2): the parallels, not the range, bound the face
        assertEquals(0, r[2]);
        assertEquals(1, r[3]);
    }

    @Test
    void facesThatCannotBeProjectedAreSkippedWithTheirReasons() throws Exception {
        IgesReader.Model m = step();
        assertEquals(3, m.surfaces().size(), "skipped: " + m.skipped());
        Map<String, Integer> skipped = m.skipped();
        assertEquals(2, skipped.values().stream().mapToInt(Integer::intValue).sum(), "skipped: " + skipped);
        assertTrue(skipped.keySet().stream().anyMatch(k -> k.contains("extrusion")), "skipped: " + skipped);
        assertTrue(skipped.keySet().stream().anyMatch(k -> k.contains("enclose no area")), "skipped: " + skipped);
    }

    @Test
    void anIgesSurfaceOfRevolutionHasTheWindowOfItsModelSpaceCurves() throws Exception {
        IgesReader.Model m = IgesReader.readModel(TextSource.of(resource("/iges/revolved3d.igs"), "revolved3d.igs"));
        assertTrue(m.skipped().isEmpty(), "skipped: " + m.skipped());
        List<FreeFormSurface> s = m.surfaces();
        assertEquals(1, s.size());
        SceneIntersector cone = traced(s.get(0));
        TraceContext ctx = cone.newContext();
        Hit hit = new Hit();
        Random rnd = new Random(3504);
        int through = 0;
        for (int k = 0; k < RAYS; k++) {
            double th = 2 * Math.PI * rnd.nextDouble(), z = 0.02 + 1.96 * rnd.nextDouble();
            if (k % 3 == 0) {
                th = 1.9 + 1.2 * rnd.nextDouble();
                z = 0.4 + 1.2 * rnd.nextDouble();
            }
            if (near(th, 2) || near(th, 3) || near(z, 0.5) || near(z, 1.5)) {
                continue;
            }
            boolean inWindow = th > 2 && th < 3 && z > 0.5 && z < 1.5;
            boolean met = cone.closestHit(ctx, 0, 0, z, Math.cos(th), Math.sin(th), 0, 0, 100, hit);
            assertEquals(!inWindow, met, "ray at θ " + th + ", z " + z);
            if (met) {
                assertEquals(1 + z / 2, hit.t, T, "ray at θ " + th + ", z " + z);
            }
            through += inWindow ? 1 : 0;
        }
        assertTrue(through > 40, "rays through the window: " + through);
    }
}
