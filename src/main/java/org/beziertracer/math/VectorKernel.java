package org.beziertracer.math;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorSpecies;

/**
 * The SIMD {@link LaneKernel}, on the JDK's Vector API ({@code jdk.incubator.vector}, JEP 338 and
 * its successors): the lanes of a batch in the processor's widest double registers
 * ({@link DoubleVector#SPECIES_PREFERRED}: 8 lanes with AVX-512, 4 with AVX2); the last register
 * of a batch whole when the arrays have room past its lanes, else lane by lane in plain Java. Loaded only by {@link Kernels}, by name, when the
 * module is in the boot layer: a JVM started without it never loads this class.
 *
 * <p>Each lane computes what {@link ScalarKernel#powerFormAt} computes, operation for operation:
 * {@code mul} then {@code add}, each rounded (the Vector API never contracts them into a fused
 * multiply-add), so the bits are the scalar kernel's.
 */
final class VectorKernel implements LaneKernel {

    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_PREFERRED;

    @Override
    public int lanes() {
        return S.length();
    }

    @Override
    public String description() {
        return "SIMD, " + S.length() + " double lanes (" + S.vectorBitSize() + "-bit)";
    }

    @Override
    public void powerForm(double[] a, int off, int n, int m, double[] u, double[] v, int count, double[] out,
                          int stride) {
        int width = S.length();
        if (width == 1) {
            for (int i = 0; i < count; i++) {
                ScalarKernel.powerFormAt(a, off, n, m, u[i], v[i], out, i, stride);
            }
            return;
        }
        // Whole registers where the arrays have room past count (LaneKernel: those lanes are scratch);
        // the rest lane by lane (a masked register is much slower on JDK 17, and a mask argument
        // keeps C2 from compiling the whole-register block to vector instructions)
        int room = Math.min(stride, Math.min(u.length, v.length)), i0 = 0;
        for (; i0 < count && i0 + width <= room; i0 += width) {
            block(a, off, n, m, u, v, i0, out, stride);
        }
        for (; i0 < count; i0++) {
            ScalarKernel.powerFormAt(a, off, n, m, u[i0], v[i0], out, i0, stride);
        }
    }

    /** Lanes {@code i0 .. i0+width}, whole registers. */
    private static void block(double[] a, int off, int n, int m, double[] u, double[] v, int i0, double[] out,
                              int stride) {
        DoubleVector x = DoubleVector.fromArray(S, u, i0).sub(0.5);
        DoubleVector y = DoubleVector.fromArray(S, v, i0).sub(0.5);
        DoubleVector zero = DoubleVector.zero(S);
        DoubleVector sx = zero, sy = zero, sz = zero, ux = zero, uy = zero, uz = zero, vx = zero, vy = zero,
                vz = zero;
        int rowLen = 3 * (n + 1);
        for (int j = m, row = off + m * rowLen; j >= 0; j--, row -= rowLen) {
            int p = row + 3 * n;
            DoubleVector rx = DoubleVector.broadcast(S, a[p]), ry = DoubleVector.broadcast(S, a[p + 1]),
                    rz = DoubleVector.broadcast(S, a[p + 2]);
            DoubleVector dx = zero, dy = zero, dz = zero;
            for (int i = n - 1; i >= 0; i--) {
                p -= 3;
                dx = dx.mul(x).add(rx); dy = dy.mul(x).add(ry); dz = dz.mul(x).add(rz);
                rx = rx.mul(x).add(DoubleVector.broadcast(S, a[p]));
                ry = ry.mul(x).add(DoubleVector.broadcast(S, a[p + 1]));
                rz = rz.mul(x).add(DoubleVector.broadcast(S, a[p + 2]));
            }
            vx = vx.mul(y).add(sx); vy = vy.mul(y).add(sy); vz = vz.mul(y).add(sz);
            sx = sx.mul(y).add(rx); sy = sy.mul(y).add(ry); sz = sz.mul(y).add(rz);
            ux = ux.mul(y).add(dx); uy = uy.mul(y).add(dy); uz = uz.mul(y).add(dz);
        }
        sx.intoArray(out, i0); sy.intoArray(out, i0 + stride); sz.intoArray(out, i0 + 2 * stride);
        ux.intoArray(out, i0 + 3 * stride); uy.intoArray(out, i0 + 4 * stride); uz.intoArray(out, i0 + 5 * stride);
        vx.intoArray(out, i0 + 6 * stride); vy.intoArray(out, i0 + 7 * stride); vz.intoArray(out, i0 + 8 * stride);
    }
}
