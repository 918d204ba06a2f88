package org.beziertracer.math;

import java.util.Arrays;

/**
 * Bézier decomposition of B-spline curves and tensor-product surfaces by knot insertion.
 *
 * <p>Every knot value in the requested parameter range, and the range's two ends, is inserted
 * until it occurs {@code degree} times; the B-spline basis on each knot span is then the Bernstein
 * basis, and the span's {@code degree + 1} control points are the Bézier points of that piece.
 * One insertion is Boehm's algorithm: W. Boehm, "Inserting new knots into B-spline curves",
 * Computer-Aided Design 12(4), 1980, 199–201; in the form of algorithm A5.1 of L. Piegl and
 * W. Tiller, <i>The NURBS Book</i>, 2nd ed., Springer 1997 (decomposition: §5.4). Clamped and
 * unclamped, uniform and non-uniform knot vectors are all handled the same way; a knot that
 * already occurs {@code degree} times or more is not touched, so a Bézier-form knot vector
 * gives back its control points bit for bit.
 *
 * <p>Control points are flat arrays of {@code dim} doubles each; rational curves pass
 * homogeneous points {@code (w·x, …, w)}, on which the algorithm is the same (insertion is an
 * affine map of the points). A tensor-product surface is decomposed as a curve in u whose
 * "points" are whole rows in v, then each piece as a curve in v. Knot vectors must be valid
 * ({@link KnotVector#problem}). Stateless; allocates its results.
 */
public final class BezierDecomposition {
    private BezierDecomposition() {}

    /**
     * The Bézier pieces of a curve: piece {@code k} covers {@code [breaks[k], breaks[k+1]]} and
     * its {@code degree + 1} points start at {@code points[offset(k)]}, {@code dim} doubles each.
     */
    public record Segments(int degree, int dim, double[] breaks, double[] points) {
        public int count() { return breaks.length - 1; }

        public int offset(int k) { return k * (degree + 1) * dim; }
    }

    /**
     * The Bézier pieces of a surface: piece {@code (a,b)} covers
     * {@code [breaksU[a], breaksU[a+1]] × [breaksV[b], breaksV[b+1]]} and its net (u fastest,
     * {@code dim} doubles a point) is {@code nets[b * countU() + a]}.
     */
    public record Patches(int degreeU, int degreeV, int dim, double[] breaksU, double[] breaksV, double[][] nets) {
        public int countU() { return breaksU.length - 1; }

        public int countV() { return breaksV.length - 1; }
    }

    /**
     * Bézier pieces of the B-spline curve of degree {@code degree} with knots {@code knots} and
     * control points {@code points} ({@code dim} doubles each) over {@code [from, to]}, which must
     * satisfy {@code U_p ≤ from < to ≤ U_count}.
     */
    public static Segments curve(int degree, double[] knots, double[] points, int dim, double from, double to) {
        int count = points.length / dim;
        if (!(from < to && from >= KnotVector.start(degree, knots) && to <= KnotVector.end(degree, knots))) {
            throw new IllegalArgumentException("range [" + from + ", " + to + "] is not inside the knot range ["
                    + KnotVector.start(degree, knots) + ", " + KnotVector.end(degree, knots) + "]");
        }
        double[] breaks = breaks(knots, from, to);
        int maxInsert = degree * breaks.length;
        double[] u = Arrays.copyOf(knots, knots.length + maxInsert);
        double[] p = Arrays.copyOf(points, (count + maxInsert) * dim);
        int uLen = knots.length;
        for (double x : breaks) {
            for (int mult = KnotVector.multiplicity(u, uLen, x); mult < degree; mult++) {
                insert(degree, u, uLen, p, count, dim, x);
                uLen++;
                count++;
            }
        }
        int pieceLength = (degree + 1) * dim;
        double[] out = new double[(breaks.length - 1) * pieceLength];
        for (int k = 0; k + 1 < breaks.length; k++) {
            int s = uLen - 1;
            while (u[s] != breaks[k]) {
                s--;
            }
            System.arraycopy(p, (s - degree) * dim, out, k * pieceLength, pieceLength);
        }
        return new Segments(degree, dim, breaks, out);
    }

    /**
     * Bézier pieces of the tensor-product B-spline surface of degrees {@code p} (u) and {@code q}
     * (v), knots {@code knotsU}, {@code knotsV} and {@code countU × countV} control points (u
     * fastest, {@code dim} doubles each) over {@code [u0,u1] × [v0,v1]}.
     */
    public static Patches surface(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV,
                                  double[] points, int dim, double u0, double u1, double v0, double v1) {
        if (onePiece(p, knotsU, countU, u0, u1) && onePiece(q, knotsV, countV, v0, v1)) {
            // already one Bézier net (what the insertions below would leave untouched): a copy
            return new Patches(p, q, dim, new double[] {u0, u1}, new double[] {v0, v1},
                    new double[][] {Arrays.copyOf(points, countU * countV * dim)});
        }
        return byInsertion(p, q, knotsU, knotsV, countU, countV, points, dim, u0, u1, v0, v1);
    }

    /** {@link #surface} by knot insertion in u, then in v, whatever the knots. */
    static Patches byInsertion(int p, int q, double[] knotsU, double[] knotsV, int countU, int countV,
                               double[] points, int dim, double u0, double u1, double v0, double v1) {
        // As a curve in u whose point i is the whole column (P_i0, …, P_i,countV-1)
        int dimU = countV * dim;
        double[] columns = new double[countU * dimU];
        for (int j = 0; j < countV; j++) {
            for (int i = 0; i < countU; i++) {
                System.arraycopy(points, (j * countU + i) * dim, columns, i * dimU + j * dim, dim);
            }
        }
        Segments inU = curve(p, knotsU, columns, dimU, u0, u1);
        // Each u piece as a curve in v whose point j is the row (P_0j, …, P_pj)
        int dimV = (p + 1) * dim;
        double[] rows = new double[countV * dimV];
        double[][] nets = null;
        double[] breaksV = null;
        int piecesU = inU.count();
        for (int a = 0; a < piecesU; a++) {
            int base = inU.offset(a);
            for (int i = 0; i <= p; i++) {
                for (int j = 0; j < countV; j++) {
                    System.arraycopy(inU.points(), base + i * dimU + j * dim, rows, j * dimV + i * dim, dim);
                }
            }
            Segments inV = curve(q, knotsV, rows, dimV, v0, v1);
            if (nets == null) {
                breaksV = inV.breaks();
                nets = new double[piecesU * inV.count()][];
            }
            for (int b = 0; b < inV.count(); b++) {
                // the piece's rows are already u fastest: row j holds P_0j … P_pj
                nets[b * piecesU + a] = Arrays.copyOfRange(inV.points(), inV.offset(b), inV.offset(b + 1));
            }
        }
        return new Patches(p, q, dim, inU.breaks(), breaksV, nets);
    }

    /**
     * True when the knots are the Bézier ones over exactly {@code [from, to]}: {@code degree + 1}
     * times {@code from}, then {@code degree + 1} times {@code to}, and {@code degree + 1} points.
     */
    static boolean onePiece(int degree, double[] knots, int count, double from, double to) {
        if (count != degree + 1 || knots.length != 2 * degree + 2 || !(from < to)) {
            return false;
        }
        for (int i = 0; i <= degree; i++) {
            if (knots[i] != from || knots[degree + 1 + i] != to) {
                return false;
            }
        }
        return true;
    }

    /** {@code from}, every distinct knot strictly between, and {@code to}, in increasing order. */
    private static double[] breaks(double[] knots, double from, double to) {
        double[] out = new double[knots.length + 2];
        int n = 0;
        out[n++] = from;
        for (double x : knots) {
            if (x > out[n - 1] && x < to) {
                out[n++] = x;
            }
        }
        out[n++] = to;
        return Arrays.copyOf(out, n);
    }

    /**
     * Inserts {@code t} once (Boehm): {@code count} points become {@code count + 1} and
     * {@code uLen} knots {@code uLen + 1}, in place; the arrays must have room.
     */
    private static void insert(int degree, double[] u, int uLen, double[] p, int count, int dim, double t) {
        int k = KnotVector.span(degree, u, count, t);
        // Points k.. move up by one: Q_i = P_{i-1} for i > k
        System.arraycopy(p, k * dim, p, (k + 1) * dim, (count - k) * dim);
        // Q_i = α_i P_i + (1 − α_i) P_{i-1} for k−p+1 ≤ i ≤ k, downwards so P_{i-1} is still intact
        for (int i = k; i >= k - degree + 1; i--) {
            double alpha = (t - u[i]) / (u[i + degree] - u[i]);
            double beta = 1 - alpha;
            for (int c = 0, a = i * dim, b = a - dim; c < dim; c++) {
                p[a + c] = alpha * p[a + c] + beta * p[b + c];
            }
        }
        System.arraycopy(u, k + 1, u, k + 2, uLen - k - 1);
        u[k + 1] = t;
    }
}
