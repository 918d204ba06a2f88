package org.beziertracer.model.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.List;
import java.util.Random;

import org.beziertracer.math.SplineReference;
import org.beziertracer.math.Vec3;
import org.beziertracer.model.FreeFormSurface;
import org.beziertracer.model.Scene;
import org.beziertracer.model.SplineBasis;
import org.beziertracer.model.TrimCurve;
import org.beziertracer.model.TrimLoop;
import org.beziertracer.model.TrimPiece;
import org.junit.jupiter.api.Test;

/**
 * The exact image of a trim curve on its surface ({@link CurveOnSurface}) against independent
 * Cox–de Boor sums of the surface at the trim's own Cox–de Boor point, at random parameters; and
 * the STEP writer's 3-D edge curves, read from its file, against the surface at their pcurves.
 */
class CurveOnSurfaceTest {

    /** Relative agreement of the composed curve with the surface at the trim's point (rounding of a degree-30 sum). */
    private static final double TOLERANCE = 1e-9;

    private static SplinePoint at(FreeFormSurface s) {
        return new SplinePoint(s.degreeU(), s.degreeV(), s.basis().knotVector(s.degreeU(), s.parmU()),
                s.basis().knotVector(s.degreeV(), s.parmV()), s.countU(), s.countV(), s.points(), s.weights());
    }

    /** The homogeneous point of a rational B-spline by Cox–de Boor, divided out. */
    private static double[] reference(int degree, double[] knots, double[] points, double[] weights, int dim, double t) {
        int n = points.length / dim;
        double[] h = new double[(dim + 1) * n];
        for (int k = 0; k < n; k++) {
            double w = weights == null ? 1 : weights[k];
            for (int a = 0; a < dim; a++) {
                h[(dim + 1) * k + a] = w * points[dim * k + a];
            }
            h[(dim + 1) * k + dim] = w;
        }
        // at the end of the range the half-open basis is 0: evaluate a hair inside
        double end = knots[knots.length - 1 - degree];
        double[] r = SplineReference.curve(knots, degree, h, dim + 1, t == end ? Math.nextDown(t) : t);
        double[] out = new double[dim];
        for (int a = 0; a < dim; a++) {
            out[a] = r[a] / r[dim];
        }
        return out;
    }

    private static Vec3 surfaceAt(FreeFormSurface s, double u, double v) {
        double[] r = s.range();
        return IgesReaderTest.coxDeBoor(s, Math.min(u, Math.nextDown(r[1])), Math.min(v, Math.nextDown(r[3])));
    }

    private static double size(FreeFormSurface s) {
        double[] p = s.points();
        double m = 0;
        for (double x : p) {
            m = Math.max(m, Math.abs(x));
        }
        return Math.max(m, 1e-300);
    }

    @Test
    void theImageOfEveryTrimOfRandomRationalSurfacesIsTheSurfaceAtTheTrim() {
        Random rnd = new Random(1993);
        int composed = 0;
        for (int trial = 0; trial < 80; trial++) {
            FreeFormSurface s = StepWriterTest.randomSurface(rnd, 1 + trial % 3);
            CurveOnSurface.Patches patches = CurveOnSurface.Patches.of(at(s));
            for (List<TrimLoop> loops : List.of(s.trim().outer(), s.trim().holes())) {
                for (TrimLoop loop : loops) {
                    for (TrimPiece piece : loop.pieces()) {
                        TrimCurve c = piece.curve();
                        double lo = Math.min(piece.from(), piece.to()), hi = Math.max(piece.from(), piece.to());
                        CurveOnSurface.Curve3 image = CurveOnSurface.compose(patches, c, lo, hi);
                        assertNotNull(image, "trial " + trial + ": " + c + " on degrees " + s.degreeU() + ", " + s.degreeV());
                        composed++;
                        assertEquals(lo, image.knots()[0]);
                        assertEquals(hi, image.knots()[image.knots().length - 1]);
                        for (int k = 0; k <= 20; k++) {
                            double t = k == 20 ? hi : lo + (hi - lo) * (k == 0 ? 0 : rnd.nextDouble());
                            double[] uv = reference(c.degree(), c.knots(), c.points(), c.weights(), 2, t);
                            Vec3 expected = surfaceAt(s, uv[0], uv[1]);
                            double[] got = reference(image.degree(), image.knots(), image.points(), image.weights(), 3, t);
                            double err = new Vec3(got[0], got[1], got[2]).sub(expected).length();
                            assertTrue(err <= TOLERANCE * size(s), "trial " + trial + ", t = " + t + ": " + expected
                                    + " against " + java.util.Arrays.toString(got) + " (error " + err + ")");
                        }
                        if (s.weights() == null && c.weights() == null) {
                            assertNull(image.weights(), "a polynomial trim on a polynomial surface has a polynomial image");
                        }
                    }
                }
            }
        }
        assertTrue(composed > 200, "composed " + composed);
    }

    @Test
    void anIsoParameterLineIsTheIsoCurveOfTheSurfacesDegree() {
        FreeFormSurface s = StepWriterTest.randomSurface(new Random(7), 0);
        CurveOnSurface.Patches patches = CurveOnSurface.Patches.of(at(s));
        double[] r = s.range();
        double v = (r[2] + r[3]) / 2;
        TrimCurve line = new TrimCurve(SplineBasis.BSPLINE, 1, new double[] {r[0], r[0], r[1], r[1]},
                new double[] {r[0], v, r[1], v}, null);
        CurveOnSurface.Curve3 image = CurveOnSurface.compose(patches, line, r[0], r[1]);
        assertEquals(s.degreeU(), image.degree(), "degree of the iso-curve");
    }

    @Test
    void aPolygonAlongIsoLinesIsLoweredToTheSurfacesDegreeAndStaysExact() {
        Random rnd = new Random(3);
        double[] knots = {0, 0, 0, 0, 1, 1, 1, 1};
        double[] pts = new double[48];
        for (int k = 0; k < pts.length; k++) {
            pts[k] = rnd.nextDouble();
        }
        FreeFormSurface s = new FreeFormSurface(SplineBasis.BSPLINE, 3, 3, knots, knots, 4, 4, pts, null,
                new double[] {0, 1, 0, 1}, null);
        TrimCurve square = TrimLoop.polygon(0.1, 0.1, 0.9, 0.1, 0.9, 0.9, 0.1, 0.9).pieces().get(0).curve();
        CurveOnSurface.Curve3 image = CurveOnSurface.compose(CurveOnSurface.Patches.of(at(s)), square, 0, 4);
        assertEquals(3, image.degree(), "each side is an iso-curve of degree 3 (composed: 6)");
        assertEquals(13, image.count());
        for (int k = 0; k <= 40; k++) {
            double t = 4.0 * k / 40;
            double[] uv = reference(1, square.knots(), square.points(), null, 2, t);
            double[] got = reference(3, image.knots(), image.points(), image.weights(), 3, t);
            assertTrue(new Vec3(got[0], got[1], got[2]).sub(surfaceAt(s, uv[0], uv[1])).length() <= 1e-12, "t = " + t);
        }
    }

    @Test
    void aLineAcrossKnotLinesIsCutAtTheCrossings() {
        // a bicubic of 2 × 2 spans; the diagonal crosses u = 0.5 and v = 0.25 inside
        double[] knots = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
        double[] kv = {0, 0, 0, 0, 0.25, 1, 1, 1, 1};
        Random rnd = new Random(5);
        double[] pts = new double[3 * 25];
        for (int k = 0; k < pts.length; k++) {
            pts[k] = rnd.nextDouble();
        }
        FreeFormSurface s = new FreeFormSurface(SplineBasis.BSPLINE, 3, 3, knots, kv, 5, 5, pts, null,
                new double[] {0, 1, 0, 1}, null);
        TrimCurve diagonal = new TrimCurve(SplineBasis.BSPLINE, 1, new double[] {0, 0, 1, 1},
                new double[] {0.1, 0.1, 0.9, 0.7}, null);
        CurveOnSurface.Curve3 image = CurveOnSurface.compose(CurveOnSurface.Patches.of(at(s)), diagonal, 0, 1);
        assertEquals(6, image.degree());
        assertEquals(3 * 6 + 1, image.count(), "three pieces of degree 6");
        double[] k = image.knots();
        assertEquals(0.25, k[7], 1e-15, "v = 0.1 + 0.6 t crosses 0.25 at t = 0.25");
        assertEquals(0.5, k[13], 1e-15, "u = 0.1 + 0.8 t crosses 0.5 at t = 0.5");
    }

    @Test
    void theFitStaysWithinItsToleranceOfTheTrueImage() {
        FreeFormSurface s = StepWriterTest.randomSurface(new Random(11), 1);
        SplinePoint at = at(s);
        TrimPiece piece = s.trim().holes().get(0).pieces().get(0);
        TrimCurve c = piece.curve();
        double lo = c.start(), hi = c.end();
        CurveOnSurface.Curve3 fit = CurveOnSurface.fit(at, c, lo, hi);
        Random rnd = new Random(2);
        double diag = 0;
        double[] p = s.points();
        for (int a = 0; a < 3; a++) {
            double min = Double.POSITIVE_INFINITY, max = Double.NEGATIVE_INFINITY;
            for (int k = a; k < p.length; k += 3) {
                min = Math.min(min, p[k]);
                max = Math.max(max, p[k]);
            }
            diag += (max - min) * (max - min);
        }
        for (int k = 0; k < 200; k++) {
            double t = lo + (hi - lo) * rnd.nextDouble();
            double[] uv = reference(c.degree(), c.knots(), c.points(), c.weights(), 2, t);
            Vec3 expected = surfaceAt(s, uv[0], uv[1]);
            double[] got = reference(1, fit.knots(), fit.points(), null, 3, t);
            // the chord's error is measured at span middles; elsewhere a parabola's is at most as large
            assertTrue(new Vec3(got[0], got[1], got[2]).sub(expected).length() <= 2 * CurveOnSurface.FIT_TOLERANCE
                    * Math.sqrt(diag), "t = " + t);
        }
    }

    @Test
    void theWrittenEdgeCurvesAreTheSurfaceAtTheirPcurves() throws IOException {
        Random rnd = new Random(42);
        for (int trial = 0; trial < 12; trial++) {
            FreeFormSurface s = StepWriterTest.randomSurface(rnd, trial % 5);
            String text = StepWriterTest.write(new Scene(s.toPatches()));
            assertTrue(!text.contains(".POLYLINE_FORM."), "no polyline is written any more");
            StepFile file = StepFile.read(TextSource.of(text, "model.stp"));
            StepGeometry g = new StepGeometry(file);
            int checked = 0;
            for (StepFile.Entity e : file.order) {
                if (!e.is("SURFACE_CURVE")) {
                    continue;
                }
                StepArgs a = g.args(e, "SURFACE_CURVE");
                StepFile.Entity c3 = basis(g, a.ref(1, "curve_3d"));
                StepFile.Entity pcurve = a.target(a.list(2, "associated_geometry").get(0), "pcurve");
                StepFile.Entity rep = g.args(pcurve, "PCURVE").ref(2, "reference_to_curve");
                StepArgs ra = g.args(rep, "DEFINITIONAL_REPRESENTATION");
                StepFile.Entity c2 = basis(g, ra.target(ra.list(1, "items").get(0), "items"));
                IgesCurve curve3 = g.spline(c3, CurveOnSurface.MAX_DEGREE);
                StepGeometry.ParamCurve curve2 = g.curve(c2);
                for (int k = 0; k <= 8; k++) {
                    double t = curve3.t0() + (curve3.t1() - curve3.t0()) * k / 8;
                    double[] uv = curve2.spline() == null ? curve2.at(t) : reference(curve2.spline().degree(),
                            curve2.spline().knots(), curve2.spline().points(), curve2.spline().weights(), 3, t);
                    Vec3 expected = surfaceAt(s, uv[0], uv[1]);
                    double[] got = reference(curve3.degree(), curve3.knots(), curve3.points(), curve3.weights(), 3, t);
                    assertTrue(new Vec3(got[0], got[1], got[2]).sub(expected).length() <= TOLERANCE * size(s),
                            "trial " + trial + ", #" + e.id() + " at t = " + t + ": " + expected + " against "
                                    + java.util.Arrays.toString(got));
                }
                checked++;
            }
            assertTrue(checked >= 2, "trial " + trial + ": " + checked + " edges");
        }
    }

    private static StepFile.Entity basis(StepGeometry g, StepFile.Entity e) {
        return e.is("TRIMMED_CURVE") ? g.args(e, "TRIMMED_CURVE").ref(1, "basis_curve") : e;
    }
}
