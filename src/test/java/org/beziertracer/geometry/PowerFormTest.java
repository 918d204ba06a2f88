package org.beziertracer.geometry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.beziertracer.model.BezierPatch;
import org.junit.jupiter.api.Test;

/**
 * {@link PowerForm}: the centred power form of a net is the same polynomial as the net (against
 * the term-by-term Bernstein sum and de Casteljau's derivatives, degrees 1..9 in each direction),
 * its constant term is the patch's centre, and a net raised from a bilinear one keeps no
 * higher terms.
 */
class PowerFormTest {

    @Test
    void thePowerFormIsTheNetsPolynomialWithItsDerivatives() {
        Random rnd = new Random(2021);
        double[] got = new double[9], want = new double[9], scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        for (int trial = 0; trial < 400; trial++) {
            int n = 1 + rnd.nextInt(PowerForm.MAX_DEGREE), m = 1 + rnd.nextInt(PowerForm.MAX_DEGREE);
            double scale = Math.pow(10, rnd.nextInt(5) - 2);
            double[] net = TestNets.randomNet(rnd, n, m, 3, scale), a = new double[net.length];
            assertTrue(PowerForm.fromBezier(net, 0, n, m, a, 0), "a finite form");
            double size = TestNets.size(net, 0, net.length);
            for (int k = 0; k < 12; k++) {
                // the corners and edges too
                double u = k < 4 ? k % 2 : rnd.nextDouble(), v = k < 4 ? k / 2 : k < 6 ? rnd.nextInt(2) : rnd.nextDouble();
                PowerForm.evaluateWithDerivatives(a, 0, n, m, u, v, got, 0);
                double[] point = TestNets.bernstein(net, n, m, 3, u, v);
                DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, want, scratch);
                String where = "trial " + trial + " " + TestNets.degrees(n, m, 3) + " at (" + u + ", " + v + ")";
                for (int c = 0; c < 3; c++) {
                    assertEquals(point[c], got[c], 1e-12 * size, where + ", point");
                    assertEquals(want[3 + c], got[3 + c], 1e-10 * size, where + ", ∂/∂u");
                    assertEquals(want[6 + c], got[6 + c], 1e-10 * size, where + ", ∂/∂v");
                }
            }
        }
    }

    @Test
    void theConstantTermIsTheCentreAndABilinearNetRaisedKeepsNoHigherTerms() {
        Random rnd = new Random(2022);
        for (int trial = 0; trial < 40; trial++) {
            BezierPatch p = new BezierPatch(1, 1, TestNets.randomNet(rnd, 1, 1, 3, 2));
            int up = rnd.nextInt(PowerForm.MAX_DEGREE), vUp = rnd.nextInt(PowerForm.MAX_DEGREE);
            for (int k = 0; k < up; k++) {
                p = DegreeElevation.elevateU(p);
            }
            for (int k = 0; k < vUp; k++) {
                p = DegreeElevation.elevateV(p);
            }
            int n = p.degreeU(), m = p.degreeV();
            double[] net = p.copyNet(), a = new double[net.length];
            PowerForm.fromBezier(net, 0, n, m, a, 0);
            double[] centre = TestNets.bernstein(net, n, m, 3, 0.5, 0.5);
            for (int j = 0; j <= m; j++) {
                for (int i = 0; i <= n; i++) {
                    for (int c = 0; c < 3; c++) {
                        double coefficient = a[3 * (j * (n + 1) + i) + c];
                        if (i == 0 && j == 0) {
                            assertEquals(centre[c], coefficient, 1e-14, "the constant term is the centre");
                        } else if (i > 1 || j > 1) {
                            // the term's largest value on the square, |a|·2^-(i+j), is rounding
                            assertEquals(0, Math.scalb(coefficient, -i - j), 1e-14,
                                    "x^" + i + " y^" + j + " of a raised bilinear net");
                        }
                    }
                }
            }
        }
    }

    @Test
    void onlyDegreesUpToNineHaveOne() {
        for (int n = 1; n <= BezierPatch.MAX_DEGREE; n++) {
            assertEquals(n <= 9, PowerForm.has(n, 1), "degree " + n);
            assertEquals(n <= 9, PowerForm.has(2, n), "degree " + n);
        }
        assertTrue(PowerForm.has(9, 9));
        assertFalse(PowerForm.has(10, 3));
    }
}
