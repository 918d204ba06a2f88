package org.beziertracer.render;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link ToneMap}: the fitted ACES curve's values, its shape, and exposure in stops. */
class ToneMapTest {

    @Test
    void theCurveHasItsFittedValues() {
        assertEquals(0, ToneMap.aces(0));
        assertEquals(0, ToneMap.aces(-1), "negative light is black");
        assertEquals(0, ToneMap.aces(Double.NaN));
        double x = 0.18;
        assertEquals(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), ToneMap.aces(x), ROUNDING);
        assertEquals(1, ToneMap.aces(1e9), "white at the end");
    }

    @Test
    void theCurveRisesMonotonicallyAndRollsHighlightsOff() {
        double last = 0;
        for (int i = 1; i <= 2000; i++) {
            double y = ToneMap.aces(i * 0.01);
            assertTrue(y >= last, "monotone at " + i * 0.01);
            last = y;
        }
        assertTrue(ToneMap.aces(2) < 1 && ToneMap.aces(2) > ToneMap.aces(1), "2 is not clipped as a plain clamp would");
    }

    @Test
    void exposureScalesInStops() {
        Film film = new Film(1, 1, false);
        film.addSample(0, 0, 0.25, 0.25, 0.25);
        int plain = ToneMap.argb(film, 1)[0], doubled = new int[] {0}[0];
        Film twice = new Film(1, 1, false);
        twice.addSample(0, 0, 0.5, 0.5, 0.5);
        doubled = ToneMap.argb(twice, 0)[0];
        assertEquals(doubled, plain, "0.25 one stop up is 0.5");
        assertEquals(Srgb.to8((float) ToneMap.aces(0.5)), plain & 0xFF);
        assertThrows(IllegalArgumentException.class, () -> ToneMap.argb(film, Double.NaN));
    }
}
