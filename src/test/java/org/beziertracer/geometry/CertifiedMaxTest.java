package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** {@link CertifiedMax} on measures whose maximum is known. */
class CertifiedMaxTest {

    /** |p(t)| of a scalar polynomial. */
    private static final CertifiedMax.Measure ABS = new CertifiedMax.Measure() {
        @Override
        public double bound(BernsteinPoly[] p) { return p[0].maxNorm(); }

        @Override
        public double value(BernsteinPoly[] p, boolean atOne) { return Math.abs(p[0].endValue(atOne)); }

        @Override
        public boolean degenerate(BernsteinPoly[] p) { return false; }
    };

    @Test
    void theBoundOfAnInteriorMaximumIsWithinOnePercentAndAboveIt() {
        // 4 t (1 − t): maximum 1 at t = ½, in Bernstein form (0, 2, 0)
        CertifiedMax.Result r = CertifiedMax.maximise(ABS, new BernsteinPoly[] {BernsteinPoly.of(2, 1, 0, 2, 0)}, 0, 10_000);
        assertTrue(r.bound() >= 1 && r.bound() <= 1.01, r.toString());
        assertEquals(0.5, r.tWorst(), 1e-12);
        assertTrue(r.tight());
        // off-centre: 27/4 t² (1 − t) has its maximum 1 at t = 2/3, which no dyadic sample hits
        BernsteinPoly p = BernsteinPoly.of(3, 1, 0, 0, 27.0 / 4 / 3, 0);
        CertifiedMax.Result q = CertifiedMax.maximise(ABS, new BernsteinPoly[] {p}, 0, 10_000);
        assertTrue(q.bound() >= 1 && q.bound() <= 1.01 * q.worst() && q.worst() <= 1, q.toString());
        assertEquals(2.0 / 3, q.tWorst(), 0.05, "a sample within 1 % of the maximum lies near it");
    }

    @Test
    void aMeasureUndefinedAtAPointIsExcludedThereAndReported() {
        // 1 / |t − 0.3| − unbounded at 0.3: bound +∞ on segments that contain it
        CertifiedMax.Measure spike = new CertifiedMax.Measure() {
            @Override
            public double bound(BernsteinPoly[] p) {
                double lo = p[0].min(), hi = p[0].max();
                return lo <= 0 && hi >= 0 ? Double.POSITIVE_INFINITY : Math.min(1, 1e-3 / Math.min(Math.abs(lo), Math.abs(hi)));
            }

            @Override
            public double value(BernsteinPoly[] p, boolean atOne) {
                double x = Math.abs(p[0].endValue(atOne));
                return x == 0 ? Double.NaN : Math.min(1, 1e-3 / x);
            }

            @Override
            public boolean degenerate(BernsteinPoly[] p) { return p[0].min() <= 0 && p[0].max() >= 0; }
        };
        CertifiedMax.Result r = CertifiedMax.maximise(spike, new BernsteinPoly[] {BernsteinPoly.of(1, 1, -0.3, 0.7)}, 0, 10_000);
        assertEquals(1, r.degenerate().length, r.toString());
        assertEquals(0.3, r.degenerate()[0], 1e-6);
        assertEquals(1, r.bound(), 1e-12, "capped at 1 away from the excluded point");
    }
}
