package org.beziertracer.accel;

/**
 * Ray–box slab test on boxes stored as six numbers {@code minX, minY, minZ, maxX, maxY, maxZ} at an
 * offset in a flat array: {@code double[]} for exact boxes ({@link #entry}), {@code float[]} for
 * the hierarchy's boxes, which are rounded outward when they are made (so a float box contains
 * the double box it stands for). Stateless and allocation-free; the arithmetic is in double either
 * way.
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
 * whenever the inner one is, so a hierarchy of unions (and of outward-rounded float boxes) never
 * culls what a leaf test would accept.
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
        int sx = nearOffset(invDx), sy = nearOffset(invDy), sz = nearOffset(invDz);
        int o = offset;
        return interval(boxes[o + sx], boxes[o + 3 - sx], boxes[o + 1 + sy], boxes[o + 4 - sy],
                boxes[o + 2 + sz], boxes[o + 5 - sz], ox, oy, oz, invDx, invDy, invDz, tMin, tMax);
    }

    /** {@link #entry} on a float box (as stored by {@link Bvh} and {@link FlatList}). */
    public static double entry(float[] boxes, int offset, double ox, double oy, double oz,
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
     * Slab test on a float box with the near-plane offsets ({@link #nearOffset}) precomputed once
     * per ray, for the traversal loops.
     */
    static double slab(float[] b, int o, double ox, double oy, double oz,
            double invDx, double invDy, double invDz, int sx, int sy, int sz,
            double tMin, double tMax) {
        return interval(b[o + sx], b[o + 3 - sx], b[o + 1 + sy], b[o + 4 - sy], b[o + 2 + sz],
                b[o + 5 - sz], ox, oy, oz, invDx, invDy, invDz, tMin, tMax);
    }

    /** The slab intersection for the box planes the ray enters ({@code near*}) and leaves ({@code far*}). */
    private static double interval(double nearX, double farX, double nearY, double farY, double nearZ,
            double farZ, double ox, double oy, double oz, double invDx, double invDy, double invDz,
            double tMin, double tMax) {
        double near = tMin, far = tMax;
        // NaN (origin on a plane of a zero-direction axis) fails every comparison: plane ignored.
        double lo = (nearX - ox) * invDx;
        double hi = (farX - ox) * invDx * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        lo = (nearY - oy) * invDy;
        hi = (farY - oy) * invDy * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        lo = (nearZ - oz) * invDz;
        hi = (farZ - oz) * invDz * ROBUST_EXIT;
        if (lo > near) near = lo;
        if (hi < far) far = hi;
        // near == +Infinity only for an origin outside a slab of a zero-direction axis.
        return near <= far && near < MISS ? near : MISS;
    }

    /** The largest float not above {@code x} (a box minimum rounded outward). */
    public static float down(double x) {
        float f = (float) x;
        return f > x ? Math.nextDown(f) : f;
    }

    /** The smallest float not below {@code x} (a box maximum rounded outward). */
    public static float up(double x) {
        float f = (float) x;
        return f < x ? Math.nextUp(f) : f;
    }

    /**
     * Writes box {@code src[s..s+5]} (doubles) rounded outward to floats at {@code dst[d..d+5]}:
     * the float box contains the double box.
     */
    public static void roundOutward(double[] src, int s, float[] dst, int d) {
        dst[d] = down(src[s]);
        dst[d + 1] = down(src[s + 1]);
        dst[d + 2] = down(src[s + 2]);
        dst[d + 3] = up(src[s + 3]);
        dst[d + 4] = up(src[s + 4]);
        dst[d + 5] = up(src[s + 5]);
    }
}
