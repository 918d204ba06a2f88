package org.beziertracer.geometry;

/**
 * The sub-patches of one patch, in flat arrays (immutable after construction; the arrays are
 * never modified and are shared with {@link SubPatchTable}).
 *
 * <ul>
 *   <li>{@code nets}: the control nets one after another, each {@code (n+1)(m+1)*3} doubles in
 *       the {@code BezierPatch} layout (u fastest);</li>
 *   <li>{@code boxes}: 4 doubles per piece, {@code u0, u1, v0, v1}: its parameter box inside the
 *       parent patch.</li>
 * </ul>
 */
public record PatchPieces(int degreeU, int degreeV, int count, double[] nets, double[] boxes) {
    /** Doubles per control net. */
    public int netLength() { return (degreeU + 1) * (degreeV + 1) * 3; }
}
