package org.beziertracer.geometry;

/**
 * The sub-patches of one patch, in flat arrays (immutable after construction; the arrays are
 * never modified and are shared with {@link SubPatchTable}).
 *
 * <ul>
 *   <li>{@code nets}: the control nets one after another, each {@code (n+1)(m+1)*3} doubles in
 *       the {@code BezierPatch} layout (u fastest) — Euclidean points, also for a rational patch;</li>
 *   <li>{@code boxes}: 4 doubles per piece, {@code u0, u1, v0, v1}: its parameter box inside the
 *       parent patch;</li>
 *   <li>{@code weights}: null for a polynomial patch, else {@code (n+1)(m+1)} weights per piece,
 *       in the order of the points;</li>
 *   <li>{@code trimTest}: null for an untrimmed patch, else per piece whether its hits must be
 *       tested against the trim loops (pieces wholly inside need not; pieces wholly outside are
 *       not here at all).</li>
 * </ul>
 */
public record PatchPieces(int degreeU, int degreeV, int count, double[] nets, double[] boxes, double[] weights,
                          boolean[] trimTest) {
    /** Doubles per control net. */
    public int netLength() { return (degreeU + 1) * (degreeV + 1) * 3; }

    /** The pieces of {@code a} then those of {@code b} (two parts of one patch, same degree and kind). */
    static PatchPieces concat(PatchPieces a, PatchPieces b) {
        return new PatchPieces(a.degreeU, a.degreeV, a.count + b.count, join(a.nets, b.nets), join(a.boxes, b.boxes),
                a.weights == null ? null : join(a.weights, b.weights), a.trimTest == null ? null : join(a.trimTest, b.trimTest));
    }

    private static double[] join(double[] a, double[] b) {
        double[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    private static boolean[] join(boolean[] a, boolean[] b) {
        boolean[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }
}
