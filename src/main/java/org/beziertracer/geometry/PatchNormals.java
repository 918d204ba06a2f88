package org.beziertracer.geometry;

/**
 * Unit surface normals of 3-D Bézier patches, with a limit normal where the surface is
 * degenerate. Allocation-free; thread-safe with one scratch array per thread.
 *
 * <h2>Regular points</h2>
 * {@code N = (∂S/∂u × ∂S/∂v) / |∂S/∂u × ∂S/∂v|}, the derivatives taken exactly from the
 * de Casteljau intermediate points ({@link DeCasteljau#evaluateWithDerivatives}; Farin,
 * <i>Curves and Surfaces for CAGD</i>). The orientation is always that of
 * {@code ∂S/∂u × ∂S/∂v}: no flipping towards a viewer happens here.
 *
 * <h2>Degenerate points and the method used</h2>
 * Where an edge collapses to a point (the Utah teapot's lid top, a "triangular" patch) one
 * partial derivative vanishes along that edge; where a control polygon has coincident end
 * points a tangent vanishes; in both cases the cross product is zero (or pure rounding noise)
 * although the surface has a well-defined tangent plane in the limit. A point counts as
 * degenerate when {@code |∂S/∂u × ∂S/∂v| ≤ }{@value #DEGENERATE_RELATIVE}{@code · n·m·L²},
 * {@code L} being the largest extent of the control net's bounding box (so the test is
 * independent of units and degree).
 *
 * <p>At a degenerate point we <b>step inward</b>: the parameters move a fraction {@code δ} of
 * the way toward the patch centre {@code (½,½)}, the cross product is re-evaluated there, and
 * {@code δ} grows ({@code 1e-7, 1e-5, 1e-3, 1e-1, ½, 1}) until the cross product is regular.
 * Because {@code N} is continuous on the open patch and the step stays inside it, the result
 * is the limit normal up to an angular error of order {@code δ} (about {@code 1e-7} rad for
 * the collapsed edges of the teapot), and its orientation is by construction that of the
 * nearby regular points. A first-order Taylor expansion of the cross product shows why the
 * first step normally suffices: at a collapsed edge {@code v = 0},
 * {@code S_u(u,δ) ≈ δ·S_uv(u,0)}, so the cross product grows linearly in {@code δ}.
 *
 * <p>If no step gives a regular point (the whole patch is a curve or a point), the normal of
 * the control net's diagonals {@code (P_nm − P_00) × (P_0m − P_n0)} is used, and if that too
 * vanishes, {@code +z}. The result is therefore never NaN and never zero for a finite net.
 *
 * <h2>Rational patches</h2>
 * Every method has a {@code dim} form: {@code dim = 3} is a polynomial net, {@code dim = 4} a
 * homogeneous rational net ({@link RationalDeCasteljau}), whose derivatives come from the
 * quotient rule; the degenerate-point method is the same (a sphere's poles are collapsed edges of
 * its rational patches), the extent and the diagonal normal use the Euclidean points.
 */
public final class PatchNormals {

    /** Relative size of the cross product below which a point counts as degenerate. */
    public static final double DEGENERATE_RELATIVE = 1e-10;

    /** Fractions of the way to the patch centre tried, in order, at a degenerate point. */
    private static final double[] INWARD_STEPS = {1e-7, 1e-5, 1e-3, 1e-1, 0.5, 1.0};

    private static final int DERIV = 0;          // S, Su, Sv in scratch[0..9)
    private static final int WORK = 9;           // scratch for evaluateWithDerivatives

    private PatchNormals() {}

    /**
     * Writes the unit normal at {@code (u,v)} of the 3-D net (layout as in {@link DeCasteljau})
     * into {@code out[outOff .. outOff+3)}. {@code scratch} needs
     * {@link DeCasteljau#SCRATCH_LENGTH} doubles.
     */
    public static void unitNormal(double[] net, int off, int n, int m, double u, double v,
                                  double[] out, int outOff, double[] scratch) {
        unitNormal(net, off, n, m, 3, u, v, out, outOff, scratch);
    }

    /** {@link #unitNormal(double[], int, int, int, double, double, double[], int, double[])} for
     *  {@code dim = 3} (polynomial) or {@code dim = 4} (homogeneous rational) nets. */
    public static void unitNormal(double[] net, int off, int n, int m, int dim, double u, double v,
                                  double[] out, int outOff, double[] scratch) {
        double threshold = DEGENERATE_RELATIVE * n * m * squaredExtent(net, off, n, m, dim);
        if (crossAt(net, off, n, m, dim, u, v, out, outOff, scratch, threshold)) {
            return;
        }
        limitNormal(net, off, n, m, dim, u, v, out, outOff, scratch, threshold);
    }

    /**
     * As {@link #unitNormal}, for a caller that already evaluated the derivatives at
     * {@code (u,v)}: {@code deriv[3..5] = S_u}, {@code deriv[6..8] = S_v} (the layout of
     * {@link DeCasteljau#evaluateWithDerivatives}). Re-evaluates only at a degenerate point.
     */
    public static void unitNormal(double[] net, int off, int n, int m, double u, double v, double[] deriv,
                                  double[] out, int outOff, double[] scratch) {
        unitNormal(net, off, n, m, u, v, deriv, squaredExtent(net, off, n, m), out, outOff, scratch);
    }

    /**
     * As {@link #unitNormal(double[], int, int, int, double, double, double[], double[], int,
     * double[])} with the net's {@link #squaredExtent} computed once by the caller (it is a
     * property of the patch, not of the point).
     */
    public static void unitNormal(double[] net, int off, int n, int m, double u, double v, double[] deriv,
                                  double squaredExtent, double[] out, int outOff, double[] scratch) {
        unitNormal(net, off, n, m, 3, u, v, deriv, squaredExtent, out, outOff, scratch);
    }

    /** The previous method for {@code dim = 3} (polynomial) or {@code dim = 4} (homogeneous rational) nets. */
    public static void unitNormal(double[] net, int off, int n, int m, int dim, double u, double v, double[] deriv,
                                  double squaredExtent, double[] out, int outOff, double[] scratch) {
        double threshold = DEGENERATE_RELATIVE * n * m * squaredExtent;
        double ux = deriv[3], uy = deriv[4], uz = deriv[5];
        double vx = deriv[6], vy = deriv[7], vz = deriv[8];
        if (!store(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx, threshold, out, outOff)) {
            limitNormal(net, off, n, m, dim, u, v, out, outOff, scratch, threshold);
        }
    }

    private static void limitNormal(double[] net, int off, int n, int m, int dim, double u, double v,
                                    double[] out, int outOff, double[] scratch, double threshold) {
        // Degenerate: step toward the centre (or, at the centre, toward an interior point)
        double tu = 0.5, tv = 0.5;
        if (Math.abs(u - 0.5) + Math.abs(v - 0.5) < 1e-3) {
            tu = 0.75;
            tv = 0.625;
        }
        for (double delta : INWARD_STEPS) {
            double su = u + delta * (tu - u), sv = v + delta * (tv - v);
            if (crossAt(net, off, n, m, dim, su, sv, out, outOff, scratch, threshold)) {
                return;
            }
        }
        netNormal(net, off, n, m, dim, out, outOff);
    }

    /**
     * Cross product {@code S_u × S_v} at {@code (u,v)} into {@code out}; normalises it and
     * returns true when its length exceeds {@code threshold} (and is finite), else false.
     */
    private static boolean crossAt(double[] net, int off, int n, int m, int dim, double u, double v,
                                   double[] out, int outOff, double[] scratch, double threshold) {
        if (dim == 4) {
            RationalDeCasteljau.evaluateWithDerivatives(net, off, n, m, u, v, scratch, DERIV, scratch, WORK);
        } else {
            DeCasteljau.evaluateWithDerivatives(net, off, n, m, 3, u, v, scratch, DERIV, scratch, WORK);
        }
        double ux = scratch[3], uy = scratch[4], uz = scratch[5];
        double vx = scratch[6], vy = scratch[7], vz = scratch[8];
        double x = uy * vz - uz * vy, y = uz * vx - ux * vz, z = ux * vy - uy * vx;
        return store(x, y, z, threshold, out, outOff);
    }

    /** Normal of the net's diagonals ({@code dim} 3), else +z. */
    static void netNormal(double[] net, int off, int n, int m, double[] out, int outOff) {
        netNormal(net, off, n, m, 3, out, outOff);
    }

    /** Normal of the net's diagonals (Euclidean corners), else +z. */
    private static void netNormal(double[] net, int off, int n, int m, int dim, double[] out, int outOff) {
        int p00 = off, pn0 = off + dim * n, p0m = off + dim * m * (n + 1), pnm = p0m + dim * n;
        double ax = coordinate(net, pnm, dim, 0) - coordinate(net, p00, dim, 0);
        double ay = coordinate(net, pnm, dim, 1) - coordinate(net, p00, dim, 1);
        double az = coordinate(net, pnm, dim, 2) - coordinate(net, p00, dim, 2);
        double bx = coordinate(net, p0m, dim, 0) - coordinate(net, pn0, dim, 0);
        double by = coordinate(net, p0m, dim, 1) - coordinate(net, pn0, dim, 1);
        double bz = coordinate(net, p0m, dim, 2) - coordinate(net, pn0, dim, 2);
        if (!store(ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx, 0, out, outOff)) {
            out[outOff] = 0;
            out[outOff + 1] = 0;
            out[outOff + 2] = 1;
        }
    }

    private static boolean store(double x, double y, double z, double threshold, double[] out, int outOff) {
        double len = Math.sqrt(x * x + y * y + z * z);
        if (!(len > threshold) || !Double.isFinite(len)) {
            return false;
        }
        double inv = 1 / len;
        out[outOff] = x * inv;
        out[outOff + 1] = y * inv;
        out[outOff + 2] = z * inv;
        return true;
    }

    /** Euclidean coordinate {@code c} of the point at {@code net[p]} ({@code dim} 3, or 4 homogeneous). */
    private static double coordinate(double[] net, int p, int dim, int c) {
        return dim == 4 ? net[p + c] / net[p + 3] : net[p + c];
    }

    /** Square of the largest extent of the control-point box. */
    public static double squaredExtent(double[] net, int off, int n, int m) {
        return squaredExtent(net, off, n, m, 3);
    }

    /** Square of the largest extent of the (Euclidean) control-point box of a {@code dim} 3 or 4 net. */
    public static double squaredExtent(double[] net, int off, int n, int m, int dim) {
        double ext = 0;
        int count = (n + 1) * (m + 1);
        for (int c = 0; c < 3; c++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int k = 0, p = off; k < count; k++, p += dim) {
                double x = coordinate(net, p, dim, c);
                if (x < lo) lo = x;
                if (x > hi) hi = x;
            }
            ext = Math.max(ext, hi - lo);
        }
        return ext * ext;
    }
}
