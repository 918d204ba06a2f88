package org.beziertracer.math;

import java.util.Locale;

/**
 * Chooses the {@link LaneKernel} once, at start: the SIMD one when the JVM was started with the
 * incubating Vector API ({@code java --add-modules jdk.incubator.vector …}, as the README's launch
 * command and the packaged app do), the scalar one otherwise — the optional-provider pattern of
 * Apache Lucene's {@code VectorizationProvider}. The system property {@code beziertracer.kernel}
 * ({@code scalar} or {@code simd}) overrides the choice (the CLI's {@code --kernel}). Both kernels
 * give the same bits, so the choice changes speed only.
 */
public final class Kernels {
    private Kernels() {}

    private static final String VECTOR_MODULE = "jdk.incubator.vector";
    private static final LaneKernel VECTOR = loadVector();
    /** How long {@link WarmingKernel} may measure before it keeps the scalar kernel. */
    private static final long WARM_UP_LIMIT_NANOS = 10_000_000_000L;
    /**
     * How long {@link WarmingKernel} waits after the first call before it starts to warm the SIMD kernel
     * up: the rent-or-buy rule (Karlin, Manasse, McGeoch and Owicki, "Competitive randomized
     * algorithms for nonuniform problems", Algorithmica 1994). Warming up costs about 0.8 s of one
     * core's time once (the uncompiled Vector API calls and their C2 compilation: a 240×180 path-traced
     * render took 3.3 s of CPU with the scalar kernel and 4.3 s with the warm-up at the first call,
     * on a 2-core EPYC); running the scalar kernel instead makes frames 5–25 % longer
     * ({@code FrameBench}), at most about 0.4 core-seconds a second on 2 cores. Buying when the
     * rent paid reaches the price (about 2 s) never costs more than twice the best choice made in
     * hindsight, and a one-shot render shorter than that pays nothing.
     */
    private static final long WARM_UP_DELAY_NANOS = 2_000_000_000L;
    private static final LaneKernel AUTO = VECTOR != null
            ? new WarmingKernel(VECTOR, ScalarKernel.INSTANCE, WARM_UP_DELAY_NANOS, WARM_UP_LIMIT_NANOS)
            : ScalarKernel.INSTANCE;
    private static final LaneKernel BEST = choose(System.getProperty("beziertracer.kernel"));

    /** The kernel chosen at start. */
    public static LaneKernel best() {
        return BEST;
    }

    /** The plain-Java kernel (always there). */
    public static LaneKernel scalar() {
        return ScalarKernel.INSTANCE;
    }

    /** True when the JVM has the Vector API module (then {@link #named}{@code ("simd")} is the SIMD kernel). */
    public static boolean vectorModulePresent() {
        return VECTOR != null;
    }

    /**
     * {@code "scalar"}, {@code "simd"} or {@code "auto"} (any case). {@code "auto"} is the SIMD
     * kernel when the module is there, answered by the scalar kernel until the JIT has compiled
     * the SIMD one ({@link WarmingKernel}: its first calls, uncompiled, cost a thousand times the
     * compiled ones); {@code "simd"} is the SIMD kernel from the first call.
     *
     * @throws IllegalArgumentException when the name is unknown, or "simd" without the module (a
     *                                  one-line message saying how to start Java)
     */
    public static LaneKernel named(String name) {
        switch (name.toLowerCase(Locale.ROOT)) {
            case "auto":
                return AUTO;
            case "scalar":
                return ScalarKernel.INSTANCE;
            case "simd":
                if (VECTOR == null) {
                    throw new IllegalArgumentException("the SIMD kernel needs Java started with --add-modules "
                            + VECTOR_MODULE);
                }
                return VECTOR;
            default:
                throw new IllegalArgumentException("kernel must be auto, scalar or simd, found \"" + name + "\"");
        }
    }

    private static LaneKernel choose(String property) {
        if (property != null) {
            try {
                return named(property);
            } catch (IllegalArgumentException e) {
                System.err.println("beziertracer.kernel: " + e.getMessage() + "; using " + named("auto").description());
            }
        }
        return named("auto");
    }

    private static LaneKernel loadVector() {
        if (ModuleLayer.boot().findModule(VECTOR_MODULE).isEmpty()) {
            return null;
        }
        try {
            return (LaneKernel) Class.forName("org.beziertracer.math.VectorKernel").getDeclaredConstructor().newInstance();
        } catch (ReflectiveOperationException | LinkageError | RuntimeException e) {
            return null; // a JVM whose module cannot run here: the scalar kernel, which gives the same bits
        }
    }
}
