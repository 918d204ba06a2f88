package org.beziertracer.intersect;

import static org.beziertracer.Tolerances.ROUNDING;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * {@link SurfaceParameters}: only exactly {@code [0,1]²} is plain, the maps between a piece's own
 * parameters and its surface's are affine and inverse to each other, and a hit is converted only
 * on a piece that is not plain.
 */
class SurfaceParametersTest {

    @Test
    void onlyTheUnitSquareIsPlain() {
        double[] domains = {0, 1, 0, 1, 0.5, 1, 0, 1, 0, 2, 0, 1, 0, 1, -1, 1, 0, 1, 0, 0.5, 1, 0, 1, 0};
        assertTrue(SurfaceParameters.unit(domains, 0));
        for (int k = 1; k < 6; k++) {
            assertFalse(SurfaceParameters.unit(domains, k), "domain " + k);
        }
    }

    @Test
    void surfaceParametersAreAffineInThePiecesOwnAndInverseToThem() {
        Random rnd = new Random(71);
        for (int trial = 0; trial < 1000; trial++) {
            int k = rnd.nextInt(4);
            double[] domains = new double[16];
            for (int i = 0; i < 16; i += 2) {
                domains[i] = 10 * rnd.nextGaussian();
                domains[i + 1] = domains[i] + 0.01 + 5 * rnd.nextDouble();
            }
            double u0 = domains[4 * k], u1 = domains[4 * k + 1], v0 = domains[4 * k + 2], v1 = domains[4 * k + 3];
            double s = rnd.nextDouble(), t = rnd.nextDouble();
            double u = SurfaceParameters.u(domains, k, s), v = SurfaceParameters.v(domains, k, t);
            double tol = ROUNDING * 100;
            assertEquals(u0 + s * (u1 - u0), u, tol);
            assertEquals(v0 + t * (v1 - v0), v, tol);
            assertEquals(s, SurfaceParameters.s(domains, k, u), tol / (u1 - u0));
            assertEquals(t, SurfaceParameters.t(domains, k, v), tol / (v1 - v0));
            assertEquals(0, SurfaceParameters.s(domains, k, u0), 0);
            assertEquals(1, SurfaceParameters.t(domains, k, v1), tol);

            Hit hit = new Hit();
            hit.index = k;
            hit.u = s;
            hit.v = t;
            SurfaceParameters.toSurface(domains, hit);
            assertEquals(u, hit.u, 0);
            assertEquals(v, hit.v, 0);
        }
    }

    @Test
    void aHitOnAPlainPatchKeepsItsParametersBitForBit() {
        double[] domains = {0.5, 1, 0, 1, 0, 1, 0, 1};
        Hit hit = new Hit();
        hit.index = 1;
        hit.u = 0.1 + 0.2; // not a round number: any arithmetic would be seen
        hit.v = 1.0 / 3;
        SurfaceParameters.toSurface(domains, hit);
        assertEquals(0.1 + 0.2, hit.u, 0);
        assertEquals(1.0 / 3, hit.v, 0);
        hit.index = 0;
        SurfaceParameters.toSurface(domains, hit);
        assertEquals(0.5 + 0.5 * (0.1 + 0.2), hit.u, ROUNDING);
        assertEquals(1.0 / 3, hit.v, ROUNDING);
    }
}
