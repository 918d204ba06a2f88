package org.beziertracer.model;

import java.util.Arrays;

import org.beziertracer.math.Aabb;

/**
 * An immutable tensor-product Bézier patch of degree {@code n} in u and {@code m} in v.
 *
 * <h2>Control-net layout</h2>
 * The {@code (n+1)(m+1)} control points {@code P_ij} ({@code i = 0..n} along u,
 * {@code j = 0..m} along v) are stored in one flat array of {@code (n+1)(m+1)*3} doubles,
 * <b>u index varying fastest</b>: point {@code k = j*(n+1) + i} holds {@code P_ij}, and its
 * coordinates are at {@code 3k, 3k+1, 3k+2}. This is the order of the BPT file format.
 *
 * <p>The surface is {@code S(u,v) = Σ_i Σ_j B_i^n(u) B_j^m(v) P_ij} on {@code [0,1]²}.
 *
 * <p>Instances are immutable and safe to share between threads: the constructor copies the
 * array and {@link #copyNet()} returns a copy. Degrees run from 1 to {@value #MAX_DEGREE}.
 */
public final class BezierPatch {

    /** Highest degree accepted in either direction. */
    public static final int MAX_DEGREE = 15;

    private final int n;
    private final int m;
    private final double[] net;

    /**
     * @param n   degree in u, 1..{@value #MAX_DEGREE}
     * @param m   degree in v, 1..{@value #MAX_DEGREE}
     * @param net {@code (n+1)(m+1)*3} finite coordinates, u fastest (copied)
     * @throws IllegalArgumentException for a degree out of range, a wrong array length or a
     *                                  NaN/infinite coordinate
     */
    public BezierPatch(int n, int m, double[] net) {
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
        this.n = n;
        this.m = m;
        this.net = net.clone();
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

    /** A new patch with control point {@code P_ij} moved to {@code (x,y,z)}. */
    public BezierPatch withPoint(int i, int j, double x, double y, double z) {
        double[] copy = net.clone();
        int k = index(i, j, 0);
        copy[k] = x;
        copy[k + 1] = y;
        copy[k + 2] = z;
        return new BezierPatch(n, m, copy);
    }

    /** Axis-aligned box of the control points; by the convex-hull property it contains the surface. */
    public Aabb controlBounds() { return Aabb.ofPoints(net); }

    @Override
    public boolean equals(Object o) {
        return o instanceof BezierPatch p && p.n == n && p.m == m && Arrays.equals(p.net, net);
    }

    @Override
    public int hashCode() { return 31 * (31 * n + m) + Arrays.hashCode(net); }

    @Override
    public String toString() { return "BezierPatch[" + n + "x" + m + "]"; }
}
