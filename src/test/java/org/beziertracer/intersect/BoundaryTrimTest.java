package org.beziertracer.intersect;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.beziertracer.model.PatchDomain;
import org.beziertracer.model.Scene;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimRegion;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A trim loop that runs along the domain boundary (what CAD tools write for a face trimmed by its
 * own edges) trims nothing: a ray at the patch's u_max or v_max edge, through the pole of a
 * sphere (where the v_max edge collapses) or at the edge two coplanar trimmed faces share hits
 * as it would hit the untrimmed patch. Once, points on a loop's right and top edges counted as
 * outside, so those rays fell through.
 */
class BoundaryTrimTest {

    private static final double H = Math.sqrt(0.5);

    /** The loop along the border of {@code [u0,u1]×[v0,v1]}. */
    static TrimRegion boundary(double u0, double u1, double v0, double v1) {
        return new TrimRegion(List.of(TrimLoop.polygon(u0, v0, u1, v0, u1, v1, u0, v1)), List.of());
    }

    /** The flat plate x = x0 + (x1−x0)s, y = t, z = 0 over the surface parameters {@code [u0,u1]×[v0,v1]}. */
    static BezierPatch plate(double x0, double x1, double u0, double u1, double v0, double v1, boolean trimmed) {
        double[] net = {x0, 0, 0, x1, 0, 0, x0, 1, 0, x1, 1, 0};
        return new BezierPatch(1, 1, net, null, new PatchDomain(u0, u1, v0, v1, trimmed ? boundary(u0, u1, v0, v1) : null), null);
    }

    /**
     * The upper unit hemisphere as four exact rational biquadratic octants (Piegl &amp; Tiller
     * §8.5), each with its v_max edge collapsed into the north pole (0, 0, 1).
     */
    static List<BezierPatch> hemisphere(boolean trimmed) {
        double[] w1 = {1, H, 1};
        List<BezierPatch> out = new ArrayList<>();
        for (int q = 0; q < 4; q++) {
            double c = Math.cos(q * Math.PI / 2), s = Math.sin(q * Math.PI / 2);
            double[] eq = {1, 0, 1, 1, 0, 1}; // (x, y) of the equator's quarter arc, before rotation
            double[] net = new double[27], w = new double[9];
            for (int i = 0; i < 3; i++) {
                double x = c * eq[2 * i] - s * eq[2 * i + 1], y = s * eq[2 * i] + c * eq[2 * i + 1];
                double[][] rows = {{x, y, 0}, {x, y, 1}, {0, 0, 1}};
                double[] wv = {1, H, 1};
                for (int j = 0; j < 3; j++) {
                    int p = j * 3 + i;
                    net[3 * p] = rows[j][0];
                    net[3 * p + 1] = rows[j][1];
                    net[3 * p + 2] = rows[j][2];
                    w[p] = w1[i] * wv[j];
                }
            }
            out.add(new BezierPatch(2, 2, net, w, new PatchDomain(0, 1, 0, 1, trimmed ? boundary(0, 1, 0, 1) : null), null));
        }
        return out;
    }

    /** Rays straight down at the given (x, y) points: how many miss. */
    static int fallThrough(List<BezierPatch> patches, Method method, double[] xy) {
        SceneIntersector si = SceneIntersector.build(new Scene(patches), IntersectOptions.defaults().withMethod(method));
        TraceContext ctx = si.newContext();
        Hit hit = new Hit();
        int misses = 0;
        for (int r = 0; r < xy.length; r += 2) {
            if (!si.closestHit(ctx, xy[r], xy[r + 1], 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY, hit)) {
                misses++;
            }
        }
        return misses;
    }

    /** {@code count} points on the segment from (x0, y0) to (x1, y1), at seeded random places inside it. */
    static double[] along(double x0, double y0, double x1, double y1, int count, long seed) {
        Random rnd = new Random(seed);
        double[] xy = new double[2 * count];
        for (int r = 0; r < count; r++) {
            double f = 0.01 + 0.98 * rnd.nextDouble();
            xy[2 * r] = x0 + (x1 - x0) * f;
            xy[2 * r + 1] = y0 + (y1 - y0) * f;
        }
        return xy;
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void raysAtTheUMaxAndVMaxEdgesOfABoundaryTrimmedPlateHit(Method method) {
        double[] uMax = along(1, 0, 1, 1, 300, 1), vMax = along(0, 1, 1, 1, 300, 2);
        assertEquals(0, fallThrough(List.of(plate(0, 1, 0, 1, 0, 1, false)), method, uMax), method + " untrimmed, u_max");
        assertEquals(0, fallThrough(List.of(plate(0, 1, 0, 1, 0, 1, false)), method, vMax), method + " untrimmed, v_max");
        // the whole surface, then a piece of a larger one: its parameters [0.2,0.7]×[0.3,0.9] are not its net's
        String misses = fallThrough(List.of(plate(0, 1, 0, 1, 0, 1, true)), method, uMax)
                + " " + fallThrough(List.of(plate(0, 1, 0, 1, 0, 1, true)), method, vMax)
                + " " + fallThrough(List.of(plate(0, 1, 0.2, 0.7, 0.3, 0.9, true)), method, uMax)
                + " " + fallThrough(List.of(plate(0, 1, 0.2, 0.7, 0.3, 0.9, true)), method, vMax);
        assertEquals("0 0 0 0", misses, method + ": rays of 300 that fell through at u_max, v_max, then the piece's u_max, v_max");
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void raysAtTheEdgeTwoCoplanarTrimmedFacesShareAtUOneHit(Method method) {
        // face A: x = u; face B: x = 2 − u; both end at u = 1 on the line x = 1
        double[] edge = along(1, 0, 1, 1, 300, 3);
        List<BezierPatch> untrimmed = List.of(plate(0, 1, 0, 1, 0, 1, false), plate(2, 1, 0, 1, 0, 1, false));
        List<BezierPatch> trimmed = List.of(plate(0, 1, 0, 1, 0, 1, true), plate(2, 1, 0, 1, 0, 1, true));
        assertEquals(0, fallThrough(untrimmed, method, edge), method + " untrimmed");
        assertEquals(0, fallThrough(trimmed, method, edge), method + " of 300 rays fell through the shared edge");
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void raysThroughThePoleOfABoundaryTrimmedSphereHitItThere(Method method) {
        Random rnd = new Random(4);
        int[] misses = new int[2];
        for (int trimmed = 0; trimmed < 2; trimmed++) {
            SceneIntersector si = SceneIntersector.build(new Scene(hemisphere(trimmed == 1)),
                    IntersectOptions.defaults().withMethod(method));
            TraceContext ctx = si.newContext();
            Hit hit = new Hit();
            rnd.setSeed(4);
            for (int r = 0; r < 200; r++) {
                // a direction within 60° of straight down, through the pole
                double a = 2 * Math.PI * rnd.nextDouble(), tilt = Math.PI / 3 * rnd.nextDouble();
                double dx = Math.sin(tilt) * Math.cos(a), dy = Math.sin(tilt) * Math.sin(a), dz = -Math.cos(tilt);
                boolean found = si.closestHit(ctx, -2 * dx, -2 * dy, 1 - 2 * dz, dx, dy, dz, 0, Double.POSITIVE_INFINITY, hit);
                if (!found || Math.abs(hit.t - 2) > 1e-6) {
                    misses[trimmed]++;
                }
            }
        }
        assertEquals("0 0", misses[0] + " " + misses[1], method + ": rays of 200 through the pole that missed it, untrimmed then trimmed");
    }

    @ParameterizedTest
    @EnumSource(Method.class)
    void theTwoFacesOfTheCadExportFixtureShowNoCrackAtTheirSharedEdge(Method method) throws java.io.IOException {
        String text;
        try (var in = getClass().getResourceAsStream("/org/beziertracer/model/io/cad-export.obj")) {
            text = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        }
        List<BezierPatch> faces = org.beziertracer.model.io.ObjReader.read(text, "cad-export.obj");
        assertEquals(0, fallThrough(faces, method, along(1, 0, 1, 1, 300, 5)), method + ": rays of 300 through x = 1");
    }

    @org.junit.jupiter.api.Test
    void aHitJustBelowTheEdgeThatMapsOntoU1ByRoundingIsStillInside() {
        // pieces of surfaces over awkward ranges: s a few ulps below 1 may map onto u1 (or past it)
        double[][] ranges = {{0.1, 0.7}, {0.2, 0.7}, {1.0 / 3, 2.0 / 3}, {-0.3, 0.9}, {0.7, 1.1}};
        double[] scratch = new double[org.beziertracer.geometry.TrimCurves.SCRATCH_LENGTH];
        int ontoEdge = 0;
        for (double[] r : ranges) {
            double[] domain = {r[0], r[1], r[0], r[1]};
            var trim = org.beziertracer.geometry.TrimCurves.of(boundary(r[0], r[1], r[0], r[1]));
            double s = 1;
            for (int k = 0; k < 40; k++, s = Math.nextDown(s)) {
                if (k > 0 && SurfaceParameters.u(domain, 0, s) >= r[1]) {
                    ontoEdge++;
                }
                String at = "range " + r[0] + ".." + r[1] + ", s = " + s;
                assertEquals(true, TrimmedLeaves.inside(domain, 0, trim, s, 0.5, scratch), "u edge, " + at);
                assertEquals(true, TrimmedLeaves.inside(domain, 0, trim, 0.5, s, scratch), "v edge, " + at);
                assertEquals(true, TrimmedLeaves.inside(domain, 0, trim, s, s, scratch), "corner, " + at);
            }
            assertEquals(true, TrimmedLeaves.inside(domain, 0, trim, 1 + 1e-9, 0.5, scratch), "a rounding error past the edge");
            assertEquals(true, TrimmedLeaves.inside(domain, 0, trim, -1e-9, 0.5, scratch), "a rounding error before u0");
        }
        assertEquals(true, ontoEdge > 0, "cases where s < 1 maps onto u1 (the ones this test is for): " + ontoEdge);
    }
}
