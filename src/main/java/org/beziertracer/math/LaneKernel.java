package org.beziertracer.math;

/**
 * The arithmetic that runs across the lanes of a ray batch: one implementation on the JDK's
 * Vector API ({@code jdk.incubator.vector}, SIMD registers) and one in plain Java, chosen once at
 * start by {@link Kernels} (the optional-provider pattern of Apache Lucene's
 * {@code VectorizationProvider}). Every method gives the same bits in both: each lane runs the same
 * sequence of separately rounded multiplies and adds (never a fused multiply-add), so a picture does
 * not depend on the kernel, the machine or the lane count.
 *
 * <h2>Lanes</h2>
 * Inputs and outputs are structure-of-arrays: lane {@code i} of a quantity at {@code [i]}; a
 * quantity with several components at {@code out[c·stride + i]}. {@code count} lanes are computed,
 * from lane 0. The lanes after them, up to {@code count} rounded up to a multiple of {@link #lanes()},
 * are scratch where the arrays have room for them (inputs shorter, or {@code stride} smaller, than
 * that: they are neither read nor written): a kernel may fill whole registers there, on whatever
 * the inputs hold, and write those lanes' meaningless results. Give the arrays that room when speed
 * matters (a partial register costs a mask).
 *
 * <p>Implementations are stateless and thread-safe; they allocate nothing per call.
 */
public interface LaneKernel {

    /** Most lanes a batch needs for this kernel to fill its registers (a batch may hold any number). */
    int lanes();

    /** What runs, for {@code --version}, {@code render --stats} and Help → About. */
    String description();

    /**
     * A 3-D polynomial patch in centred power form ({@code org.beziertracer.geometry.PowerForm}: the
     * coefficient of {@code xⁱyʲ}, {@code x = u − ½}, {@code y = v − ½}, at
     * {@code a[off + 3·(j·(n+1) + i) ..+3]}) evaluated with its first derivatives at the points
     * {@code (u[i], v[i])}, {@code i < count}, by Horner's rule: per row {@code j} (from the highest)
     * the row's value and its x-derivative, then the rows' sums in {@code y}. Writes {@code S} to
     * components 0..2, {@code ∂S/∂u} to 3..5 and {@code ∂S/∂v} to 6..8 of {@code out} (component
     * {@code c} of lane {@code i} at {@code out[c·stride + i]}).
     */
    void powerForm(double[] a, int off, int n, int m, double[] u, double[] v, int count, double[] out, int stride);
}
