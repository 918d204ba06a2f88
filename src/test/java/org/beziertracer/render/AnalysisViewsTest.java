package org.beziertracer.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.beziertracer.model.RenderSettings;
import org.beziertracer.model.Scene;
import org.beziertracer.model.io.Models;
import org.junit.jupiter.api.Test;

/**
 * The analysis views' settings, their automatic colour range and their colours: the range of a
 * sphere's views is its one curvature, a fixed range is kept, the colours follow the value.
 */
class AnalysisViewsTest {

    private static RenderJob job(Scene scene, String view, Analysis a) {
        RenderSettings s = new RenderSettings(160, 120, 1, "regular", "clipping", true, view, 0, true, 5);
        return RenderJob.prepare(scene, s, RenderOptions.defaults().withThreads(2).withProgressive(false).withAnalysis(a));
    }

    @Test
    void theDefaultEnvironmentIsTheStudioMadeOnFirstUseAndAGivenOneIsKept() {
        Analysis d = Analysis.defaults();
        assertSame(EnvironmentMap.studio(), d.environment(), "no environment given: the built-in studio");
        assertSame(EnvironmentMap.studio(), d.withRange(0, 1).withZebra(new double[] {1, 0, 0}, 8, 0.3).environment());
        EnvironmentMap sky = new EnvironmentMap(2, 2, new float[] {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12});
        Analysis a = new Analysis(new double[] {0, 0, 1}, 16, 0.5, null, 10, Double.NaN, Double.NaN,
                new double[] {0, 0, 1}, 1, sky);
        assertSame(sky, a.withIsophotes(new double[] {0, 1, 0}, 5).environment(), "a given map survives the withers");
    }

    @Test
    void theAutomaticRangeOfTheUnitSphereIsItsOneCurvature() {
        Scene sphere = Models.sphere();
        assertArrayEquals(new double[] {-1, 1}, AnalysisRange.of(job(sphere, "gaussian", Analysis.defaults())), 1e-9,
                "K = 1 everywhere: ±1");
        assertArrayEquals(new double[] {-1, 1}, AnalysisRange.of(job(sphere, "mean", Analysis.defaults())), 1e-9,
                "|H| = 1 everywhere: ±1");
        // one radius everywhere: widened by 2 each way, so it sits mid-scale on the logarithmic axis
        assertArrayEquals(new double[] {0.5, 2}, AnalysisRange.of(job(sphere, "min-radius", Analysis.defaults())), 1e-9);
    }

    @Test
    void aFixedRangeIsKeptAndTheTeapotsAutomaticRangeSpansItsValues() {
        Scene teapot = Models.teapot();
        assertArrayEquals(new double[] {-0.5, 2}, AnalysisRange.of(job(teapot, "mean", Analysis.defaults().withRange(-0.5, 2))));
        double[] radii = AnalysisRange.of(job(teapot, "min-radius", Analysis.defaults()));
        assertTrue(radii[0] > 0 && radii[1] > 10 * radii[0], "a teapot has small and large radii: "
                + java.util.Arrays.toString(radii));
        double[] other = AnalysisRange.of(job(teapot, "zebra", Analysis.defaults()));
        assertArrayEquals(new double[] {0, 1}, other, "no curvature range for a view without one");
    }

    @Test
    void badSettingsAreOneLineErrors() {
        Analysis a = Analysis.defaults();
        assertEquals("zebra stripes must be 2..200, got 1",
                assertThrows(IllegalArgumentException.class, () -> a.withZebra(a.zebraAxis(), 1, 0.5)).getMessage());
        assertEquals("pull direction must be a non-zero finite direction, got 0.0,0.0,0.0",
                assertThrows(IllegalArgumentException.class, () -> a.withDraft(new double[3], 1)).getMessage());
        assertTrue(assertThrows(IllegalArgumentException.class, () -> a.withRange(2, 1)).getMessage()
                .startsWith("analysis range must be two finite numbers, low < high"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> ShadingMode.parse("zebras")).getMessage()
                .contains("zebra, emap, isophotes, gaussian, mean, min-radius, max-radius, draft"));
    }

    @Test
    void curvatureColoursGoFromBlueThroughGreyToRed() {
        double[] neg = new double[3], zero = new double[3], pos = new double[3];
        AnalysisColours.curvature(ShadingMode.MEAN, -1, -1, 1, 1, neg);
        AnalysisColours.curvature(ShadingMode.MEAN, 0, -1, 1, 1, zero);
        AnalysisColours.curvature(ShadingMode.MEAN, 5, -1, 1, 1, pos);
        assertTrue(neg[2] > neg[0], "negative is blue");
        assertTrue(pos[0] > pos[2], "positive is red");
        assertEquals(zero[0], zero[2], 1e-12, "zero is grey");
        double[] flat = new double[3], tight = new double[3];
        AnalysisColours.curvature(ShadingMode.MAX_RADIUS, Double.POSITIVE_INFINITY, 1, 100, 1, flat);
        AnalysisColours.curvature(ShadingMode.MAX_RADIUS, 1, 1, 100, 1, tight);
        assertNotEquals(flat[1], tight[1], "a flat point and a tight one differ");
        assertTrue(flat[0] + flat[1] > tight[0] + tight[1], "flat is the bright top of the scale");
    }

    @Test
    void aDraftViewTellsPositiveNegativeAndVerticalFaces() {
        Analysis a = Analysis.defaults().withDraft(new double[] {0, 0, 1}, 2);
        double[] up = new double[3], down = new double[3], wall = new double[3], almost = new double[3];
        AnalysisColours.draft(a, 0, 0.5, Math.sqrt(0.75), 1, up);      // 60° of draft
        AnalysisColours.draft(a, 0, 0.5, -Math.sqrt(0.75), 1, down);   // −60°
        AnalysisColours.draft(a, 1, 0, 0, 1, wall);                   // 0°
        double t = Math.toRadians(1.5);
        AnalysisColours.draft(a, Math.cos(t), 0, Math.sin(t), 1, almost); // 1.5° < the 2° tolerance
        assertTrue(up[1] > up[0], "positive: green");
        assertTrue(down[0] > down[1], "negative: red");
        assertTrue(wall[0] > 0.5 && wall[1] > 0.5, "vertical: yellow");
        assertArrayEquals(wall, almost, "within the tolerance: vertical");
        assertEquals(60, AnalysisColours.draftAngle(a, 0, 0.5, Math.sqrt(0.75)), 1e-9);
    }

    @Test
    void anEnvironmentMapIsLookedUpByAzimuthAndPolarAngleZUp() {
        // 4 × 2: the top row red, the bottom row blue; columns differ in green by azimuth
        int[] argb = new int[8];
        for (int x = 0; x < 4; x++) {
            argb[x] = 0xFF0000 | (x * 80) << 8;
            argb[4 + x] = 0x0000FF | (x * 80) << 8;
        }
        EnvironmentMap map = EnvironmentMap.fromSrgb(4, 2, argb);
        double[] c = new double[3];
        map.lookup(0, 0, 1, c);
        assertEquals(1, c[0], 1e-6, "straight up: the top row");
        assertEquals(0, c[2], 1e-6);
        map.lookup(0, 0, -1, c);
        assertEquals(1, c[2], 1e-6, "straight down: the bottom row");
        double[] a = new double[3], b = new double[3];
        map.lookup(1, -0.2, 0.5, a);
        map.lookup(-1, 0.2, 0.5, b);
        assertNotEquals(a[1], b[1], "opposite azimuths see other columns");
        assertEquals("an environment image holds finite colours ≥ 0, got NaN", assertThrows(IllegalArgumentException.class,
                () -> new EnvironmentMap(2, 2, new float[] {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, Float.NaN})).getMessage());
        // a mirror facing the viewer reflects the view ray back: the colour behind the eye
        double[] seen = new double[3], behind = new double[3];
        Analysis withMap = Analysis.defaults().withEnvironment(map);
        AnalysisColours.emap(withMap, 0, 1, 0, 0, -1, 0, seen);
        map.lookup(0, -1, 0, behind);
        assertArrayEquals(behind, seen, 1e-12);
    }

    @Test
    void theProbeGivesTheValueUnderAPixel() {
        Scene sphere = Models.sphere();
        RenderJob k = job(sphere, "gaussian", Analysis.defaults());
        String centre = AnalysisProbe.at(k, 80, 60);
        assertTrue(centre.startsWith("K = 1.000 (k1 "), centre);
        assertTrue(centre.contains(" on patch "), centre);
        assertEquals("", AnalysisProbe.at(k, 0, 0), "a miss: nothing");
        assertEquals("", AnalysisProbe.at(k, -1, 60), "outside the picture: nothing");
        assertEquals("", AnalysisProbe.at(job(sphere, "zebra", Analysis.defaults()), 80, 60), "zebra shows no number");
        String radius = AnalysisProbe.at(job(sphere, "max-radius", Analysis.defaults()), 80, 60);
        assertTrue(radius.startsWith("R max = 1.000 "), radius);
        // the default camera looks down at the sphere: the centre pixel's normal faces the eye, tilted up
        String draft = AnalysisProbe.at(job(sphere, "draft", Analysis.defaults()), 80, 60);
        assertTrue(draft.matches("draft -?[0-9.]+° on patch [0-9]+"), draft);
    }

    @Test
    void theLegendRunsFromTheLowEndToTheHighEndOnTheViewsAxis() {
        double[] a = new double[3], b = new double[3];
        for (ShadingMode mode : new ShadingMode[] {ShadingMode.GAUSSIAN, ShadingMode.MEAN, ShadingMode.MIN_RADIUS}) {
            double low = mode == ShadingMode.MIN_RADIUS ? 0.5 : -4, high = mode == ShadingMode.MIN_RADIUS ? 50 : 4;
            assertEquals(low, AnalysisLegend.valueAt(mode, low, high, 0), 1e-12, mode + " low end");
            assertEquals(high, AnalysisLegend.valueAt(mode, low, high, 1), 1e-12, mode + " high end");
            for (double f : new double[] {0, 0.3, 0.5, 1}) {
                AnalysisLegend.colourAt(mode, low, high, f, a);
                AnalysisColours.curvature(mode, AnalysisLegend.valueAt(mode, low, high, f), low, high, 1, b);
                assertArrayEquals(b, a, 1e-12, mode + " at " + f + ": the colour a point of that value gets");
            }
        }
        assertEquals(0, AnalysisLegend.valueAt(ShadingMode.MEAN, -4, 4, 0.5), 0, "the middle of a signed scale is 0");
        assertEquals(1, AnalysisLegend.valueAt(ShadingMode.GAUSSIAN, -4, 4, 0.75), 1e-12, "K on a square-root axis");
        assertEquals(5, AnalysisLegend.valueAt(ShadingMode.MIN_RADIUS, 0.5, 50, 0.5), 1e-12, "radii on a log axis");
        assertThrows(IllegalArgumentException.class, () -> AnalysisLegend.colourAt(ShadingMode.ZEBRA, 0, 1, 0.5, new double[3]));
    }

    @Test
    void zebraStripesAlternateAroundTheAxis() {
        Analysis a = Analysis.defaults().withZebra(new double[] {0, 0, 1}, 4, 0.5);
        // looking down −y at a mirror whose normal turns about z: the reflection turns twice as fast
        int changes = 0;
        double last = -1;
        double[] c = new double[3];
        for (int k = 0; k <= 360; k++) {
            double phi = Math.toRadians(-40 + 90.0 * k / 360);
            AnalysisColours.zebra(a, 0, -1, 0, Math.sin(phi), Math.cos(phi), 0, c);
            if (last >= 0 && c[0] != last) {
                changes++;
            }
            last = c[0];
        }
        // a 90° turn of the normal turns the reflection by 180°: 4 bars a turn give 4 stripe edges
        assertEquals(4, changes, "stripe edges over a half turn of the reflection");
    }
}
