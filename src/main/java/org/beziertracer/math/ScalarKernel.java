package org.beziertracer.math;

/**
 * The plain-Java {@link LaneKernel}: one lane at a time, each exactly as the SIMD kernel computes
 * it ({@link #powerFormAt}, also the single-ray evaluation of {@code PowerForm}).
 */
public final class ScalarKernel implements LaneKernel {

    static final ScalarKernel INSTANCE = new ScalarKernel();

    private ScalarKernel() {}

    @Override
    public int lanes() {
        return 8;
    }

    @Override
    public String description() {
        return Kernels.vectorModulePresent()
                ? "scalar (chosen; SIMD is available)"
                : "scalar: start Java with --add-modules jdk.incubator.vector for SIMD";
    }

    @Override
    public void powerForm(double[] a, int off, int n, int m, double[] u, double[] v, int count, double[] out,
                          int stride) {
        for (int i = 0; i < count; i++) {
            powerFormAt(a, off, n, m, u[i], v[i], out, i, stride);
        }
    }

    /**
     * One lane of {@link #powerForm}: component {@code c} of the result at {@code out[outOff + c·stride]}.
     * Each step is a product rounded, then a sum rounded (no fused multiply-add: the SIMD kernel
     * computes the same bits).
     */
    public static void powerFormAt(double[] a, int off, int n, int m, double u, double v, double[] out, int outOff,
                                   int stride) {
        double x = u - 0.5, y = v - 0.5;
        int rowLen = 3 * (n + 1);
        double sx = 0, sy = 0, sz = 0, ux = 0, uy = 0, uz = 0, vx = 0, vy = 0, vz = 0;
        for (int j = m, row = off + m * rowLen; j >= 0; j--, row -= rowLen) {
            int p = row + 3 * n;
            double rx = a[p], ry = a[p + 1], rz = a[p + 2], dx = 0, dy = 0, dz = 0;
            for (int i = n - 1; i >= 0; i--) {
                p -= 3;
                dx = dx * x + rx; dy = dy * x + ry; dz = dz * x + rz;
                rx = rx * x + a[p]; ry = ry * x + a[p + 1]; rz = rz * x + a[p + 2];
            }
            vx = vx * y + sx; vy = vy * y + sy; vz = vz * y + sz;
            sx = sx * y + rx; sy = sy * y + ry; sz = sz * y + rz;
            ux = ux * y + dx; uy = uy * y + dy; uz = uz * y + dz;
        }
        out[outOff] = sx; out[outOff + stride] = sy; out[outOff + 2 * stride] = sz;
        out[outOff + 3 * stride] = ux; out[outOff + 4 * stride] = uy; out[outOff + 5 * stride] = uz;
        out[outOff + 6 * stride] = vx; out[outOff + 7 * stride] = vy; out[outOff + 8 * stride] = vz;
    }
}
