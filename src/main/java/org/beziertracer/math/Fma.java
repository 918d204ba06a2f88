package org.beziertracer.math;

import java.lang.management.ManagementFactory;

import com.sun.management.HotSpotDiagnosticMXBean;

/**
 * Multiply-add for the evaluation kernels: {@link Math#fma} (one rounding, one instruction) where the
 * virtual machine compiles it to the processor's fused multiply-add, else {@code a·b + c}.
 * {@code Math.fma} is always correct, but without the instruction it is computed in
 * {@link java.math.BigDecimal} arithmetic, about a hundred times slower than the two operations it
 * replaces; HotSpot says whether it has the instruction in its {@code UseFMA} option (on by default
 * on every x86-64 processor since 2013 and on AArch64). Which form is used is decided once, when this
 * class is loaded; the JIT folds the choice away.
 *
 * <p>The two forms differ by at most one rounding of the product per call; the kernels that use
 * them are tested against de Casteljau at a tolerance of a few ulps per degree either way.
 */
public final class Fma {
    private Fma() {}

    /** True when {@link #mad} is a fused multiply-add. */
    public static final boolean FUSED = fusedByTheMachine();

    /** {@code a·b + c}, fused where that is fast ({@link #FUSED}). */
    public static double mad(double a, double b, double c) {
        return FUSED ? Math.fma(a, b, c) : a * b + c;
    }

    private static boolean fusedByTheMachine() {
        try {
            HotSpotDiagnosticMXBean vm = ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class);
            return vm != null && Boolean.parseBoolean(vm.getVMOption("UseFMA").getValue());
        } catch (RuntimeException | LinkageError e) {
            return false; // not HotSpot, or no management module: the plain form is always fast
        }
    }
}
