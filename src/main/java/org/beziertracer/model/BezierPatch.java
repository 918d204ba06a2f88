package org.beziertracer.model;

import java.util.Arrays;
import java.util.Objects;

import org.beziertracer.math.Aabb;
import org.beziertracer.math.Bounds;

/**
 * An immutable tensor-product Bézier patch of degree {@code n} in u and {@code m} in v.
 *
 * <h2>Control-net layout</h2>
 * The {@code (n+1)(m+1)} control points {@code P_ij} ({@code i = 0..n} along u,
 * {@code j = 0..m} along v) are stored in one flat array of {@code (n+1)(m+1)*3} doubles,
 * <b>u index varying fastest</b>: point {@code k = j*(n+1) + i} holds {@code P_ij}, and its
 * coordinates are at {@code 3k, 3k+1, 3k+2}. This is the order of the BPT file format.
 *
 * <p>The surface is {@code S(u,v) = Σ_i Σ_j B_i^n(u) B_j^m(v) P_ij} on {@code [0,1]²}. A
 * <b>rational</b> patch has a positive weight {@code w_ij} per control point (same order) and is
 * {@code S(u,v) = Σ w_ij P_ij B_i^n(u) B_j^m(v) / Σ w_ij B_i^n(u) B_j^m(v)}; a patch whose weights
 * are all exactly 1 is stored as polynomial ({@link #weights()} is null), so it keeps the
 * polynomial code paths and their results bit for bit.
 *
 * <p>A patch cut from a free-form surface also carries its {@link PatchDomain} (the part of the
 * surface's parameter domain it covers, and the surface's trim loops) and its
 * {@link PatchOrigin}; a plain patch has neither.
 *
 * <p>Instances are immutable and safe to share between threads: the constructor copies the
 * arrays and {@link #copyNet()} returns a copy. Degrees run from 1 to {@value #MAX_DEGREE}.
 */
public final class BezierPatch {

    /** Highest degree accepted in either direction. */
    public static final int MAX_DEGREE = 15;

    private final int n;
    private final int m;
    private final double[] net;
    /** Null for a polynomial patch. */
    private final double[] weights;
    /** Null for {@code [0,1]²} untrimmed. */
    private final PatchDomain domain;
    private final PatchOrigin origin;

    /** A polynomial patch; see {@link #BezierPatch(int, int, double[], double[], PatchDomain, PatchOrigin)}. */
    public BezierPatch(int n, int m, double[] net) {
        this(n, m, net, null, null, null);
    }

    /**
     * @param n   degree in u, 1..{@value #MAX_DEGREE}
     * @param m   degree in v, 1..{@value #MAX_DEGREE}
     * @param net {@code (n+1)(m+1)*3} finite coordinates, u fastest (copied)
     * @param weights null (polynomial) or {@code (n+1)(m+1)} positive finite weights (copied);
     *                all 1 gives a polynomial patch
     * @param domain  null or the patch's part of its surface's domain ({@link PatchDomain#UNIT}
     *                counts as none)
     * @param origin  null or the free-form surface the patch was cut from
     * @throws IllegalArgumentException for a degree out of range, a wrong array length, a
     *                                  NaN/infinite coordinate or a weight that is not positive
     *                                  and finite
     */
    public BezierPatch(int n, int m, double[] net, double[] weights, PatchDomain domain, PatchOrigin origin) {
        this(n, m, net, weights, domain, origin, false);
    }

    /**
     * The public constructor's patch; with {@code adopt} the net is kept, not copied: for nets made
     * in this package that nothing else holds or changes (a free-form surface's pieces, or the
     * surface's own immutable points when it is one piece), which saves a copy a patch on models
     * of a million patches.
     */
    BezierPatch(int n, int m, double[] net, double[] weights, PatchDomain domain, PatchOrigin origin,
                boolean adopt) {
        checkDegree("u", n);
        checkDegree("v", m);
        if (net == null) {
            throw new IllegalArgumentException("control net is null");
        }
        int expected = (n + 1) * (m + 1) * 3;
        if (net.length != expected) {
            throw new IllegalArgumentException("control net of a degree " + n + "x" + m + " patch needs "
                    + expected + " coordinates ((n+1)(m+1) points), got " + net.length);
        }
        for (int k = 0; k < net.length; k++) {
            if (!Double.isFinite(net[k])) {
                int point = k / 3;
                throw new IllegalArgumentException("control point P(" + point % (n + 1) + "," + point / (n + 1)
                        + ") has a non-finite " + "xyz".charAt(k % 3) + " coordinate: " + net[k]);
            }
        }
        if (weights != null) {
            checkWeights(weights, (n + 1) * (m + 1));
        }
        this.n = n;
        this.m = m;
        this.net = adopt ? net : net.clone();
        this.weights = weights == null || allOnes(weights) ? null : adopt ? weights : weights.clone();
        this.domain = domain == null || domain.isUnit() ? null : domain;
        this.origin = origin;
    }

    /**
     * A patch from a net of {@code dim = 3} Euclidean points, or of {@code dim = 4} homogeneous
     * points {@code (w·x, w·y, w·z, w)} (divided out here).
     */
    public static BezierPatch fromNet(int n, int m, double[] net, int dim, PatchDomain domain, PatchOrigin origin) {
        return fromNet(n, m, net, dim, domain, origin, false);
    }

    /** {@link #fromNet}; with {@code adopt}, a net of {@code dim = 3} is kept, not copied (the adopting constructor). */
    static BezierPatch fromNet(int n, int m, double[] net, int dim, PatchDomain domain, PatchOrigin origin,
                               boolean adopt) {
        if (dim == 3) {
            return new BezierPatch(n, m, net, null, domain, origin, adopt);
        }
        int count = net.length / 4;
        double[] xyz = new double[3 * count], w = new double[count];
        for (int k = 0; k < count; k++) {
            w[k] = net[4 * k + 3];
            xyz[3 * k] = net[4 * k] / w[k];
            xyz[3 * k + 1] = net[4 * k + 1] / w[k];
            xyz[3 * k + 2] = net[4 * k + 2] / w[k];
        }
        return new BezierPatch(n, m, xyz, w, domain, origin, true); // xyz and w are made here
    }

    /**
     * Throws an {@link IllegalArgumentException} unless {@code weights} holds {@code count}
     * positive finite values.
     */
    public static void checkWeights(double[] weights, int count) {
        if (weights.length != count) {
            throw new IllegalArgumentException("expected " + count + " weights (one per control point), got "
                    + weights.length);
        }
        for (int k = 0; k < count; k++) {
            if (!(weights[k] > 0 && weights[k] < Double.POSITIVE_INFINITY)) {
                throw new IllegalArgumentException("expected positive finite weights, found " + weights[k]
                        + " for control point " + (k + 1));
            }
        }
    }

    private static boolean allOnes(double[] weights) {
        for (double w : weights) {
            if (w != 1) {
                return false;
            }
        }
        return true;
    }

    /** Throws an {@link IllegalArgumentException} naming the direction when a degree is out of range. */
    public static void checkDegree(String direction, int degree) {
        if (degree < 1 || degree > MAX_DEGREE) {
            throw new IllegalArgumentException("degree in " + direction + " must be 1.." + MAX_DEGREE + ", got " + degree);
        }
    }

    /** Degree in u. */
    public int degreeU() { return n; }

    /** Degree in v. */
    public int degreeV() { return m; }

    /** Number of control points, {@code (n+1)(m+1)}. */
    public int pointCount() { return (n + 1) * (m + 1); }

    /** Index in the flat net of coordinate {@code c} (0=x,1=y,2=z) of {@code P_ij}. */
    public int index(int i, int j, int c) { return 3 * (j * (n + 1) + i) + c; }

    /** Coordinate {@code c} (0=x, 1=y, 2=z) of control point {@code P_ij}. */
    public double get(int i, int j, int c) { return net[index(i, j, c)]; }

    /** A fresh copy of the control net (layout as in the class comment). */
    public double[] copyNet() { return net.clone(); }

    /** Copies the control net into {@code dest} at {@code offset}. */
    public void copyNetInto(double[] dest, int offset) {
        System.arraycopy(net, 0, dest, offset, net.length);
    }

    /** True when the patch has weights (not all 1). */
    public boolean isRational() { return weights != null; }

    /** A copy of the weights (layout of the points), or null for a polynomial patch. */
    public double[] weights() { return weights == null ? null : weights.clone(); }

    /** Weight of {@code P_ij} (1 for a polynomial patch). */
    public double weight(int i, int j) { return weights == null ? 1 : weights[j * (n + 1) + i]; }

    /** The patch's part of its surface's parameter domain; {@link PatchDomain#UNIT} when it has none. */
    public PatchDomain domain() { return domain == null ? PatchDomain.UNIT : domain; }

    /** The trim region of the patch's surface, or null when untrimmed. */
    public TrimRegion trim() { return domain == null ? null : domain.trim(); }

    /** The free-form surface the patch was cut from, or null. */
    public PatchOrigin origin() { return origin; }

    /**
     * A new patch with control point {@code P_ij} moved to {@code (x,y,z)}; weights and domain
     * are kept, the origin is dropped (the patch no longer matches its surface).
     */
    public BezierPatch withPoint(int i, int j, double x, double y, double z) {
        double[] copy = net.clone();
        int k = index(i, j, 0);
        copy[k] = x;
        copy[k + 1] = y;
        copy[k + 2] = z;
        return withNet(copy);
    }

    /** A new patch with another net of the same size; weights and domain kept, origin dropped. */
    public BezierPatch withNet(double[] newNet) {
        return new BezierPatch(n, m, newNet, weights, domain, null);
    }

    /**
     * Axis-aligned box of the control points; by the convex-hull property it contains the surface
     * (for a rational patch too, its weights being positive).
     */
    public Aabb controlBounds() { return Aabb.ofPoints(net); }

    /**
     * {@link #controlBounds()} into {@code box[0..5]} ({@link Bounds#ofPoints}), without making a
     * box: what walks over every patch of a model of a million patches uses.
     */
    public void controlBoundsInto(double[] box) { Bounds.ofPoints(net, 0, net.length / 3, box); }

    /** Equal patches have equal geometry, weights and domain; the origin does not count. */
    @Override
    public boolean equals(Object o) {
        return o instanceof BezierPatch p && p.n == n && p.m == m && Arrays.equals(p.net, net)
                && Arrays.equals(p.weights, weights) && Objects.equals(p.domain, domain);
    }

    @Override
    public int hashCode() { return 31 * (31 * (31 * n + m) + Arrays.hashCode(net)) + Arrays.hashCode(weights); }

    @Override
    public String toString() { return "BezierPatch[" + n + "x" + m + (weights == null ? "" : ", rational") + "]"; }
}
