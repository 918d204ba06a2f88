package org.beziertracer;

/**
 * The named tolerances of the tests, each with what it bounds and why it has that value. Tests
 * use these (times a scale where the quantity has one) instead of re-typing literals, so that
 * "how close is close" is decided once and reads the same everywhere. Constants that follow from
 * one test's own derivation (a finite-difference step, a chord bound) stay in that test, named.
 */
public final class Tolerances {
    private Tolerances() {}

    /**
     * Two double computations of the same value, or an identity that holds in exact arithmetic
     * (a unit normal's length, a split reproducing its parent), for a quantity of magnitude about
     * 1 (multiply by the scale otherwise): about 4,500 ulps of 1, room for the rounding of a few
     * hundred operations and no more.
     */
    public static final double ROUNDING = 1e-12;

    /**
     * A value derived through trigonometry, square roots or a linear solve from exact inputs
     * (camera angles, distances after rotations), relative to its magnitude: the conditioning of
     * {@code acos}/{@code atan} near their flat ends costs about three digits over
     * {@link #ROUNDING}.
     */
    public static final double DERIVED = 1e-9;

    /**
     * A float (24-bit mantissa, relative precision 6e-8) image value against the double it was
     * accumulated from, for values of magnitude about 1 summed over a few samples.
     */
    public static final double FLOAT = 1e-5;

    /**
     * The ray parameter t of an exact root (and the hit point along the ray), as a fraction of the
     * scene size: the solvers converge to a residual of 1e-12 of the scene size
     * ({@code PatchLeaves.RELATIVE_TOLERANCE}), and a root's t is that residual divided by the
     * sine of the angle between ray and surface, so 1e-9 allows angles down to about 0.06°.
     */
    public static final double ROOT_T = 1e-9;

    /**
     * The parameters (u,v) of an exact root against the (u,v) the ray was aimed at: a t within
     * {@link #ROOT_T} moves (u,v) by t's error over the surface's speed |∂S/∂u|, which on the
     * random test patches (degree up to 9, nets folded to 60 % relief) falls to about 1e-3 of
     * the patch size.
     */
    public static final double ROOT_UV = 1e-6;

    /**
     * The (u,v) of the same root found by two exact methods that both end with Newton on the
     * parent patch (clipping and the slow reference): only the final iterate's rounding differs.
     */
    public static final double SAME_ROOT_UV = 1e-7;

    /**
     * Distance of a reported hit point {@code o + t·d} from the surface point {@code S(u,v)}, as a
     * fraction of the scene size: ten times {@link #ROOT_T}, since t and (u,v) each carry their own
     * error.
     */
    public static final double ON_SURFACE = 1e-8;

    /**
     * A unit normal's direction against a known exact direction (1 − |cos|, or a component): the
     * normal is a cross product of derivatives that carry the root's (u,v) error
     * {@link #ROOT_UV}.
     */
    public static final double NORMAL = 1e-6;

    /**
     * The subdivision method's t against the exact t, as a fraction of the patch size: it stops
     * halving at 1e-3 of the leaf size ({@code SubdivisionSolver.TINY}) and intersects the
     * control mesh, whose distance from the surface is at most that piece size.
     */
    public static final double SUBDIVISION_T = 1e-3;

    /**
     * A colour channel of a shaded pixel (linear, magnitude about 1) against its closed-form
     * value: the hit is exact to {@link #ROOT_T}, and the normal and Phong terms carry that error
     * through a few products and a power.
     */
    public static final double COLOUR = 1e-6;
}
