package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.IOException;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.beziertracer.math.KnotVector;
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
 * Scene → IGES → scene keeps random rational B-spline surfaces and their trims to the last bit:
 * knots, points, weights and range exactly; each trim piece keeps its curve and run, or, run
 * backwards, comes back as the exact mirror curve of {@code −t} (IGES 126 curves run forwards).
 */
class IgesRoundTripTest {

    private static final int SURFACES = 40;

    @Test
    void randomRationalBSplinesWithTrimsComeBackBitForBit() throws IOException {
        Random rnd = new Random(35);
        List<FreeFormSurface> written = new ArrayList<>();
        List<BezierPatch> patches = new ArrayList<>();
        for (int s = 0; s < SURFACES; s++) {
            FreeFormSurface surface = randomSurface(rnd, s);
            written.add(surface);
            patches.addAll(surface.toPatches());
        }
        StringWriter out = new StringWriter();
        IgesWriter.write(out, new Scene(patches));
        IgesReader.Model read = IgesReader.readModel(TextSource.of(out.toString(), "round.igs"));

        assertEquals(SURFACES, read.surfaces().size());
        for (int s = 0; s < SURFACES; s++) {
            FreeFormSurface a = written.get(s), b = read.surfaces().get(s);
            String what = "surface " + s + ": " + a;
            assertEquals(a.degreeU(), b.degreeU(), what);
            assertEquals(a.degreeV(), b.degreeV(), what);
            assertEquals(a.countU(), b.countU(), what);
            assertEquals(a.countV(), b.countV(), what);
            assertArrayEquals(a.basis().knotVector(a.degreeU(), a.parmU()), b.basis().knotVector(b.degreeU(), b.parmU()), what);
            assertArrayEquals(a.basis().knotVector(a.degreeV(), a.parmV()), b.basis().knotVector(b.degreeV(), b.parmV()), what);
            assertArrayEquals(a.points(), b.points(), what);
            if (a.weights() == null) {
                assertNull(b.weights(), what);
            } else {
                assertArrayEquals(a.weights(), b.weights(), what);
            }
            assertArrayEquals(a.range(), b.range(), what);
            assertSameTrim(a.trim(), b.trim(), what);
        }
    }

    static FreeFormSurface randomSurface(Random rnd, int s) {
        int p = 1 + rnd.nextInt(4), q = 1 + rnd.nextInt(4);
        int cu = p + 1 + rnd.nextInt(5), cv = q + 1 + rnd.nextInt(5);
        double[] ku = SplineReference.randomKnots(rnd, p, cu, rnd.nextBoolean());
        double[] kv = SplineReference.randomKnots(rnd, q, cv, rnd.nextBoolean());
        double[] pts = new double[3 * cu * cv];
        for (int k = 0; k < pts.length; k++) {
            pts[k] = 10 * (2 * rnd.nextDouble() - 1);
        }
        double[] w = null;
        if (s % 2 == 1) {
            w = new double[cu * cv];
            for (int k = 0; k < w.length; k++) {
                w[k] = 0.25 + 2 * rnd.nextDouble();
            }
        }
        double u0 = KnotVector.start(p, ku), u1 = KnotVector.end(p, ku), v0 = KnotVector.start(q, kv), v1 = KnotVector.end(q, kv);
        TrimRegion trim = s % 3 == 0 ? null : trim(rnd, u0, u1, v0, v1, s % 3 == 2);
        return new FreeFormSurface(SplineBasis.BSPLINE, p, q, ku, kv, cu, cv, pts, w, new double[] {u0, u1, v0, v1}, trim);
    }

    /** A quadrilateral outer loop inside the range and a circular hole, the hole run backwards when asked. */
    private static TrimRegion trim(Random rnd, double u0, double u1, double v0, double v1, boolean backwards) {
        double du = u1 - u0, dv = v1 - v0;
        TrimLoop outer = TrimLoop.polygon(u0 + 0.05 * du * rnd.nextDouble(), v0 + 0.05 * dv * rnd.nextDouble(),
                u1 - 0.05 * du * rnd.nextDouble(), v0 + 0.05 * dv * rnd.nextDouble(),
                u1 - 0.05 * du * rnd.nextDouble(), v1 - 0.05 * dv * rnd.nextDouble(),
                u0 + 0.05 * du * rnd.nextDouble(), v1 - 0.05 * dv * rnd.nextDouble());
        double r = 0.1 * Math.min(du, dv) * (1 + rnd.nextDouble());
        TrimLoop hole = TrimLoop.circle(u0 + 0.5 * du, v0 + 0.5 * dv, r, backwards);
        if (backwards) {
            TrimPiece c = hole.pieces().get(0);
            hole = new TrimLoop(List.of(new TrimPiece(c.curve(), c.to(), c.from())));
        }
        return new TrimRegion(List.of(outer), List.of(hole));
    }

    private static void assertSameTrim(TrimRegion a, TrimRegion b, String what) {
        if (a == null) {
            assertNull(b, what);
            return;
        }
        assertEquals(a.outer().size(), b.outer().size(), what);
        assertEquals(a.holes().size(), b.holes().size(), what);
        for (int k = 0; k < a.outer().size(); k++) {
            assertSameLoop(a.outer().get(k), b.outer().get(k), what + ", outer loop " + k);
        }
        for (int k = 0; k < a.holes().size(); k++) {
            assertSameLoop(a.holes().get(k), b.holes().get(k), what + ", hole " + k);
        }
    }

    /**
     * Both loops hold the same pieces, to the bit: a piece run forwards is the same curve over the same
     * run; a piece run backwards comes back as the mirrored curve (knots {@code −t} reversed, points
     * and weights reversed) run forwards over the negated ends.
     */
    private static void assertSameLoop(TrimLoop a, TrimLoop b, String what) {
        assertEquals(a.pieces().size(), b.pieces().size(), what);
        for (int k = 0; k < a.pieces().size(); k++) {
            TrimPiece pa = a.pieces().get(k), pb = b.pieces().get(k);
            String piece = what + ", piece " + k;
            assertArrayEquals(TrimLoop.ends(pa), TrimLoop.ends(pb), piece + " ends");
            TrimCurve ca = pa.curve(), cb = pb.curve();
            assertEquals(ca.degree(), cb.degree(), piece);
            if (pa.from() < pa.to()) {
                assertArrayEquals(ca.knots(), cb.knots(), piece);
                assertArrayEquals(ca.points(), cb.points(), piece);
                assertArrayEquals(ca.weights(), cb.weights(), piece);
                assertEquals(pa.from(), pb.from(), piece);
                assertEquals(pa.to(), pb.to(), piece);
            } else {
                assertArrayEquals(mirrored(ca.knots(), 1, true), cb.knots(), piece);
                assertArrayEquals(mirrored(ca.points(), 2, false), cb.points(), piece);
                assertArrayEquals(ca.weights() == null ? null : mirrored(ca.weights(), 1, false), cb.weights(), piece);
                assertEquals(-pa.from(), pb.from(), piece);
                assertEquals(-pa.to(), pb.to(), piece);
            }
        }
    }

    /** {@code values} in reverse order of their {@code stride}-tuples, each negated when asked. */
    private static double[] mirrored(double[] values, int stride, boolean negate) {
        double[] out = new double[values.length];
        int n = values.length / stride;
        for (int i = 0; i < n; i++) {
            for (int c = 0; c < stride; c++) {
                double x = values[(n - 1 - i) * stride + c];
                out[i * stride + c] = negate ? -x : x;
            }
        }
        return out;
    }
}
