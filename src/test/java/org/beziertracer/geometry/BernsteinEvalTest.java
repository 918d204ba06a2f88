package org.beziertracer.geometry;

import static org.beziertracer.geometry.TestNets.randomNet;
import static org.beziertracer.geometry.TestNets.size;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class BernsteinEvalTest {

    /** Allowed difference from de Casteljau, in units of net size × ulp(1) × degree. */
    private static final double ULPS_PER_DEGREE = 4;

    /** Both ways of summing the rows (the processor picks one), against de Casteljau. */
    @ParameterizedTest(name = "rows in pairs: {0}")
    @ValueSource(booleans = {false, true})
    void agreesWithDeCasteljauForEveryDegreePair(boolean inPairs) {
        Random rnd = new Random(41);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        double[] a = new double[9], b = new double[9];
        for (int n = 1; n <= 15; n++) {
            for (int m = 1; m <= 15; m++) {
                // a net far from the origin (cancellation in the derivative sums) and one around it
                for (double shift : new double[] {0, 100}) {
                    double[] net = randomNet(rnd, n, m, 3, 1);
                    for (int k = 0; k < net.length; k++) {
                        net[k] += shift;
                    }
                    double sz = size(net, 0, net.length);
                    for (int trial = 0; trial < 8; trial++) {
                        double u = trial == 0 ? 0 : trial == 1 ? 1 : rnd.nextDouble();
                        double v = trial == 0 ? 1 : trial == 1 ? 0 : rnd.nextDouble();
                        DeCasteljau.evaluateWithDerivatives(net, 0, n, m, u, v, a, scratch);
                        BernsteinEval.evaluateWithDerivatives(net, 0, n, m, u, v, b, 0, scratch, 0, inPairs);
                        for (int c = 0; c < 9; c++) {
                            // derivatives carry the degree as a factor
                            int deg = c < 3 ? 1 : c < 6 ? n : m;
                            double tol = ULPS_PER_DEGREE * Math.ulp(sz) * (n + m) * Math.max(1, deg);
                            double err = Math.abs(a[c] - b[c]);
                            int cc = c, nn = n, mm = m;
                            assertTrue(err <= tol, () -> "degree " + nn + "x" + mm + " shift " + shift + " at (" + u
                                    + "," + v + ") component " + cc + ": " + b[cc] + " vs de Casteljau " + a[cc]
                                    + ", error " + err + " > " + tol);
                        }
                    }
                }
            }
        }
    }

    @Test
    void theBasesArePartitionsOfUnityThatMatchTheBinomialFormula() {
        double[] b = new double[64];
        for (int deg = 1; deg <= 15; deg++) {
            for (double t : new double[] {0, 1e-9, 0.3, 0.5, 0.999, 1}) {
                BernsteinEval.basis(deg, t, b, 0, 16);
                double sum = 0, lowerSum = 0;
                for (int i = 0; i <= deg; i++) {
                    assertTrue(b[i] >= 0, "B_" + i + "^" + deg + "(" + t + ") = " + b[i]);
                    sum += b[i];
                    assertEquals(TestNets.basis(deg, i, t), b[i], 1e-15, "B_" + i + "^" + deg + "(" + t + ")");
                    if (i < deg) {
                        lowerSum += b[16 + i];
                        assertEquals(TestNets.basis(deg - 1, i, t), b[16 + i], 1e-15, "B_" + i + "^" + (deg - 1));
                    }
                }
                assertEquals(1, sum, 1e-14, "degree " + deg + " at " + t);
                assertEquals(1, lowerSum, 1e-14, "degree " + (deg - 1) + " at " + t);
            }
        }
    }

    @Test
    void rowsInPairsAndOneAtATimeGiveTheSameSums() {
        Random rnd = new Random(45);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH], a = new double[9], b = new double[9];
        for (int n = 1; n <= 15; n++) {
            for (int m = 1; m <= 15; m++) {
                double[] net = randomNet(rnd, n, m, 3, 1);
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                BernsteinEval.evaluateWithDerivatives(net, 0, n, m, u, v, a, 0, scratch, 0, false);
                BernsteinEval.evaluateWithDerivatives(net, 0, n, m, u, v, b, 0, scratch, 0, true);
                // the same operations on the same values, in the same order within each sum
                for (int c = 0; c < 9; c++) {
                    assertEquals(a[c], b[c], 0, "degree " + n + "x" + m + ", component " + c);
                }
                BernsteinEval.evaluateWithDerivatives(net, 0, n, m, u, v, b, 0, scratch, 0);
                assertEquals(a[0], b[0], 0, "the public form is one of the two");
            }
        }
    }

    @Test
    void theBasesOfBothDirectionsAtOnceAreTheBasesOfEach() {
        Random rnd = new Random(44);
        double[] both = new double[128], one = new double[128];
        for (int n = 1; n <= 15; n++) {
            for (int m = 1; m <= 15; m++) {
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                BernsteinEval.bases(n, u, m, v, both, 0, 16, 32, 48);
                BernsteinEval.basis(n, u, one, 0, 16);
                BernsteinEval.basis(m, v, one, 32, 48);
                for (int i = 0; i <= Math.max(n, m); i++) {
                    if (i <= n) {
                        assertEquals(one[i], both[i], "B_" + i + "^" + n + "(u)");
                        assertEquals(i < n ? one[16 + i] : 0, i < n ? both[16 + i] : 0, "lower basis in u");
                    }
                    if (i <= m) {
                        assertEquals(one[32 + i], both[32 + i], "B_" + i + "^" + m + "(v)");
                        assertEquals(i < m ? one[48 + i] : 0, i < m ? both[48 + i] : 0, "lower basis in v");
                    }
                }
            }
        }
    }

    @ParameterizedTest(name = "rows in pairs: {0}")
    @ValueSource(booleans = {false, true})
    void aDerivativeAlongACollapsedEdgeIsExactlyZero(boolean inPairs) {
        Random rnd = new Random(43);
        double[] scratch = new double[DeCasteljau.SCRATCH_LENGTH];
        double[] out = new double[9];
        for (int n = 1; n <= 15; n++) {
            int m = 1 + rnd.nextInt(15);
            double[] rowCollapsed = randomNet(rnd, n, m, 3, 50), columnCollapsed = randomNet(rnd, n, m, 3, 50);
            // row j = 0 of one net, column i = 0 of the other collapse to points far from the origin
            for (int i = 0; i <= n; i++) {
                System.arraycopy(new double[] {77.7, -31.3, 12.9}, 0, rowCollapsed, 3 * i, 3);
            }
            for (int j = 0; j <= m; j++) {
                System.arraycopy(new double[] {-5.5, 60.1, 3.3}, 0, columnCollapsed, 3 * j * (n + 1), 3);
            }
            double t = rnd.nextDouble();
            BernsteinEval.evaluateWithDerivatives(rowCollapsed, 0, n, m, t, 0, out, 0, scratch, 0, inPairs);
            for (int c = 3; c < 6; c++) {
                assertEquals(0.0, out[c], "S_u on the collapsed row, degree " + n + "x" + m + " at u=" + t);
            }
            BernsteinEval.evaluateWithDerivatives(columnCollapsed, 0, n, m, 0, 0.2 + 0.6 * t, out, 0, scratch, 0, inPairs);
            for (int c = 6; c < 9; c++) {
                assertEquals(0.0, out[c], "S_v on the collapsed column, degree " + n + "x" + m);
            }
        }
    }
}
