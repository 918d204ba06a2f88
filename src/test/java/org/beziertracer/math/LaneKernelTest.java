package org.beziertracer.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * The SIMD kernel gives the scalar kernel's bits, lane for lane, at every degree and lane count;
 * and the scalar kernel is the power form's Horner sum (an independent term-by-term oracle).
 * The test JVM runs with {@code --add-modules jdk.incubator.vector} (pom.xml), so both kernels are here.
 */
class LaneKernelTest {

    private static final int STRIDE = 24;

    @Test
    void theTestJvmHasTheSimdKernelAndChoosesIt() {
        assertTrue(Kernels.vectorModulePresent(), "surefire must start the tests with the Vector API module");
        LaneKernel simd = Kernels.named("simd");
        assertNotSame(Kernels.scalar(), simd);
        LaneKernel auto = Kernels.named("auto");
        assertTrue(auto instanceof WarmingKernel, "auto is the SIMD kernel behind its warm-up: " + auto);
        assertSame(auto, Kernels.named("AUTO"));
        assertEquals(simd.description(), auto.description());
        assertEquals(simd.lanes(), auto.lanes());
        assertTrue(simd.description().startsWith("SIMD, " + simd.lanes() + " double lanes"), simd.description());
        assertTrue(Kernels.scalar().description().startsWith("scalar"));
    }

    @Test
    void simdLanesEqualScalarLanesBitForBit() {
        Random rnd = new Random(3201);
        LaneKernel scalar = Kernels.scalar(), simd = Kernels.named("simd");
        double[] a0 = new double[9 * STRIDE], b0 = new double[9 * STRIDE];
        for (int n = 1; n <= 15; n++) {
            for (int m = 1; m <= 15; m++) {
                double[] a = randomForm(rnd, n, m, 2);
                int off = 2;
                int count = rnd.nextInt(STRIDE + 1);
                // inputs with room past count (whole registers), or exactly count long (a mask)
                boolean room = rnd.nextBoolean();
                double[] u = new double[room ? STRIDE : count], v = new double[room ? STRIDE : count];
                for (int i = 0; i < count; i++) {
                    // inside the square, on its border and a little outside (Newton's iterates)
                    u[i] = i % 5 == 0 ? (i % 2) : -0.1 + 1.2 * rnd.nextDouble();
                    v[i] = i % 7 == 0 ? 1 : -0.1 + 1.2 * rnd.nextDouble();
                }
                java.util.Arrays.fill(a0, 42);
                java.util.Arrays.fill(b0, 42);
                scalar.powerForm(a, off, n, m, u, v, count, a0, STRIDE);
                simd.powerForm(a, off, n, m, u, v, count, b0, STRIDE);
                int scratchEnd = room ? (count + simd.lanes() - 1) / simd.lanes() * simd.lanes() : count;
                for (int c = 0; c < 9; c++) {
                    for (int i = 0; i < STRIDE; i++) {
                        int k = c * STRIDE + i;
                        String where = "degree " + n + "x" + m + ", " + count + " lanes, lane " + i + ", component " + c;
                        if (i < count) {
                            assertEquals(Double.doubleToRawLongBits(a0[k]), Double.doubleToRawLongBits(b0[k]), where);
                        } else if (i >= scratchEnd) {
                            assertEquals(42.0, b0[k], where + ": written past the scratch lanes");
                        }
                        if (i >= count) {
                            assertEquals(42.0, a0[k], where + ": the scalar kernel wrote past count");
                        }
                    }
                }
            }
        }
    }

    @Test
    void scalarLanesAreThePowerFormsTermByTermSum() {
        Random rnd = new Random(3202);
        double[] out = new double[9 * STRIDE];
        double[] u = new double[STRIDE], v = new double[STRIDE];
        for (int trial = 0; trial < 300; trial++) {
            int n = 1 + rnd.nextInt(9), m = 1 + rnd.nextInt(9), count = 1 + rnd.nextInt(STRIDE);
            double[] a = randomForm(rnd, n, m, 0);
            for (int i = 0; i < count; i++) {
                u[i] = rnd.nextDouble();
                v[i] = rnd.nextDouble();
            }
            Kernels.scalar().powerForm(a, 0, n, m, u, v, count, out, STRIDE);
            for (int i = 0; i < count; i++) {
                double x = u[i] - 0.5, y = v[i] - 0.5;
                for (int c = 0; c < 3; c++) {
                    double s = 0, su = 0, sv = 0;
                    for (int j = 0; j <= m; j++) {
                        for (int k = 0; k <= n; k++) {
                            double coef = a[3 * (j * (n + 1) + k) + c];
                            s += coef * Math.pow(x, k) * Math.pow(y, j);
                            su += k == 0 ? 0 : coef * k * Math.pow(x, k - 1) * Math.pow(y, j);
                            sv += j == 0 ? 0 : coef * j * Math.pow(x, k) * Math.pow(y, j - 1);
                        }
                    }
                    String where = "degree " + n + "x" + m + " at (" + u[i] + ", " + v[i] + "), coordinate " + c;
                    assertEquals(s, out[c * STRIDE + i], 1e-12, where);
                    assertEquals(su, out[(3 + c) * STRIDE + i], 1e-11, where);
                    assertEquals(sv, out[(6 + c) * STRIDE + i], 1e-11, where);
                }
            }
        }
    }

    @Test
    void unknownKernelNamesAreOneLineErrors() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Kernels.named("gpu"));
        assertEquals("kernel must be auto, scalar or simd, found \"gpu\"", e.getMessage());
        assertSame(Kernels.scalar(), Kernels.named("SCALAR"));
    }

    private static double[] randomForm(Random rnd, int n, int m, int off) {
        double[] a = new double[off + 3 * (n + 1) * (m + 1)];
        for (int k = off; k < a.length; k++) {
            a[k] = 2 * rnd.nextDouble() - 1;
        }
        return a;
    }
}
