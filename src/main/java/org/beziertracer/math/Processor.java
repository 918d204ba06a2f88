package org.beziertracer.math;

import java.lang.management.ManagementFactory;

import com.sun.management.HotSpotDiagnosticMXBean;

/**
 * What the evaluation kernels ask of the processor the virtual machine compiles for, read once from
 * HotSpot's own options when this class is loaded (the JIT then folds the choices away):
 * <ul>
 *   <li>{@link #WIDE_REGISTER_FILE}: whether compiled code has 32 floating-point registers (x86-64
 *       with AVX-512, {@code UseAVX} ≥ 3; AArch64), not 16. A kernel that keeps two rows' sums in
 *       registers at once is faster with 32 and slower with 16, where they spill
 *       ({@code BernsteinEval}).</li>
 * </ul>
 * Not HotSpot, or no management module: no (the plain forms are always correct and fast).
 *
 * <p>No choice here changes a result: {@link #mad} is never fused, on any processor (a fused
 * multiply-add rounds once where the product and the sum round twice, so a render would differ
 * bit-wise between machines with and without the instruction; JOML keeps FMA opt-in for the same
 * reason), and the SIMD kernels ({@link LaneKernel}) compute the same separately rounded operations.
 */
public final class Processor {
    private Processor() {}

    /** True when compiled code has 32 floating-point registers. */
    public static final boolean WIDE_REGISTER_FILE = "aarch64".equals(System.getProperty("os.arch"))
            || option("UseAVX", 3);

    /** {@code a·b + c}: the product rounded, then the sum (never fused, on any processor). */
    public static double mad(double a, double b, double c) {
        return a * b + c;
    }

    /** True when HotSpot's option {@code name} (a flag, or a number) is set to at least {@code least}. */
    static boolean option(String name, int least) {
        try {
            HotSpotDiagnosticMXBean vm = ManagementFactory.getPlatformMXBean(HotSpotDiagnosticMXBean.class);
            String value = vm == null ? null : vm.getVMOption(name).getValue();
            if (value == null) {
                return false;
            }
            return "true".equals(value) || !"false".equals(value) && Long.parseLong(value) >= least;
        } catch (RuntimeException | LinkageError e) {
            return false; // not HotSpot, no management module, no such option on this processor
        }
    }
}
