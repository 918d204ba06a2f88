package org.beziertracer.accel;

/**
 * Ray–box slab test on boxes stored as six doubles {@code minX, minY, minZ, maxX, maxY, maxZ} at an
 * offset in a flat array. Stateless and allocation-free.
 *
 * <p><b>Zero direction components.</b> The ray comes as origin and reciprocal direction; a zero
 * component gives {@code invD = ±Infinity}. Per axis the near plane is chosen by the sign of
 * {@code invD} (not by comparing the two slab distances), so {@code -0.0 → -Infinity} and
 * {@code +0.0 → +Infinity} both pick the right plane. An origin strictly inside the slab then gives
 * {@code (-Infinity, +Infinity)} and one outside gives an empty interval. When the origin lies
 * exactly on a slab plane, {@code 0 * Infinity} is NaN; every update is written as
 * {@code if (t > near) near = t} (resp. {@code <}), which is false for NaN, so that plane is
 * ignored and the box faces count as inside (boxes are closed). No NaN ever reaches the result.
 *
 * <p><b>Robustness.</b> Each slab exit distance is multiplied by {@code 1 + 2γ₃} (γₙ = nε/(1-nε))
 * so a ray that touches a box is not lost to rounding (Pharr, Jakob, Humphreys, <i>Physically Based
 * Rendering</i>, 3rd ed., §3.9.2). Because rounding is monotone, a box that contains another is hit
 * whenever the inner one is, so a hierarchy of unions never culls what a leaf test would accept.
 */
public final class RayBox {

    /** Returned for a miss. */
    public static final double MISS = Double.POSITIVE_INFINITY;

    private static final double EPS = Math.ulp(1.0) * 0.5;
    /** {@code 1 + 2γ₃}: exit distances are scaled by this. */
    static final double ROBUST_EXIT = 1 + 2 * (3 * EPS / (1 - 3 * EPS));

    private RayBox() {}

    /**
     * Entry distance of the ray into the box at {@code boxes[offset..offset+5]}, clamped to
     * {@code tMin}; {@link #MISS} when the ray does not meet the box within {@code [tMin, tMax]}.
     * A finite result {@code t} satisfies {@code tMin <= t <= tMax}.
     */
    public static double entry(double[] boxes, int offset, double ox, double oy, double oz,
            double invDx, double invDy, double invDz, double tMin, double tMax) {
        return slab(boxes, offset, ox, oy, oz, invDx, invDy, invDz,
                nearOffset(invDx), nearOffset(invDy), nearOffset(invDz), tMin, tMax);
    }

    /** Offset (0 = min, 3 = max) of the plane a ray with this reciprocal component enters first. */
    static int nearOffset(double invD) {
        // Sign bit, so that -0.0 (never produced by 1/d, but possible from callers) also works.
        return (Double.doubleToRawLongBits(invD) < 0) ? 3 : 0;
    }

    /**
     * Slab test with the near-plane offsets ({@link #nearOffset}) precomputed once per ray, for
     * the traversal loops.
     */
    static double slab(double[] b, int o, double ox, double oy, double oz,
            double invDx, double invDy, double invDz, int sx, int sy, int sz,
            double tMin, double tMax) {
        double near = tMin, far = tMax;
        // NaN (origin on a plane of a zero-direction axis) fails every comparison: plane ignored.
        double lo = (b[o + sx] - ox) * invDx;
        double hi = (b[o + 3 - sx] - ox) * invDx * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        lo = (b[o + 1 + sy] - oy) * invDy;
        hi = (b[o + 4 - sy] - oy) * invDy * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        lo = (b[o + 2 + sz] - oz) * invDz;
        hi = (b[o + 5 - sz] - oz) * invDz * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        // near == +Infinity only for an origin outside a slab of a zero-direction axis.
        return near <= far && near < MISS ? near : MISS;
    }
}
